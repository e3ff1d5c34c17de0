// SPDX-License-Identifier: Apache-2.0
#pragma once
// The words of the canned drilling cycles and of cutter radius compensation per dialect (data:
// cycle_words.cpp). A kind whose word is empty has no native cycle in the dialect and is
// expanded into explicit moves.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/cl_record.hpp"
#include "ncpost/postproc/dialect.hpp"

namespace ncpost {

struct CycleWords {
  std::string drill, drill_dwell, deep, chip_break, tap, tap_left, bore, bore_dwell, bore_drag;
  std::string retract_initial = "G98", retract_r = "G99", cancel = "G80";
  bool dwell_in_ms = true;       ///< P in integer milliseconds (Fanuc, Haas), else seconds with decimals
  bool first_peck_ijk = false;   ///< G83 takes I (first peck), J (reduction), K (minimum peck): Haas
  /// The word of this kind (with or without a dwell at the bottom), empty when not native.
  const std::string& word(const cl::Cycle& c) const;
};

/// The cycle words of the dialect, or none when it has no ISO canned cycles (Sinumerik, Heidenhain:
/// every hole is expanded).
std::optional<CycleWords> cycle_words(const Dialect& d);

/// The block(s) of a dwell of `seconds` in the dialect (G4 P, G4 F, CYCL DEF 9).
std::vector<std::string> dwell_blocks(const Dialect& d, double seconds);

/// G41/G42 D<n> / G40 in the dialect, or none when the dialect writes no compensation words.
struct CompWords {
  std::string left = "G41", right = "G42", off = "G40";
  std::string register_letter = "D";  ///< empty: the control takes the radius of the active tool
};
std::optional<CompWords> comp_words(const Dialect& d);

}  // namespace ncpost
