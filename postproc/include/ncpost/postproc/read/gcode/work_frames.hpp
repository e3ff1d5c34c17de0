// SPDX-License-Identifier: Apache-2.0
#pragma once
// The work offsets of a program placed in one frame (docs/formats.md "Work offsets").
//
// The posted program has one workpiece frame: the frame of the offset in force at the program's
// first motion in work coordinates (the base; G54 when none was selected: the power-on offset).
// A program point written under another offset k lies, in the base frame, at
//   p_base = p_k + (value_k - value_base)          (per axis; mm, rad)
// where value_n is where offset n's zero lies in machine coordinates (the control adds it to the
// program's words): the `shift()` added to every absolute coordinate. Values come from the
// --work-offsets file and from the program's own G10 L2 (absolute) and LinuxCNC G10 L20 (so that
// the current position reads the given value: value_k - value_base = p_base - given, known even
// where the base's own value is not). A shift that needs a value nobody gave is refused.
//
// A local shift (G52, G92) is added on top, in every work offset alike (Fanuc: G52 and G92 shift
// all of G54 .. G59; LinuxCNC: one offset for both, applied in every coordinate system):
//   p_base = p_k + (value_k - value_base) + local
// G52 sets `local` on the given axes; G92 sets it so that the current position reads the given
// values. Axes not given keep theirs.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "ncpost/postproc/read/gcode/work_offsets.hpp"

namespace ncpost::gcode {

class WorkFrames {
 public:
  /// `table`: the --work-offsets file (null: none); `used`: the axes (X Y Z A B C slots) the
  /// program may move, the only ones whose shift must be known.
  WorkFrames(std::shared_ptr<const WorkOffsetTable> table, std::array<bool, 6> used);

  /// The offset in force (G54, the power-on offset of Fanuc, Haas and LinuxCNC, until the program
  /// or the dialect's power-on state selects another).
  const std::string& active() const { return active_; }
  /// Whether the first motion in work coordinates has fixed the base frame.
  bool fixed() const { return fixed_; }
  /// The base frame's offset ("": the control's active one at the start).
  const std::string& base() const { return base_; }
  /// `name` for messages ("the control's active offset" for "").
  static std::string named(const std::string& name);
  /// Added to absolute program coordinates (mm, rad): zero while the base is in force and no
  /// local shift is set.
  const std::array<double, 6>& shift() const { return shift_; }

  /// Selects offset `name`. Returns "" or why its shift is not known.
  std::string select(const std::string& name);
  /// The program moves in work coordinates: the first call fixes the base frame.
  void moved();
  /// G10 L2: the given axes of offset `name` lie at `machine_value` (mm, rad). "" or why not.
  std::string set_value(const std::string& name, const std::array<std::optional<double>, 6>& machine_value);
  /// LinuxCNC G10 L20: the given axes of offset `name` are set so that the current position
  /// `position_base` (base frame) reads `reads` in it. Only after the base is fixed. "" or why not.
  std::string set_reading(const std::string& name, const std::array<double, 6>& position_base,
                          const std::array<std::optional<double>, 6>& reads);
  /// G52: the local shift (mm, rad) on the given axes.
  void set_local(const std::array<std::optional<double>, 6>& shift);
  /// G92: the local shift on the given axes such that the current position `position_base`
  /// (base frame) reads `reads` (mm, rad) in the active offset.
  void set_local_reading(const std::array<double, 6>& position_base, const std::array<std::optional<double>, 6>& reads);
  /// The local shift in force (mm, rad): zero until a G52 or G92.
  const std::array<double, 6>& local() const { return local_; }
  /// Where the shift of `name` came from, for notices ("work-offsets.toml", "G10 at line 12").
  std::string source_of(const std::string& name) const;
  void note_source(const std::string& name, std::string source) { sources_[name] = std::move(source); }

 private:
  /// An offset's value on one axis: absolute (machine coordinates) or relative to the base's
  /// value at the first motion (from_base), which G10 L20 gives without knowing that value.
  struct Value {
    double v = 0.0;
    bool from_base = false;
  };
  using Values = std::array<std::optional<Value>, 6>;
  std::string update_shift();
  std::optional<double> shift_of(const Values& values, std::size_t axis) const;

  std::shared_ptr<const WorkOffsetTable> table_;
  std::array<bool, 6> used_{};
  std::map<std::string, Values> values_;
  std::map<std::string, std::string> sources_;
  std::string active_ = "G54";
  std::string base_;
  bool fixed_ = false;
  std::array<std::optional<double>, 6> base_value_{};  ///< the base's value at the first motion
  void combine();

  std::array<double, 6> offset_shift_{};  ///< value_k - value_base
  std::array<double, 6> local_{};         ///< G52 / G92
  std::array<double, 6> shift_{};         ///< the sum of both
};

}  // namespace ncpost::gcode
