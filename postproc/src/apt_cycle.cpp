// SPDX-License-Identifier: Apache-2.0
// CYCLE/ statements of NX/CATIA APT, Creo and SOLIDWORKS CAM (apt_cycle.hpp). The kinds and the
// parameter words are tables; anything else stops the post naming the line.
#include "ncpost/postproc/apt_cycle.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ncpost::cl {
namespace {

constexpr double kMmPerInch = 25.4;

/// The leading words of a CYCLE statement that name its kind, as the CAM systems write them.
struct KindEntry {
  const char* words;  ///< comma separated, upper case
  Cycle::Kind kind;
};
constexpr KindEntry kKinds[] = {
    {"DRILL", Cycle::Kind::drill},          {"DRILL,DEEP", Cycle::Kind::deep},
    {"DEEP", Cycle::Kind::deep},            {"DEEP2", Cycle::Kind::deep},
    {"DRILL,BRKCHP", Cycle::Kind::chip_break}, {"BRKCHP", Cycle::Kind::chip_break},
    {"TAP", Cycle::Kind::tap},              {"TAP,FLOAT", Cycle::Kind::tap},
    {"TAP,RIGID", Cycle::Kind::tap},        {"RIGID", Cycle::Kind::tap},
    {"BORE", Cycle::Kind::bore},            {"REAM", Cycle::Kind::bore},
    {"BORE,DRAG", Cycle::Kind::bore_drag},
};

/// The parameter words (each followed by its value).
enum class Param { fedto, rapto, rtrcto, depth, clear, step, first_peck, sub_peck, mmpm, ipm, mmpr, ipr, dwell, tpi, pitch };
struct ParamEntry {
  const char* word;
  Param param;
};
constexpr ParamEntry kParams[] = {
    {"FEDTO", Param::fedto}, {"RAPTO", Param::rapto},     {"RTRCTO", Param::rtrcto},    {"DEPTH", Param::depth},
    {"CLEAR", Param::clear}, {"STEP", Param::step},       {"INCR", Param::step},        {"1STPECK", Param::first_peck},
    {"SUBPECK", Param::sub_peck}, {"MMPM", Param::mmpm},  {"IPM", Param::ipm},          {"MMPR", Param::mmpr},
    {"IPR", Param::ipr},     {"DWELL", Param::dwell},     {"TPI", Param::tpi},          {"PITCH", Param::pitch},
};

const ParamEntry* param_of(const std::string& w) {
  for (const ParamEntry& p : kParams)
    if (w == p.word) return &p;
  return nullptr;
}

std::string known_kinds() {
  std::string s;
  for (const KindEntry& k : kKinds) s += (s.empty() ? "" : "; ") + std::string(k.words);
  return s;
}

}  // namespace

