// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading a TOML file with file:line:column errors: the machine files, the dialect files, the tool
// tables and the work-offset files are read through these two, so that a syntax error or a wrong
// value names its place the same way in each (InputError, exit code 2). Includes toml++: include it
// only where a TOML file is read.
#include <string>
#include <toml++/toml.h>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::toml_input {

/// Where a TOML node or key stands in `file` (1-based line and column).
inline SourcePosition at(const std::string& file, const toml::source_region& r) {
  return {file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

/// The TOML document; a syntax error becomes an InputError at its position.
inline toml::table parse_toml(const std::string& text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(at(file, e.source()), std::string(e.description()));
  }
}

}  // namespace ncpost::toml_input
