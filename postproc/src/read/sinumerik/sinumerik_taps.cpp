// SPDX-License-Identifier: Apache-2.0
// CYCLE84 (rigid tapping) and CYCLE840 (tapping with a compensating chuck) of the Sinumerik
// translator (sinumerik_translator.hpp), posted as the ISO tap G84 (right-hand) / G74 (left-hand).
// Parameters as in the SINUMERIK 840D sl "Programming Manual Cycles" (docs/formats.md, "Sinumerik
// tapping cycles"); RTP RFP SDIS DP DPR first, as in CYCLE81 (Translator::drilling):
//   CYCLE84(RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT, PIT, POSS, SST, SST1, _AXN, _PTAB, _TECHNO, _VARI, _DAM, _VRT)
//   CYCLE840(RTP, RFP, SDIS, DP, DPR, DTB, SDR, SDAC, ENC, MPIT, PIT, _AXN, _PTAB, _TECHNO)
// Both: rapid to RFP + SDIS, tap to the depth, the spindle reversed, back to RFP + SDIS at the
// thread's feed, rapid to RTP, then the spindle as SDAC says. MPIT is the metric coarse thread
// size (M3 .. M48: its pitch from ISO 261), PIT the pitch itself; their sign is the thread's hand
// (+ right, - left).
#include <fmt/format.h>

#include <cmath>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"

