// SPDX-License-Identifier: Apache-2.0
// Cutter radius compensation in the post (poster.hpp): CUTCOM/LEFT|RIGHT|OFF as G41/G42 D<n> / G40
// (cycle_words.hpp `comp_words`), and the moves it allows.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/postproc/write/cycle_words.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {

/// CUTCOM/LEFT|RIGHT|OFF as G41/G42 D<n> / G40 (cycle_words.hpp `comp_words`).
void Poster::on(const cl::CutterComp& c) {
  const SourcePosition at{input_, c.where.line, c.where.column};
  if (!words_.cutter_comp_supported && c.side != cl::CutterComp::Side::off)
    throw InputError(at,
                     fmt::format("cutter radius compensation is not posted on the {} machine (its control "
                                 "compensates in no plane of these axes): post the tool centre path without "
                                 "CUTCOM",
                                 machine_.name),
                     "CUTCOM/" + c.text);
  if (!words_.cutter_comp_supported) return;  // CUTCOM/OFF: nothing was on
  const auto words = comp_words(writer_.dialect());
  if (!words)
    throw InputError(at,
                     fmt::format("CUTCOM: the {} dialect writes no radius compensation ([compensation] native "
                                 "= false in {}); post with a dialect that has it, or post the path without "
                                 "CUTCOM",
                                 writer_.dialect().name, writer_.dialect().file),
                     "CUTCOM/" + c.text);
  comp_ = c;
  if (c.side == cl::CutterComp::Side::off) {
    writer_.block(words->off);
    return;
  }
  if (words->register_letter.empty() && c.offset_register && *c.offset_register != tool_)
    // (Sinumerik: G41/G42 take the radius of the edge the tool call selected, D1)
    throw InputError(at,
                     fmt::format("CUTCOM/{}: radius register {} cannot be written in the {} dialect (G41/G42 "
                                 "take the radius of the active tool's edge: [compensation] register_letter is "
                                 "empty in {}); give the tool's own radius (CUTCOM/{} without a register), or "
                                 "post with a dialect that writes one (fanuc, haas, linuxcnc)",
                                 c.text, *c.offset_register, writer_.dialect().name, writer_.dialect().file,
                                 c.side == cl::CutterComp::Side::left ? "LEFT" : "RIGHT"),
                     "CUTCOM/" + c.text);
  if (!words->register_letter.empty() && !c.offset_register && !tool_numbered_)
    throw InputError(at,
                     fmt::format("{}: the {} dialect names the radius register, by default the tool's number, "
                                 "but the tool was called by name: give its number in a tool table "
                                 "(--tool-table FILE; docs/formats.md, Tool tables)",
                                 c.text, writer_.dialect().name),
                     c.text);
  const int reg = c.offset_register.value_or(tool_);
  writer_.block((c.side == cl::CutterComp::Side::left ? words->left : words->right) +
                (words->register_letter.empty() ? std::string() : " " + words->register_letter + std::to_string(reg)));
}

/// With G41/G42 active the motion must keep the tool axis and have it along Z of the program
/// frame (the control compensates in the XY plane): else the post stops.
void Poster::check_comp(const cl::Motion& m) {
  if (!comp_ || comp_->side == cl::CutterComp::Side::off || !have_position_) return;
  const std::string side = comp_->side == cl::CutterComp::Side::left ? "LEFT" : "RIGHT";
  const SourcePosition at{input_, m.where.line, m.where.column};
  if (m.point.axis.cross(previous_.cl.axis).norm() > 1e-9)
    throw InputError(at, fmt::format("CUTCOM/{} (line {}) is active in a simultaneous five-axis move (the tool axis "
                                     "turns): G41/G42 compensate in a plane normal to a fixed tool axis; post the "
                                     "path without CUTCOM (the CL data are then the tool centre path)",
                                     side, comp_->where.line));
  if (plane_) return;  // the plane's Z is the tool axis: G41/G42 compensate in its XY
  const Vec3d tip =
      options_.rtcp ? previous_.cl.tip_mm : solver_.with_rotary(previous_.cl, previous_.q.rotary_rad, data_).linear_mm;
  const Vec3d up = options_.rtcp ? Vec3d(previous_.cl.tip_mm + previous_.cl.axis)
                                 : solver_
                                       .with_rotary(ClPoint{previous_.cl.tip_mm + previous_.cl.axis, previous_.cl.axis},
                                                    previous_.q.rotary_rad, data_)
                                       .linear_mm;
  if ((up - tip - Vec3d::UnitZ()).norm() > 1e-6)
    throw InputError(at, fmt::format("CUTCOM/{} (line {}): the tool axis is not along Z of the program frame here, "
                                     "and G41/G42 compensate in the XY plane; post the path without CUTCOM",
                                     side, comp_->where.line));
}

}  // namespace ncpost::detail
