// SPDX-License-Identifier: Apache-2.0
#pragma once
// The error every reader of user input throws: it names the file, line and column, what was
// expected and the offending text. The CLI maps it to exit code 2 (docs/cli.md).
#include <stdexcept>
#include <string>

namespace ncpost {

struct SourcePosition {
  std::string file;
  int line = 0;    ///< 1-based; 0 = unknown
  int column = 0;  ///< 1-based; 0 = unknown
};

class InputError : public std::runtime_error {
 public:
  InputError(SourcePosition where, std::string what, std::string source_line = {})
      : std::runtime_error(format(where, what)),
        where_(std::move(where)),
        detail_(std::move(what)),
        source_line_(std::move(source_line)) {}

  const SourcePosition& where() const { return where_; }
  const std::string& detail() const { return detail_; }
  /// The offending line of input, if known (for a caret display).
  const std::string& source_line() const { return source_line_; }

  /// "file:line:column: what" (line and column left out where unknown); input_error.cpp.
  static std::string format(const SourcePosition& w, const std::string& what);

 private:
  SourcePosition where_;
  std::string detail_;
  std::string source_line_;
};

/// An expected failure that is not bad input: a pose out of the axis limits, a fit that did not
/// converge. The CLI maps it to exit code 3.
class Infeasible : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ncpost
