// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a G-code program starts and whether it said anything: the leader before the opening '%'
// and the words that make a motion.
//
// Leader (Fanuc, Haas: the control reads a program from its first '%'): the lines before the
// first '%' line are a leader and are skipped when they hold no motion (comments, a PowerMill
// title). A file that starts with NX's "Information listing" header (the listing window saved
// into a file, as NX shows its post's output) is read from its '%' on, with a notice saying so;
// without a '%' after it (the head of the file, 64 KiB) it is refused, saying what it is. Lines before it that move the
// machine make that '%' the closing one when nothing moves after it (`G0 X1 / M30 / %`); when motions stand on both
// sides the reading is ambiguous (a program before its leader's end, or a leader that moves) and the input is refused,
// naming both lines.
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"

namespace ncpost::gcode {

/// Whether `block` has a word that moves an axis: one of `axis_letters` outside a G4 (dwell: X is
/// its time) or G10 (data setting) block.
bool has_motion_words(const Block& block, std::string_view axis_letters);

struct Leader {
  int lines = 0;       ///< lines before the opening '%' to skip (0: none)
  std::string notice;  ///< what was skipped and why ("" when nothing)
};

/// Looks at `head` (the start of the input, the UTF-8 byte order mark already skipped or not;
/// `complete`: the input ends within it). Throws InputError when motions stand before and after
/// the first '%'.
Leader find_leader(std::string_view head, bool complete, const std::string& file, std::string_view axis_letters);

}  // namespace ncpost::gcode
