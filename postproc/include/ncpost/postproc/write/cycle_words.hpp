// SPDX-License-Identifier: Apache-2.0
#pragma once
// The words of the canned drilling cycles and of cutter radius compensation of a dialect (data:
// the dialect file's [cycles], [dwell] and [compensation], dialect.hpp).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost {

/// The cycle words of the dialect, or none when it has no ISO canned cycles (every hole is expanded).
std::optional<CycleWords> cycle_words(const Dialect& d);

/// The block(s) of a dwell of `seconds` in the dialect (G4 P, G4 F, CYCL DEF 9).
std::vector<std::string> dwell_blocks(const Dialect& d, double seconds);

/// G41/G42 D<n> / G40 in the dialect, or none when the dialect writes no compensation words.
std::optional<CompWords> comp_words(const Dialect& d);

}  // namespace ncpost
