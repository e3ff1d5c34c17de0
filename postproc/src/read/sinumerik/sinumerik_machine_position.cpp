// SPDX-License-Identifier: Apache-2.0
// The machine position of the Sinumerik translator (sinumerik_translator.hpp): what SUPA/G53 and G75
// blocks and CYCLE800's retraction leave the linear axes at, in machine coordinates, so that the plane
// CYCLE800 swivels to knows where the tool tip stands. On the control the position after the swivel
// is the machine position seen in the new frame: a block that programs X and Y only moves at the
// Z where the tool stands in the tilted plane. The machine coordinates count from each axis's
// `reference` in the machine file (Z without it: the top of its travel), as the G-code reader places
// G53; an axis without either is not known.
#include <fmt/format.h>

#include <cmath>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/machine_points.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"
#include "read/sinumerik/sinumerik_words.hpp"

namespace ncpost::sinumerik {

/// Where machine coordinate 0 of linear axis `axis` (0 X, 1 Y, 2 Z) lies in M (mm), as G53 counts.
std::optional<double> Translator::machine_reference_mm(int axis) const {
  const int at = machine_.index_of("XYZ"[axis]);
  if (at < 0) return std::nullopt;
  return reference_or_top(machine_.axes[static_cast<std::size_t>(at)]);
}

/// A SUPA/G53 block's X Y Z (absolute, program unit) as machine commands.
void Translator::note_machine_words(const Words& w) {
  for (int i = 0; i < 3; ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (!w.xyz[s]) continue;
    const std::optional<double> ref = machine_reference_mm(i);
    machine_mm_[s] = ref ? std::optional<double>(*ref + *w.xyz[s] * (inch_ ? 25.4 : 1.0)) : std::nullopt;
  }
}

/// The rotary axes' angles in force (rad, machine order; 0 where none was programmed yet).
RotaryAngles Translator::rotary_now() const {
  RotaryAngles rad = RotaryAngles::Zero(machine_.rotary_count());
  for (int k = 0; k < machine_.rotary_count(); ++k)
    rad[k] = rotary_deg_[static_cast<std::size_t>(machine_.rotary(k).letter - 'A')] * M_PI / 180.0;
  return rad;
}

/// Where the linear axes stand, per axis, as machine commands in M (CYCLE800, which uses it, is read in
/// mm only): where SUPA/G53 or the retraction put them; else outside TRAORI and a plane the position
/// (its X Y Z are the axes there); in a plane all three from the tool tip through the machine.
std::array<std::optional<double>, 3> Translator::machine_now() const {
  std::array<std::optional<double>, 3> m = machine_mm_;
  const bool all = base_known_[0] && base_known_[1] && base_known_[2];
  if (traori_ || swivel_tip_) {
    if (!all) return m;
    const Eigen::Vector3d linear = linear_for(machine_, rotary_now(), base_, setup_);
    for (int i = 0; i < 3; ++i)
      if (!m[static_cast<std::size_t>(i)]) m[static_cast<std::size_t>(i)] = linear[i];
    return m;
  }
  for (std::size_t i = 0; i < 3; ++i)
    if (!m[i] && base_known_[i]) m[i] = base_[static_cast<int>(i)];
  return m;
}

/// CYCLE800 _FR=1: machine Z to the swivel data record's retraction position, which the machine
/// file gives as [axes.Z] swivel_retract; without it Z goes to its reference point (G53 Z0) in the
/// posted program, with a notice, and where it stands is not known (a block after the swivel that
/// does not program X, Y and Z is refused).
void Translator::retract_for_swivel(const ProgramLine& l) {
  machine_mm_ = machine_now();  // X and Y stay where they stand
  if (swivel_tip_) emit(l, "TRAFOOF"), swivel_tip_ = false;
  base_known_ = {false, false, false};
  const int z = machine_.index_of('Z');
  const std::optional<double> retract =
      z < 0 ? std::nullopt : machine_.axes[static_cast<std::size_t>(z)].swivel_retract;
  const std::optional<double> ref = machine_reference_mm(2);
  if (retract && ref) {
    notice_once(l, "CYCLE800 _FR",
                fmt::format("CYCLE800 _FR=1: Z retracts to {:.3f} mm in M before the swivel (the machine file's "
                            "[axes.Z] swivel_retract, the control's swivel data)",
                            *retract));
    emit(l, "G0 G53 Z" + gcode::word_number((*retract - *ref) / (inch_ ? 25.4 : 1.0)));
    machine_mm_[2] = retract;
    return;
  }
  notice_once(l, "CYCLE800 _FR",
              "CYCLE800 _FR=1: the retract in Z goes to Z's reference point (G53 Z0: the machine file's reference, "
              "else the top of Z's travel); the tool carrier's retract position is the control's data, which the "
              "machine file may give as [axes.Z] swivel_retract; without it where Z stands after the swivel is not "
              "known");
  emit(l, "G0 G53 Z0");
  machine_mm_[2].reset();
}

/// Rotary words alone outside TRAORI and a swivelled plane: the linear axes stand still, so D0 (no
/// tool offset) changes nothing the block moves (NC-PB's `B0 C0` after the closing G53 retracts).
bool Translator::rotary_only_under_d0(const Words& w) const {
  return w.any_rotary() && !w.any_linear() && !w.any_orientation() && !traori_ && !swivel_tip_ && !w.radius &&
         !w.ijk[0] && !w.ijk[1] && !w.ijk[2];
}

}  // namespace ncpost::sinumerik
