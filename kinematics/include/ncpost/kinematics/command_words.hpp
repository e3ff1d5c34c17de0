// SPDX-License-Identifier: Apache-2.0
#pragma once
// The NC words of a kinematic model's commands (kinematic_model.hpp): which slot of AxisPosition
// is which letter, and which are angles. Units: rad inside, degrees in the program; mm.
#include <string>
#include <vector>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost {

/// The NC words of a model's commands: AxisPosition slot i (operator[]) is the word `letters[i]`,
/// an angle (rad inside, degrees in the program) where `angle[i]`, else a length (mm). As many as
/// the model has axes: a three-axis machine X Y Z, a four-axis one X Y Z and its rotary axis, a
/// five-axis one X Y Z and its two; the TRR-XY machine X Y U V W, all lengths. Read once per post
/// (not per point).
struct CommandWords {
  int count = 3;
  std::vector<char> letters{'X', 'Y', 'Z'};
  std::vector<bool> angle{false, false, false};
  int rotary_count = 0;  ///< how many words are angles (slots 3 and up on a serial machine)
  // What the post may do with these words, set by the model's kind (a serial chain: all of them,
  // CommandWords::of; the TRR-XY machine: none, its words are five lengths).
  /// A program's own rotary angles (G-code input) are taken as they are (with_rotary()).
  bool angles_are_programmed = true;
  /// The control compensates the tool radius (G41/G42) in a plane of these axes.
  bool cutter_comp_supported = true;
  /// Work planes can be tilted by the rotary axes (PLANE / CYCLE800 / G68.2 words).
  bool tilted_plane_capable = true;
  /// The inverse has rotary branches the post chooses among (branch plan, change of solution
  /// with a retract).
  bool branches_chosen = true;
  /// machine() is the chain the commands solve (its axes and limits name the axis a point
  /// leaves the travel of).
  bool limits_name_the_axis = true;

  /// The words of a serial machine (X Y Z, then its rotary axes).
  static CommandWords of(const Machine& m) {
    CommandWords w;
    w.count = static_cast<int>(m.axes.size());
    w.letters.clear();
    w.angle.clear();
    for (const Axis& a : m.axes) {
      w.letters.push_back(a.letter);
      w.angle.push_back(a.is_rotary());
    }
    w.rotary_count = m.rotary_count();
    return w;
  }
  /// The model's position at home (every axis at 0), sized for its words.
  AxisPosition home() const { return AxisPosition::zero(count - 3); }
};

}  // namespace ncpost
