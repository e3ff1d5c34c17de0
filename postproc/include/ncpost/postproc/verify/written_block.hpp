// SPDX-License-Identifier: Apache-2.0
#pragma once
// `post --verify` reads what it wrote: each motion block's text, as it stands in the program, read
// back as the control reads it — ISO G-code (G0 G1 G2 G3, G93 G94, G17-G19, I J K, F: their RS274
// meaning, whatever words the dialect file chose) or Klartext (L, FMAX, F) — with the machine's axis
// letters, the dialect's comments and block numbers, and the modal state a control keeps (the
// motion, every axis word, the feed mode and feed). The verifier executes these words — not the
// values the post meant to write — so a dialect file that writes the wrong word (G2 for an arc that
// runs counter-clockwise, G94 where the block needs G93) shows.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost {

/// What the control holds after a block (output units: mm, deg, mm/min or 1/min).
struct WrittenState {
  enum class Motion { none, rapid, linear, clockwise, counter_clockwise } motion = Motion::none;
  PerAxis<std::optional<double>> values{};   ///< every axis word in force, in `letters` order
  std::array<double, 3> centre_offset_mm{};  ///< I J K of the last arc block (centre − start)
  int plane = 17;
  bool inverse_time = false;
  std::optional<double> feed;
};

class WrittenBlockReader {
 public:
  WrittenBlockReader(const Dialect& dialect, std::string letters);
  /// Starts from the words in force `s` (NcWriter::in_force() before the block is written).
  void start_from(const WrittenState& s) { state_ = s; }
  /// Reads one block (a line as written, comments and block number included) into the state;
  /// throws std::runtime_error naming the word it cannot read.
  const WrittenState& read(std::string_view text);
  const WrittenState& state() const { return state_; }

 private:
  const Dialect& dialect_;
  std::string letters_;
  WrittenState state_;
};

}  // namespace ncpost