namespace ncpost::sinumerik {
namespace {

/// ISO 261 coarse pitches (mm) of the metric thread sizes MPIT names.
struct CoarseThread {
  int size;
  double pitch_mm;
};
constexpr CoarseThread kCoarse[] = {{3, 0.5},  {4, 0.7},  {5, 0.8},  {6, 1.0},  {8, 1.25}, {10, 1.5}, {12, 1.75},
                                    {14, 2.0}, {16, 2.0}, {18, 2.5}, {20, 2.5}, {22, 2.5}, {24, 3.0}, {27, 3.0},
                                    {30, 3.5}, {33, 3.5}, {36, 4.0}, {39, 4.0}, {42, 4.5}, {45, 4.5}, {48, 5.0}};

/// The argument positions of the two cycles.
struct TapLayout {
  std::size_t spindle_after, mpit, pit, axis, pitch_unit, techno, count;
};
constexpr TapLayout kCycle84{6, 7, 8, 12, 13, 14, 18};
constexpr TapLayout kCycle840{7, 9, 10, 11, 12, 13, 14};

}  // namespace

/// The signed pitch (mm; > 0 right-hand) from MPIT or PIT and _PTAB.
double Translator::tap_pitch(const ProgramLine& l, const Item& item, const Arguments& args, std::size_t mpit,
                             std::size_t pit, std::size_t unit) const {
  const auto num = [&](std::size_t i) { return args.given(i) ? value(l, item.column, args.text[i]) : 0.0; };
  std::optional<double> by_size;
  if (num(mpit) != 0.0) {
    for (const CoarseThread& t : kCoarse)
      if (std::abs(num(mpit)) == t.size) by_size = std::copysign(t.pitch_mm, num(mpit));
    if (!by_size)
      fail(l, item.column,
           fmt::format("{}: MPIT={} is no metric coarse thread size (3, 4, 5, 6, 8, 10 ... 48); give the pitch PIT",
                       item.name, num(mpit)));
  }
  const double ptab = num(unit);
  double by_value = num(pit);
  if (ptab == 2.0)
    by_value = by_value == 0.0 ? 0.0 : std::copysign(25.4 / std::abs(by_value), by_value);  // threads per inch
  else if (ptab == 3.0)
    by_value *= 25.4;  // inch per revolution
  else if (ptab != 0.0 && ptab != 1.0)
    fail(l, item.column,
         fmt::format("{}: _PTAB={} (the pitch's unit: 0 or 1 mm, 2 threads/inch, 3 inch)", item.name, ptab));
  if (by_size && by_value != 0.0 && std::abs(*by_size - by_value) > 1e-9)
    fail(l, item.column,
         fmt::format("{}: MPIT={} (pitch {} mm) and PIT={} disagree (the control stops with a thread-pitch alarm)",
                     item.name, num(mpit), *by_size, num(pit)));
  const double pitch = by_size ? *by_size : by_value;
  if (pitch == 0.0) fail(l, item.column, fmt::format("{}: neither MPIT nor PIT gives the thread's pitch", item.name));
  return pitch;
}

/// The parameters after DPR of CYCLE84 and CYCLE840; what changes the motions and is not read is refused by name.
void Translator::tap_parameters(const ProgramLine& l, const Item& item, const Arguments& args, Drilling& d) const {
  const auto num = [&](std::size_t i) { return args.given(i) ? value(l, item.column, args.text[i]) : 0.0; };
  const bool rigid = item.name == "CYCLE84";
  const TapLayout& at = rigid ? kCycle84 : kCycle840;
  for (std::size_t i = at.count; i < args.text.size(); ++i)
    if (num(i) != 0.0)
      fail(l, item.column,
           fmt::format("{}: parameter {} ({}, a mode of SINUMERIK Operate) is not read", item.name, i + 1,
                       args.text[i]));
  if (d.dwell_s != 0.0)
    fail(l, item.column,
         fmt::format("{}: DTB={} (a dwell at the thread's depth) is not read: the posted tap G84 reverses at once; "
                     "program DTB=0",
                     item.name, d.dwell_s));
  if (num(at.axis) != 0.0 && num(at.axis) != 3.0)
    fail(l, item.column, fmt::format("{} _AXN={}: only the tool axis Z (0 or 3) is read", item.name, num(at.axis)));
  d.spindle_after = static_cast<int>(num(at.spindle_after));
  if (d.spindle_after < 3 || d.spindle_after > 5 || num(at.spindle_after) != d.spindle_after)
    fail(l, item.column,
         fmt::format("{}: SDAC={} (the spindle after the cycle: 3, 4 or 5)", item.name, num(at.spindle_after)));
  d.tap = rigid ? Drilling::Tap::rigid : Drilling::Tap::floating;
  if (rigid) {
    if (num(15) != 0.0)
      fail(
          l, item.column,
          fmt::format("CYCLE84 _VARI={}: deep-hole tapping (chip breaking or removal) is not read; only 0 (in one cut)",
                      num(15)));
    d.tap_rpm = num(10);
    if (!(d.tap_rpm > 0.0))
      fail(l, item.column, fmt::format("CYCLE84: SST={} (the tapping speed must be > 0)", num(10)));
    if (num(11) != 0.0 && num(11) != d.tap_rpm)
      fail(l, item.column,
           fmt::format("CYCLE84: SST1={} (a retraction speed other than SST={}) is not read: the posted tap G84 comes "
                       "out at the tapping speed; program SST1=0",
                       num(11), d.tap_rpm));
    d.pitch_mm = tap_pitch(l, item, args, at.mpit, at.pit, at.pitch_unit);
    return;
  }
  const double retract_dir = num(6), encoder = num(8);
  if (encoder != 0.0 && encoder != 1.0)
    fail(l, item.column,
         fmt::format("CYCLE840: ENC={}: only 0 (with encoder: the feed from the pitch) and 1 (without: the F "
                     "programmed before) are read",
                     encoder));
  d.with_encoder = encoder == 0.0;
  if (d.with_encoder) d.pitch_mm = tap_pitch(l, item, args, at.mpit, at.pit, at.pitch_unit);
  if (retract_dir != 0.0 && retract_dir != 3.0 && retract_dir != 4.0)
    fail(l, item.column,
         fmt::format("CYCLE840: SDR={} (the spindle out of the thread: 0 reversed, 3 or 4)", retract_dir));
  d.retract_spindle = static_cast<int>(retract_dir);
}

/// The thread's hand (true: left): CYCLE84's pitch sign; CYCLE840 taps as the spindle turns (with
/// an encoder its pitch sign must agree); refused where they disagree or SDR goes the way in.
bool Translator::tap_left_hand(const ProgramLine& l, const Drilling& d) const {
  if (d.tap == Drilling::Tap::rigid) return d.pitch_mm < 0.0;
  const bool m4_before = spindle_direction_ == 4;
  if (spindle_direction_ != 3 && spindle_direction_ != 4)
    fail(l, 1, "CYCLE840 with the spindle not turning (no M3 or M4 before): the thread's hand is not known");
  if (!(spindle_rpm_ > 0.0)) fail(l, 1, "CYCLE840 before any spindle speed S: the thread's pitch (F / S) is not known");
  const bool left = d.with_encoder ? d.pitch_mm < 0.0 : m4_before;
  if (d.with_encoder && left != m4_before)
    fail(l, 1,
         fmt::format("CYCLE840 with a {}-hand thread (the sign of MPIT/PIT) and the spindle {}: program {}",
                     left ? "left" : "right", m4_before ? "M4" : "M3", left ? "M4" : "M3"));
  if (d.retract_spindle != 0 && (d.retract_spindle == 4) == left)
    fail(l, 1,
         fmt::format("CYCLE840: SDR={} turns the spindle out of the thread the way it went in", d.retract_spindle));
  return left;
}

/// The tap at the current X Y: G84 / G74 with G98 (the tool on RTP) or G99 (RTP is the safety
/// plane), the thread's feed, the spindle as SDAC says after it and the programmed F again.
void Translator::tap(const ProgramLine& l, const Drilling& d) {
  const Eigen::Vector3d at = current_prog(l, 1);
  if (!base_known_[0] || !base_known_[1] || !base_known_[2])
    fail(l, 1, fmt::format("{}: X, Y and Z of the tool before the tap are not known", d.name));
  const Frame f = frame();
  if (!f.shift_only() || swivel_tip_ || traori_)
    fail(l, 1,
         fmt::format("{} in a rotated, scaled or swivelled frame or under TRAORI is not read (the posted tap runs "
                     "along machine Z)",
                     d.name));
  if (inch_) fail(l, 1, fmt::format("{} in an inch program (G70/G700) is not read", d.name));
  if (feed_mode_ == 93) fail(l, 1, fmt::format("{} under G93 (inverse-time feed) is not read", d.name));
  const double safety = d.reference + d.safety;
  if (at.z() < safety - 1e-9)
    fail(l, 1, fmt::format("{}: the tool stands below the safety plane RFP + SDIS = {}", d.name, safety));
  const bool left = tap_left_hand(l, d);
  const double rpm = d.tap == Drilling::Tap::rigid ? d.tap_rpm : spindle_rpm_;
  double feed = feed_mode_ == 95 ? std::abs(d.pitch_mm) : std::abs(d.pitch_mm) * rpm;
  if (d.tap == Drilling::Tap::floating && !d.with_encoder) {
    if (!(feed_ > 0.0)) fail(l, 1, "CYCLE840 without encoder (ENC=1) before any F: the tapping feed is the F before");
    feed = feed_;
  }
  const Eigen::Vector3d hole = f.apply(at);
  const double dz = f.offset.z();
  if (d.tap == Drilling::Tap::rigid) emit(l, fmt::format("S{} M{}", gcode::word_number(rpm), left ? 4 : 3));
  const bool on_retract = std::abs(at.z() - d.retract) < 1e-9;
  if (!on_retract && std::abs(d.retract - safety) >= 1e-9) {  // to RTP first, along the hole's axis (above it)
    emit(l, fmt::format("G0 Z{}", gcode::word_number(d.retract + dz)));
    notice_once(l, d.name + " RTP",
                fmt::format("{}: the tool goes to the retract plane RTP first, on the hole's axis, so the posted "
                            "tap (G98) comes back there",
                            d.name));
  }
  emit(l, fmt::format("G{} G{} X{} Y{} Z{} R{} F{}", std::abs(d.retract - safety) < 1e-9 ? 99 : 98, left ? 74 : 84,
                      gcode::word_number(hole.x()), gcode::word_number(hole.y()), gcode::word_number(d.depth + dz),
                      gcode::word_number(safety + dz), gcode::word_number(feed)));
  emit(l, "G80");
  emit(l, fmt::format("M{}", d.spindle_after));
  if (feed_ > 0.0 && feed_ != feed) emit(l, "F" + gcode::word_number(feed_));
  base_[2] = d.retract + dz;
  base_known_[2] = true;
  spindle_direction_ = d.spindle_after;
  if (d.tap == Drilling::Tap::rigid) spindle_rpm_ = rpm;
}

}  // namespace ncpost::sinumerik
