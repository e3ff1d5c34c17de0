// SPDX-License-Identifier: Apache-2.0
#pragma once
// The NC words of a kinematic model's commands (kinematic_model.hpp): which slot of AxisPosition
// is which letter, and which are angles. Units: rad inside, degrees in the program; mm.
#include <array>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost {

/// The NC words of a model's commands: AxisPosition slot i (operator[]) is the word `letters[i]`,
/// an angle (rad inside, degrees in the program) where `angle[i]`, else a length (mm). Serial
/// machines: X Y Z and their rotary axes; the TRR-XY machine: X Y U V W, all lengths. Read once
/// per post (not per point).
struct CommandWords {
  int count = 5;
  std::array<char, 5> letters{'X', 'Y', 'Z', 'A', 'B'};
  std::array<bool, 5> angle{false, false, false, true, true};
  int rotary_count = 2;  ///< how many words are angles (slots 3 and 4 on a serial machine)
  /// True for a serial chain (Machine, closed-form inverse): with_rotary() and the rotary-axis
  /// strategies of the post (branch changes, native arcs and cycles, cutter compensation) apply.
  bool serial = true;

  /// The words of a serial machine (X Y Z, then its rotary axes).
  static CommandWords of(const Machine& m) {
    CommandWords w;
    w.count = static_cast<int>(m.axes.size());
    for (int i = 0; i < w.count && i < 5; ++i) {
      w.letters[static_cast<std::size_t>(i)] = m.axes[static_cast<std::size_t>(i)].letter;
      w.angle[static_cast<std::size_t>(i)] = m.axes[static_cast<std::size_t>(i)].is_rotary();
    }
    w.rotary_count = m.rotary_count();
    return w;
  }
};

}  // namespace ncpost
