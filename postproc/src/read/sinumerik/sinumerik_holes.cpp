// SPDX-License-Identifier: Apache-2.0
// CYCLE83 (deep-hole drilling), CYCLE85 (boring with feed out) and CYCLE86 (boring with spindle
// stop) of the Sinumerik translator (sinumerik_translator.hpp), written as their motions. The
// parameters and sequences are those of the SINUMERIK 840D sl "Programming Manual Cycles"
// (docs/formats.md, "Sinumerik drilling cycles"); RTP RFP SDIS DP DPR come first in each, as in
// CYCLE81 (Translator::drilling):
//   CYCLE83(RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI, _AXN, _MDEP, _VRT, _DTD, _DIS1)
//   CYCLE85(RTP, RFP, SDIS, DP, DPR, DTB, FFR, RFF)
//   CYCLE86(RTP, RFP, SDIS, DP, DPR, DTB, SDIR, RPA, RPO, RPAP, POSS)
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"

namespace ncpost::sinumerik {
namespace {

constexpr double kEps = 1e-9;

/// The bottoms of the infeeds from the reference plane down to `depth`: the first at `first`,
/// each further infeed `degression` shorter than the one before while longer than `degression`,
/// then infeeds of `degression` while more than twice it remains, the last two splitting the
/// rest equally (degression 0: every infeed as long as the first, the last what remains).
std::vector<double> stroke_bottoms(double reference, double first, double depth, double degression) {
  std::vector<double> bottoms{std::max(first, depth)};
  double stroke = reference - first;
  while (bottoms.back() > depth + kEps) {
    const double left = bottoms.back() - depth;
    stroke = std::max(stroke - degression, degression);
    if (left <= stroke + kEps) {
      bottoms.push_back(depth);
    } else if (degression > 0.0 && stroke <= degression + kEps && left < 2.0 * degression) {
      bottoms.push_back(bottoms.back() - left / 2.0);
      bottoms.push_back(depth);
    } else {
      bottoms.push_back(bottoms.back() - stroke);
    }
  }
  return bottoms;
}

}  // namespace

/// The parameters after DPR of CYCLE83, CYCLE85 and CYCLE86; what would change the motions and is
/// not read is refused by name.
void Translator::hole_parameters(const ProgramLine& l, const Item& item, const Arguments& args, Drilling& d) const {
  const auto num = [&](std::size_t i) { return args.given(i) ? value(l, item.column, args.text[i]) : 0.0; };
  const auto unread_after = [&](std::size_t count, const char* names) {
    for (std::size_t i = count; i < args.text.size(); ++i)
      if (num(i) != 0.0)
        fail(l, item.column,
             fmt::format("{}: parameter {} ({}) is not read; only {} are", item.name, i + 1, args.text[i], names));
  };
  d.dwell_s = num(5);
  if (item.name != "CYCLE83" && d.dwell_s < 0.0)
    fail(l, item.column,
         fmt::format("{}: DTB={} (a dwell in spindle turns) is not read; give seconds", item.name, d.dwell_s));
  if (item.name == "CYCLE83") return deep_hole_parameters(l, item, args, d);
  if (item.name == "CYCLE84" || item.name == "CYCLE840") return tap_parameters(l, item, args, d);
  if (item.name == "CYCLE85") {
    unread_after(8, "RTP, RFP, SDIS, DP, DPR, DTB, FFR, RFF");
    d.feed_in = num(6), d.feed_out = num(7);
    if (!(d.feed_in > 0.0) || !(d.feed_out > 0.0))
      fail(l, item.column,
           fmt::format("CYCLE85: FFR={} and RFF={} (the feeds in and out) must be > 0", num(6), num(7)));
    return;
  }
  unread_after(11, "RTP, RFP, SDIS, DP, DPR, DTB, SDIR, RPA, RPO, RPAP, POSS");
  if (num(7) != 0.0 || num(8) != 0.0 || num(9) != 0.0)
    fail(l, item.column,
         fmt::format("CYCLE86 with a lift-off (RPA={} RPO={} RPAP={}) is not read: the cycles manual fixes the "
                     "motions (an oriented spindle stop at POSS={}, then the lift-off incremental along the plane's "
                     "axes and the tool axis, out to RFP+SDIS, back over the hole at RTP), but the lift-off is safe "
                     "only with the cutting edge turned away from the wall by that oriented stop, which the posted "
                     "program has no word for (it stops the spindle with M5 anywhere); set RPA RPO RPAP to 0 (no "
                     "lift-off) or post the CL data",
                     gcode::word_number(num(7)), gcode::word_number(num(8)), gcode::word_number(num(9)),
                     gcode::word_number(num(10))));
  d.spindle_after = static_cast<int>(num(6));
  if (num(6) != 3.0 && num(6) != 4.0)
    fail(l, item.column, fmt::format("CYCLE86: SDIR={} (the spindle after the cycle: 3 or 4)", num(6)));
}

void Translator::deep_hole_parameters(const ProgramLine& l, const Item& item, const Arguments& args,
                                      Drilling& d) const {
  const auto num = [&](std::size_t i) { return args.given(i) ? value(l, item.column, args.text[i]) : 0.0; };
  for (std::size_t i = 17; i < args.text.size(); ++i)
    if (num(i) != 0.0)
      fail(l, item.column,
           fmt::format("CYCLE83: parameter {} ({}, a mode of SINUMERIK Operate) is not read", i + 1, args.text[i]));
  const double axis = num(12), vari = num(11), degression = num(7), factor = args.given(10) ? num(10) : 1.0;
  if (axis != 0.0 && axis != 3.0)
    fail(l, item.column, fmt::format("CYCLE83 _AXN={}: only the tool axis Z (0 or 3) is read", axis));
  if (vari != 0.0 && vari != 1.0)
    fail(l, item.column, fmt::format("CYCLE83 VARI={}: only 0 (chip breaking) and 1 (chip removal) are read", vari));
  if (degression < 0.0)
    fail(l, item.column,
         fmt::format("CYCLE83 DAM={}: a negative degression is not read: the SINUMERIK 840D sl cycles manual gives DAM "
                     "as a length (each infeed that much shorter than the one before, DAM 0: all as long as the first) "
                     "and leaves open what a negative DAM does (a factor of the last infeed, or a percentage as "
                     "ShopMill's input screen offers, is the cycle version's own); give the degression as a length "
                     "(DAM > 0) or 0",
                     gcode::word_number(degression)));
  if (!(factor >= 0.0 && factor <= 1.0))
    fail(l, item.column, fmt::format("CYCLE83 FRF={}: the feed factor lies in 0.001 .. 1", factor));
  for (const auto& [i, name] : {std::pair<std::size_t, const char*>{8, "DTB"}, {9, "DTS"}, {15, "_DTD"}})
    if (num(i) < 0.0)
      fail(l, item.column,
           fmt::format("CYCLE83: {}={} is a dwell in spindle turns, which is not read; give seconds", name, num(i)));
  double first = d.depth;
  if (args.given(6) && num(6) != 0.0)
    first = d.reference - std::abs(num(6));  // FDPR, relative to RFP, wins as DPR does
  else if (args.given(5))
    first = num(5);
  if (first < d.depth - kEps)
    fail(l, item.column, fmt::format("CYCLE83: the first depth {} lies below the final depth {}", first, d.depth));
  if (first >= d.reference - kEps)
    fail(l, item.column, fmt::format("CYCLE83: the first depth {} does not lie below RFP {}", first, d.reference));
  d.stroke_bottoms = stroke_bottoms(d.reference, first, d.depth, degression);
  d.chip_removal = vari == 1.0;
  d.first_feed_factor = factor == 0.0 ? 1.0 : factor;
  d.dwell_s = num(8);
  d.top_dwell_s = num(9);
  d.final_dwell_s = num(15) > 0.0 ? num(15) : d.dwell_s;
  d.back_off = num(14) > 0.0 ? num(14) : 1.0;
  const double hole = d.reference - d.depth;
  d.anticipation = num(16) > 0.0 ? num(16) : hole <= 30.0 ? 0.6 : std::min(hole / 50.0, 7.0);
}

/// `g` (G0, G1) to `z` on the frame's Z at `at`'s X Y, with F`feed` where it is > 0.
void Translator::hole_move(const ProgramLine& l, const Eigen::Vector3d& at, const char* g, double z, double feed) {
  std::string s = g + axis_words(l, Eigen::Vector3d(at.x(), at.y(), z), {false, false, true}, false);
  if (feed > 0.0) s += " F" + gcode::word_number(feed);
  emit(l, s);
}

/// CYCLE83/85/86 at the current X Y of the frame, along its Z (G17): the motions, each feed given
/// on its block and the programmed F back on the last (the cycles keep F).
void Translator::expand_hole(const ProgramLine& l, const Drilling& d) {
  const Eigen::Vector3d at = current_prog(l, 1);
  if (!base_known_[0] || !base_known_[1]) fail(l, 1, fmt::format("{}: X and Y of the hole are not known", d.name));
  if (feed_mode_ == 93) fail(l, 1, fmt::format("{} under G93 (inverse-time feed) is not read", d.name));
  if (!(feed_ > 0.0)) fail(l, 1, fmt::format("{} before any F: program the feed before the cycle", d.name));
  if (d.name == "CYCLE83") return deep_hole_motions(l, d, at);
  const auto to = [&](const char* g, double z, double feed) { hole_move(l, at, g, z, feed); };
  const double safety = d.reference + d.safety;
  to("G0", safety, 0.0);
  to("G1", d.depth, d.name == "CYCLE85" ? d.feed_in : feed_);
  if (d.dwell_s > 0.0) emit(l, fmt::format("G4 P{:.4f}", d.dwell_s));
  if (d.name == "CYCLE85") {
    to("G1", safety, d.feed_out);
  } else {
    notice_once(l, "CYCLE86 SPOS",
                "CYCLE86: the spindle stops at the bottom (M5); its oriented stop POSS is the control's and is not "
                "posted (no lift-off is read)");
    emit(l, "M5");
    to("G0", safety, 0.0);
  }
  to("G0", d.retract, feed_);
  if (d.name == "CYCLE86") emit(l, fmt::format("M{}", d.spindle_after));
}

/// CYCLE83: the first infeed at F * FRF, the others at F; after each, out to the safety plane and
/// back in rapid to the anticipation distance above the last bottom (VARI=1), or back off by _VRT
/// at F (VARI=0); dwell DTB at each bottom (_DTD at the last), DTS at the top; rapid to RTP.
void Translator::deep_hole_motions(const ProgramLine& l, const Drilling& d, const Eigen::Vector3d& at) {
  const auto to = [&](const char* g, double z, double feed) { hole_move(l, at, g, z, feed); };
  const auto dwell = [&](double s) {
    if (s > 0.0) emit(l, fmt::format("G4 P{:.4f}", s));
  };
  const double safety = d.reference + d.safety;
  to("G0", safety, 0.0);
  for (std::size_t i = 0; i < d.stroke_bottoms.size(); ++i) {
    const bool last = i + 1 == d.stroke_bottoms.size();
    to("G1", d.stroke_bottoms[i], i == 0 ? feed_ * d.first_feed_factor : feed_);
    dwell(last ? d.final_dwell_s : d.dwell_s);
    if (last) break;
    if (d.chip_removal) {
      to("G0", safety, 0.0);
      dwell(d.top_dwell_s);
      const double reentry = std::min(d.stroke_bottoms[i] + d.anticipation, safety);
      if (reentry < safety - kEps) to("G0", reentry, 0.0);
    } else {
      to("G1", d.stroke_bottoms[i] + d.back_off, feed_);
    }
  }
  to("G0", d.retract, feed_);
}

}  // namespace ncpost::sinumerik