std::optional<Cycle> read_apt_cycle(const AptStatement& st, const AptCycleContext& ctx) {
  const std::string text = "CYCLE/" + st.raw_arguments;
  auto fail = [&](int column, const std::string& what) -> void {
    throw InputError({ctx.file, st.where.line, column > 0 ? column : st.where.column}, what, text);
  };
  const auto& args = st.arguments;
  if (args.empty() || args[0].is_number)
    fail(st.where.column, "CYCLE expects a cycle kind (DRILL, DEEP, TAP, BORE, ...) or OFF first");

  // SOLIDWORKS CAM opens every cycle with CYCLE/INIT (and CYCLE/CLEAR before a new definition):
  // no parameters, nothing to do.
  if (args.size() == 1 && (args[0].word == "INIT" || args[0].word == "CLEAR")) return std::nullopt;

  // the kind: the leading words before the first parameter word or number
  std::size_t i = 0;
  std::string words;
  while (i < args.size() && !args[i].is_number && !param_of(args[i].word)) {
    words += (words.empty() ? "" : ",") + args[i].word;
    ++i;
  }
  if (words == "OFF") {
    Cycle c;
    c.where = st.where;
    c.kind = Cycle::Kind::off;
    c.text = st.raw_arguments;
    return c;
  }

  Cycle c;
  c.where = st.where;
  c.text = st.raw_arguments;
  c.kind_word = words;
  bool known = false;
  for (const KindEntry& k : kKinds)
    if (words == k.words) c.kind = k.kind, known = true;
  if (!known)
    fail(args[0].column, fmt::format("cycle kind '{}' is not known (known: {}); its holes would be cut wrong, so "
                                     "the post stops: post the operation as explicit moves or as one of these kinds",
                                     words.empty() ? args[0].word : words, known_kinds()));

  const double u = ctx.mm_per_unit;
  std::optional<double> fedto, depth, rapto, clear, feed, first_peck, sub_peck, step, tpi, pitch;
  int positional = 0;
  while (i < args.size()) {
    const auto& a = args[i];
    if (a.is_number) {
      // classic APT / CATIA: CYCLE/DRILL,depth,clearance,MMPM,f — numbers without their word
      if (positional == 0) depth = a.number * u;
      else if (positional == 1) clear = a.number * u;
      else fail(a.column, fmt::format("a third number without its word ({}) in CYCLE", a.number));
      ++positional;
      ++i;
      continue;
    }
    const ParamEntry* p = param_of(a.word);
    if (!p) fail(a.column, fmt::format("CYCLE word '{}' is not known (known after the kind: FEDTO, RAPTO, RTRCTO, DEPTH, "
                                       "CLEAR, STEP, INCR, 1STPECK, SUBPECK, MMPM, IPM, MMPR, IPR, DWELL, TPI, PITCH)",
                                       a.word));
    if (p->param == Param::rtrcto && i + 1 < args.size() && !args[i + 1].is_number) {
      // NX: RTRCTO,AUTO — back to the R plane
      if (args[i + 1].word != "AUTO")
        fail(args[i + 1].column, fmt::format("RTRCTO,{} is not known (expected a distance or AUTO)", args[i + 1].word));
      c.retract_mm.reset();
      i += 2;
      continue;
    }
    if (i + 1 >= args.size() || !args[i + 1].is_number) fail(a.column, fmt::format("CYCLE word {} expects a number", a.word));
    const double v = args[i + 1].number;
    switch (p->param) {
      case Param::fedto: fedto = v * u; break;
      case Param::depth: depth = v * u; break;
      case Param::rapto: rapto = v * u; break;
      case Param::clear: clear = v * u; break;
      case Param::rtrcto: c.retract_mm = v * u; break;
      case Param::step: step = v * u; break;
      case Param::first_peck: first_peck = v * u; break;
      case Param::sub_peck: sub_peck = v * u; break;
      case Param::mmpm: feed = v, c.feed_per_rev = false; break;
      case Param::ipm: feed = v * kMmPerInch, c.feed_per_rev = false; break;
      case Param::mmpr: feed = v, c.feed_per_rev = true; break;
      case Param::ipr: feed = v * kMmPerInch, c.feed_per_rev = true; break;
      case Param::dwell: c.dwell_s = v; break;
      case Param::tpi: tpi = v; break;
      case Param::pitch: pitch = v * u; break;
    }
    i += 2;
  }

  // depth below the GOTO point
  if (fedto && depth) fail(st.where.column, "CYCLE gives both FEDTO and DEPTH");
  if (fedto) c.depth_mm = ctx.signed_fedto ? -*fedto : std::abs(*fedto);
  else if (depth) c.depth_mm = *depth;
  else fail(st.where.column, "CYCLE without a depth (FEDTO or DEPTH)");
  // the R plane above it
  if (rapto && clear) fail(st.where.column, "CYCLE gives both RAPTO and CLEAR");
  c.rapid_to_mm = rapto ? *rapto : clear ? *clear : 0.0;
  if (!(c.rapid_to_mm + c.depth_mm > 0.0))
    fail(st.where.column, fmt::format("CYCLE: the bottom ({:.4f} mm below the hole point) is not below the R plane "
                                      "({:.4f} mm above it)", c.depth_mm, c.rapid_to_mm));
  if (c.retract_mm && *c.retract_mm < c.rapid_to_mm)
    fail(st.where.column, fmt::format("CYCLE: the retract plane RTRCTO ({:.4f} mm) is below the R plane ({:.4f} mm)",
                                      *c.retract_mm, c.rapid_to_mm));
  if (c.dwell_s < 0.0) fail(st.where.column, "CYCLE: negative DWELL");
  c.feed = feed;
  if (feed && !(*feed > 0.0)) fail(st.where.column, "CYCLE: the feed must be positive");

  // pecks
  const bool pecking = c.kind == Cycle::Kind::deep || c.kind == Cycle::Kind::chip_break;
  if (step && sub_peck) fail(st.where.column, "CYCLE gives both a peck (STEP/INCR) and SUBPECK");
  c.peck_mm = step ? *step : sub_peck ? *sub_peck : first_peck ? *first_peck : 0.0;
  c.first_peck_mm = first_peck ? *first_peck : c.peck_mm;
  if (pecking && !(c.peck_mm > 0.0 && c.first_peck_mm > 0.0))
    fail(st.where.column, fmt::format("CYCLE/{}: a peck cycle without a positive peck depth (STEP, INCR, 1STPECK, SUBPECK)",
                                      words));
  if (!pecking && (step || sub_peck || first_peck))
    fail(st.where.column, fmt::format("CYCLE/{}: a peck depth on a cycle that does not peck", words));

  // thread
  if (tpi && pitch) fail(st.where.column, "CYCLE gives both TPI and PITCH");
  if (tpi) {
    if (!(*tpi > 0.0)) fail(st.where.column, "CYCLE: TPI must be positive");
    c.pitch_mm = kMmPerInch / *tpi;
  } else if (pitch) {
    c.pitch_mm = *pitch;
  }
  if (c.kind == Cycle::Kind::tap) {
    if (c.pitch_mm <= 0.0 && !(feed && c.feed_per_rev))
      fail(st.where.column, "CYCLE/TAP without the thread pitch (TPI, PITCH, or a feed per revolution MMPR/IPR)");
    if (c.pitch_mm <= 0.0) c.pitch_mm = *feed;  // the feed per revolution is the pitch
    else if (feed && c.feed_per_rev && std::abs(*feed - c.pitch_mm) > 1e-3 * c.pitch_mm)
      fail(st.where.column, fmt::format("CYCLE/TAP: the feed per revolution {:.4f} mm is not the pitch {:.4f} mm",
                                        *feed, c.pitch_mm));
  } else if (c.pitch_mm > 0.0) {
    fail(st.where.column, fmt::format("CYCLE/{}: a thread pitch on a cycle that does not tap", words));
  }
  return c;
}

}  // namespace ncpost::cl
