// SPDX-License-Identifier: Apache-2.0
// CYCLE800 (swivel plane) and CYCLE81/CYCLE82 (drilling; the parameters all drilling cycles share) of the
// Sinumerik translator
// (sinumerik_translator.hpp). Parameters as in the SINUMERIK 840D sl "Programming Manual
// Measuring/Standard cycles":
//   CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR, _FR_I, _DMODE)
//     _FR retract before swivelling (0 none; 1 machine Z: to the machine file's [axes.Z] swivel_retract, else
//     to Z's reference point, G53 Z0, and Z is then not known: sinumerik_machine_position.cpp),
//     _TC the tool carrier (the machine file gives the kinematics), _ST units digit 0 (a new plane;
//     1 additive: refused), _MODE axis by axis (57: X, then Y', then Z'': the frame
//     Rx(_A) Ry(_B) Rz(_C); 27: Rz(_A) Ry(_B) Rx(_C); Translator::axis_by_axis), _X0.._Z0 the shift before the
//     rotation, _X1.._Z1 after it, _DIR the direction of the reference (first) rotary axis (+1/-1; 0: rotary axes not
//     positioned: refused for a tilted plane). CYCLE800() resets the plane.
//   CYCLE81(RTP, RFP, SDIS, DP, DPR), CYCLE82(RTP, RFP, SDIS, DP, DPR, DTB): rapid to RFP + SDIS,
//     feed to RFP - DPR (DPR not 0) or DP, dwell DTB s (CYCLE82), rapid to RTP; at the current X Y, along
//     the current frame's Z: G81/G82 (a cl::Cycle) where that is the same motion, else the motions.
#include <fmt/format.h>

#include <cmath>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"
#include "read/sinumerik/sinumerik_words.hpp"

