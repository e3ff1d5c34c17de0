// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the comments of a G-code program say about its units, for a program without G20/G21:
// inch words (INCH, IPM, SFM, UNC, a number followed by IN or ") against metric ones (MM, a
// number followed by MM, METRIC, SMM). The control's default units decide such a program, so
// comments that speak inches and never millimetres are evidence against reading it as mm.
#include <string>
#include <string_view>

namespace ncpost::gcode {

class UnitsEvidence {
 public:
  /// Counts the unit words of one comment on `line`.
  void scan_comment(std::string_view text, int line);
  /// Comments name inch units and never metric ones.
  bool speaks_inches() const { return inch_words_ > 0 && metric_words_ == 0; }
  int first_inch_line() const { return first_inch_line_; }
  /// The first inch word as written (for the message).
  const std::string& first_inch_word() const { return first_inch_word_; }

 private:
  int inch_words_ = 0;
  int metric_words_ = 0;
  int first_inch_line_ = 0;
  std::string first_inch_word_;
};

}  // namespace ncpost::gcode
