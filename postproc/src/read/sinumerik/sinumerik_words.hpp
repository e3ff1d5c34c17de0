// SPDX-License-Identifier: Apache-2.0
#pragma once
// What one Sinumerik block asks, gathered from its items before any of it is written
// (sinumerik_translator.hpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "read/sinumerik/sinumerik_translator.hpp"

namespace ncpost::sinumerik {

/// How an axis value is meant: as the modal G90/G91 says, or IC()/AC() for this word.
enum class Reference { modal, incremental, absolute };

struct Translator::Words {
  std::vector<std::string> iso;              ///< ISO words written before the motion (G17 F S T M3 ...)
  std::optional<int> motion;                 ///< G0..G3 in this block
  std::array<std::optional<double>, 3> xyz;  ///< X Y Z as written (program unit)
  std::array<Reference, 3> xyz_ref{};
  std::array<std::optional<double>, 3> abc;  ///< A B C (deg)
  std::array<Reference, 3> abc_ref{};
  std::array<std::optional<double>, 3> ijk;          ///< I J K
  std::array<bool, 3> ijk_absolute{};                ///< AC(): the centre itself
  std::optional<double> radius;                      ///< CR=
  std::array<std::optional<double>, 3> orientation;  ///< A3 B3 C3
  std::optional<double> dwell_s;                     ///< G4 F (s)
  std::optional<std::string> tool_name;              ///< a T word: T="name" (its name), T<n> ("")
  bool supa = false;                                 ///< SUPA, or G53 (read as SUPA: sinumerik_block.cpp)
  std::optional<int> g53_column;                     ///< G53 in this block: where
  std::optional<int> g75_column;                     ///< G75 (fixed point approach) in this block: where
  std::optional<double> fixed_point;                 ///< FP= (G75's fixed point number)
  int fixed_point_column = 1;                        ///< of FP=
  bool program_end = false;                          ///< M2 / M30
  bool unit_end = false;                             ///< M17 / RET
  std::vector<const Item*> after;                    ///< calls run after the motion (CYCLE800, CYCLE81, subprograms)
  int column = 1;                                    ///< of the block's first item
  int axis_column = 1;                               ///< of its first axis word

  /// The word that suppressed the frames, for messages.
  const char* suppression() const { return g53_column ? "G53" : "SUPA"; }
  bool any_linear() const { return xyz[0] || xyz[1] || xyz[2]; }
  bool any_rotary() const { return abc[0] || abc[1] || abc[2]; }
  bool any_orientation() const { return orientation[0] || orientation[1] || orientation[2]; }
};

}  // namespace ncpost::sinumerik