namespace ncpost::sinumerik {

void Translator::cycle800_reset(const ProgramLine& l) {
  swivel_ = Frame{};
  if (!swivel_tip_) return;
  if (base_known_[0] && base_known_[1] && base_known_[2]) base_ = linear_for(machine_, rotary_now(), base_, setup_);
  swivel_tip_ = false;
  emit(l, "TRAFOOF");
}

/// _MODE axis by axis (bits 7-6 00): bits 1-0, 3-2, 5-4 name the first, second, third axis (01 X,
/// 10 Y, 11 Z; 57: X Y Z, 27: Z Y X); the plane is turned by _A about the first, then _B about the
/// second and _C about the third as they are after the turns before (R = R1(_A) R2(_B) R3(_C)).
Eigen::Matrix3d Translator::axis_by_axis(const ProgramLine& l, const Item& item, double mode,
                                         const Eigen::Vector3d& angles_deg) const {
  const int bits = static_cast<int>(mode);
  if (bits != mode || bits < 0 || bits > 255 || (bits >> 6) != 0)
    fail(l, item.column,
         fmt::format("CYCLE800 _MODE={}: only axis-by-axis angles (_MODE below 64, e.g. 57: X Y Z, 27: Z Y X) are "
                     "read, not projection or solid angles or rotary axes directly; have the CAM system write "
                     "axis-by-axis angles",
                     mode));
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  for (int k = 0; k < 3; ++k) {
    const int axis = (bits >> (2 * k)) & 3;
    if (axis == 0)
      fail(l, item.column, fmt::format("CYCLE800 _MODE={}: axis {} of the sequence is not set", mode, k + 1));
    r = r * about_axis(axis - 1, angles_deg[k]);
  }
  return r;
}

void Translator::cycle800(const ProgramLine& l, const Item& item) {
  const Arguments args{split_arguments(item.text)};
  if (args.text.empty()) return cycle800_reset(l);
  const auto num = [&](std::size_t i) { return args.given(i) ? value(l, item.column, args.text[i]) : 0.0; };
  if (traori_) fail(l, item.column, "CYCLE800 under TRAORI is not read (program TRAFOOF first)");
  if (inch_) fail(l, item.column, "CYCLE800 in an inch program (G70/G700) is not read");
  const double fr = num(0), st = num(2), mode = num(3), dir = num(13);
  const Eigen::Vector3d x0(num(4), num(5), num(6)), angles(num(7), num(8), num(9)), x1(num(10), num(11), num(12));
  if (fr != 0.0 && fr != 1.0)
    fail(l, item.column, fmt::format("CYCLE800 _FR={}: only 0 (no retract) and 1 (retract Z) are read", fr));
  if (std::fmod(std::abs(st), 10.0) != 0.0)
    fail(l, item.column, "CYCLE800 _ST: an additive swivel plane is not read (only a new plane, units digit 0)");
  const bool tilted = angles.norm() > 1e-12;
  Frame r;
  r.rotation = tilted ? axis_by_axis(l, item, mode, angles) : Eigen::Matrix3d::Identity();
  if (tilted && dir == 0.0)
    fail(l, item.column, "CYCLE800 _DIR=0 (the plane without positioning the rotary axes) is not read");
  if (fr == 1.0) retract_for_swivel(l);
  position_swivel(l, item, r.rotation * Eigen::Vector3d::UnitZ(), static_cast<int>(dir), tilted);
  swivel_ = shift(x0).then(r).then(shift(x1));
}

/// The rotary axes to the plane's normal (machine axes still), then tool-tip input.
void Translator::position_swivel(const ProgramLine& l, const Item& item, const Eigen::Vector3d& axis_W, int dir,
                                 bool tilted) {
  if (machine_.rotary_count() == 0) {
    if (tilted)
      fail(l, item.column,
           fmt::format("CYCLE800 with a tilted plane on machine {}, which has no rotary axes", machine_.name));
    return;
  }
  const std::optional<RotaryAngles> a = nearest_solution(axis_W, dir);
  if (!a)
    fail(l, item.column,
         fmt::format("CYCLE800: the plane's normal is beyond the reach or the limits of machine {}", machine_.name));
  // the linear axes stand still while the rotary axes turn (sinumerik_machine_position.cpp)
  const std::array<std::optional<double>, 3> machine = machine_now();
  const bool known = machine[0] && machine[1] && machine[2];
  if (swivel_tip_) emit(l, "TRAFOOF");
  std::string words = "G0";
  for (int k = 0; k < machine_.rotary_count(); ++k) {
    const char letter = machine_.rotary(k).letter;
    const double deg = (*a)[k] * 180.0 / M_PI;
    rotary_deg_[static_cast<std::size_t>(letter - 'A')] = deg;
    rotary_known_[static_cast<std::size_t>(letter - 'A')] = true;
    words += fmt::format(" {}{}", letter, gcode::word_number(std::abs(deg) < 5e-11 ? 0.0 : deg));
  }
  emit(l, words);
  emit(l, "TRAORI");
  swivel_tip_ = true;
  if (known) {
    AxisPosition q = AxisPosition::zero(machine_.rotary_count());
    q.linear_mm = Eigen::Vector3d(*machine[0], *machine[1], *machine[2]);
    q.rotary_rad = *a;
    base_ = forward(machine_, q, setup_).tip_mm;
    base_known_ = {true, true, true};
  }
}

Drilling Translator::drilling(const ProgramLine& l, const Item& item) {
  const Arguments args{split_arguments(item.text)};
  const auto need = [&](std::size_t i, const char* name) {
    if (!args.given(i)) fail(l, item.column, fmt::format("{}: {} is not given", item.name, name));
    return value(l, item.column, args.text[i]);
  };
  Drilling d;
  d.name = item.name;
  d.retract = need(0, "RTP (the retract plane)");
  d.reference = need(1, "RFP (the reference plane)");
  d.safety = args.given(2) ? std::abs(value(l, item.column, args.text[2])) : 0.0;
  // DPR (relative) wins over DP where it is not 0, as the cycle does ("Depth: corresponding to value for relative
  // depth")
  const double relative = args.given(4) ? std::abs(value(l, item.column, args.text[4])) : 0.0;
  if (relative != 0.0) {
    d.depth = d.reference - relative;
    if (args.given(3) && std::abs(value(l, item.column, args.text[3]) - d.depth) > 1e-9)
      notice_once(
          l, item.name + " DPR",
          fmt::format("{}: DP and DPR differ; the depth is RFP - DPR = {}, as the cycle takes it", item.name, d.depth));
  } else if (args.given(3)) {
    d.depth = value(l, item.column, args.text[3]);
  } else {
    fail(l, item.column, fmt::format("{}: neither DP nor DPR (the depth) is given", item.name));
  }
  if (item.name == "CYCLE82" && args.given(5)) d.dwell_s = value(l, item.column, args.text[5]);
  if (item.name == "CYCLE81" || item.name == "CYCLE82") {
    if (args.text.size() > (item.name == "CYCLE82" ? 6u : 5u))
      fail(l, item.column,
           fmt::format("{}: more parameters than RTP, RFP, SDIS, DP, DPR{} are not read", item.name,
                       item.name == "CYCLE82" ? ", DTB" : ""));
  } else {
    hole_parameters(l, item, args, d);
  }
  if (d.depth >= d.reference + d.safety)
    fail(l, item.column, fmt::format("{}: the depth lies above the safety plane", item.name));
  if (d.dwell_s < 0.0) fail(l, item.column, "CYCLE82: DTB < 0");
  return d;
}

/// The hole at the current X Y of the frame: rapid to the safety plane, feed to the depth, dwell,
/// rapid to the retract plane. Where the frame only shifts and the tool stands on the retract plane
/// (or the retract plane is the safety plane) it is the canned cycle G81/G82 with G98 (G99), which
/// the G-code reader gives as a cl::Cycle; otherwise those motions.
void Translator::drill(const ProgramLine& l, const Drilling& d) {
  if (plane_ != 17) fail(l, 1, fmt::format("{} under G{}: only G17 (drilling along Z) is read", d.name, plane_));
  machine_mm_ = {};  // the hole moves the linear axes
  if (d.tap != Drilling::Tap::none) return tap(l, d);
  if (d.name != "CYCLE81" && d.name != "CYCLE82") return expand_hole(l, d);
  const Eigen::Vector3d at = current_prog(l, 1);
  if (!base_known_[0] || !base_known_[1]) fail(l, 1, fmt::format("{}: X and Y of the hole are not known", d.name));
  const std::array<bool, 3> z_only{false, false, true};
  const auto to_z = [&](double z) { return Eigen::Vector3d(at.x(), at.y(), z); };
  const Frame f = frame();
  const double safety = d.reference + d.safety;
  const bool on_retract = base_known_[2] && std::abs(at.z() - d.retract) < 1e-9;
  if (f.shift_only() && !swivel_tip_ && !traori_ && (on_retract || std::abs(d.retract - safety) < 1e-9)) {
    const Eigen::Vector3d hole = f.apply(at);
    const double dz = f.offset.z();
    emit(l, fmt::format("G{} G{} X{} Y{} Z{} R{}{}", on_retract ? 98 : 99, d.dwell_s > 0.0 ? 82 : 81,
                        gcode::word_number(hole.x()), gcode::word_number(hole.y()), gcode::word_number(d.depth + dz),
                        gcode::word_number(safety + dz), d.dwell_s > 0.0 ? fmt::format(" P{:.4f}", d.dwell_s) : ""));
    emit(l, "G80");
    base_[2] = d.retract + dz;
    base_known_[2] = true;
    return;
  }
  emit(l, "G0" + axis_words(l, to_z(safety), z_only, false));
  emit(l, "G1" + axis_words(l, to_z(d.depth), z_only, false));
  if (d.dwell_s > 0.0) emit(l, fmt::format("G4 P{:.4f}", d.dwell_s));
  emit(l, "G0" + axis_words(l, to_z(d.retract), z_only, false));
}

}  // namespace ncpost::sinumerik
