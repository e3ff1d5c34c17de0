// SPDX-License-Identifier: Apache-2.0
// CYCLE/ statements of NX/CATIA APT, Creo and SOLIDWORKS CAM (apt_cycle.hpp). The kinds and the
// parameter words are tables; anything else stops the post naming the line.
#include "ncpost/postproc/read/apt/apt_cycle.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ncpost::cl {
namespace {

/// The leading words of a CYCLE statement that name its kind, as the CAM systems write them.
struct KindEntry {
  const char* words;  ///< comma separated, upper case
  Cycle::Kind kind;
};
constexpr KindEntry kKinds[] = {
    {"DRILL", Cycle::Kind::drill},
    {"DRILL,DEEP", Cycle::Kind::deep},
    {"DEEP", Cycle::Kind::deep},
    {"DEEP2", Cycle::Kind::deep},
    {"DRILL,BRKCHP", Cycle::Kind::chip_break},
    {"BRKCHP", Cycle::Kind::chip_break},
    {"TAP", Cycle::Kind::tap},
    {"TAP,FLOAT", Cycle::Kind::tap},
    {"TAP,RIGID", Cycle::Kind::tap},
    {"RIGID", Cycle::Kind::tap},
    {"BORE", Cycle::Kind::bore},
    {"REAM", Cycle::Kind::bore},
    {"BORE,DRAG", Cycle::Kind::bore_drag},
};

/// The parameter words (each followed by its value).
enum class Param {
  fedto,
  rapto,
  rtrcto,
  depth,
  clear,
  step,
  first_peck,
  sub_peck,
  mmpm,
  ipm,
  mmpr,
  ipr,
  dwell,
  tpi,
  pitch
};
struct ParamEntry {
  const char* word;
  Param param;
};
constexpr ParamEntry kParams[] = {
    {"FEDTO", Param::fedto},      {"RAPTO", Param::rapto}, {"RTRCTO", Param::rtrcto}, {"DEPTH", Param::depth},
    {"CLEAR", Param::clear},      {"STEP", Param::step},   {"INCR", Param::step},     {"1STPECK", Param::first_peck},
    {"SUBPECK", Param::sub_peck}, {"MMPM", Param::mmpm},   {"IPM", Param::ipm},       {"MMPR", Param::mmpr},
    {"IPR", Param::ipr},          {"DWELL", Param::dwell}, {"TPI", Param::tpi},       {"PITCH", Param::pitch},
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

/// A tap's feed per revolution and its pitch differ by more than this fraction: refused.
constexpr double kPitchFeedRelTol = 1e-3;

/// Throws the InputError of the statement (column 0: the statement's).
struct Fail {
  const AptStatement& st;
  const AptCycleContext& ctx;
  const std::string& text;
  [[noreturn]] void operator()(int column, const std::string& what) const {
    throw InputError({ctx.file, st.where.line, column > 0 ? column : st.where.column}, what, text);
  }
};

/// The parameter values of a CYCLE statement, in mm (feeds in mm/min or mm/rev), as given.
struct CycleParams {
  std::optional<double> fedto, depth, rapto, clear, feed, first_peck, sub_peck, step, tpi, pitch;
};

/// The parameters that are lengths in the program's unit, and where they go.
struct LengthParam {
  Param param;
  std::optional<double> CycleParams::*field;
};
constexpr LengthParam kLengthParams[] = {
    {Param::fedto, &CycleParams::fedto},       {Param::depth, &CycleParams::depth},
    {Param::rapto, &CycleParams::rapto},       {Param::clear, &CycleParams::clear},
    {Param::step, &CycleParams::step},         {Param::first_peck, &CycleParams::first_peck},
    {Param::sub_peck, &CycleParams::sub_peck}, {Param::pitch, &CycleParams::pitch},
};

/// One parameter's value `v` (as written, `u` the length unit in mm) into `p`, or into `c` (RTRCTO,
/// DWELL, the feed mode).
void set_param(Param param, double v, double u, CycleParams& p, Cycle& c) {
  for (const LengthParam& l : kLengthParams)
    if (l.param == param) {
      p.*l.field = v * u;
      return;
    }
  if (param == Param::rtrcto) {
    c.retract_mm = v * u;
  } else if (param == Param::dwell) {
    c.dwell_s = v;
  } else if (param == Param::tpi) {
    p.tpi = v;
  } else {  // MMPM, IPM, MMPR, IPR
    p.feed = param == Param::mmpm || param == Param::mmpr ? v : v * kMmPerInch;
    c.feed_per_rev = param == Param::mmpr || param == Param::ipr;
  }
}

/// The parameters from args[i] on (word and value, or classic APT positional depth and clearance);
/// RTRCTO, DWELL and the feed mode go straight into `c`.
CycleParams read_params(const std::vector<AptStatement::Argument>& args, std::size_t i, double u, const Fail& fail,
                        Cycle& c) {
  CycleParams p;
  int positional = 0;
  while (i < args.size()) {
    const auto& a = args[i];
    if (a.is_number) {
      // classic APT / CATIA: CYCLE/DRILL,depth,clearance,MMPM,f — numbers without their word
      if (positional == 0)
        p.depth = a.number * u;
      else if (positional == 1)
        p.clear = a.number * u;
      else
        fail(a.column, fmt::format("a third number without its word ({}) in CYCLE", a.number));
      ++positional;
      ++i;
      continue;
    }
    const ParamEntry* e = param_of(a.word);
    if (!e)
      fail(a.column, fmt::format("CYCLE word '{}' is not known (known after the kind: FEDTO, RAPTO, RTRCTO, DEPTH, "
                                 "CLEAR, STEP, INCR, 1STPECK, SUBPECK, MMPM, IPM, MMPR, IPR, DWELL, TPI, PITCH)",
                                 a.word));
    if (e->param == Param::rtrcto && i + 1 < args.size() && !args[i + 1].is_number) {
      // NX: RTRCTO,AUTO — back to the R plane
      if (args[i + 1].word != "AUTO")
        fail(args[i + 1].column, fmt::format("RTRCTO,{} is not known (expected a distance or AUTO)", args[i + 1].word));
      c.retract_mm.reset();
      i += 2;
      continue;
    }
    if (i + 1 >= args.size() || !args[i + 1].is_number)
      fail(a.column, fmt::format("CYCLE word {} expects a number", a.word));
    set_param(e->param, args[i + 1].number, u, p, c);
    i += 2;
  }
  return p;
}

/// The depth below the GOTO point, the R plane above it, the retract plane, dwell and feed.
void set_levels(const CycleParams& p, const AptCycleContext& ctx, int column, const Fail& fail, Cycle& c) {
  if (p.fedto && p.depth) fail(column, "CYCLE gives both FEDTO and DEPTH");
  if (p.fedto)
    c.depth_mm = ctx.signed_fedto ? -*p.fedto : std::abs(*p.fedto);
  else if (p.depth)
    c.depth_mm = *p.depth;
  else
    fail(column, "CYCLE without a depth (FEDTO or DEPTH)");
  if (p.rapto && p.clear) fail(column, "CYCLE gives both RAPTO and CLEAR");
  c.rapid_to_mm = p.rapto ? *p.rapto : p.clear ? *p.clear : 0.0;
  if (!(c.rapid_to_mm + c.depth_mm > 0.0))
    fail(column, fmt::format("CYCLE: the bottom ({:.4f} mm below the hole point) is not below the R plane "
                             "({:.4f} mm above it)",
                             c.depth_mm, c.rapid_to_mm));
  if (c.retract_mm && *c.retract_mm < c.rapid_to_mm)
    fail(column, fmt::format("CYCLE: the retract plane RTRCTO ({:.4f} mm) is below the R plane ({:.4f} mm)",
                             *c.retract_mm, c.rapid_to_mm));
  if (c.dwell_s < 0.0) fail(column, "CYCLE: negative DWELL");
  c.feed = p.feed;
  if (p.feed && !(*p.feed > 0.0)) fail(column, "CYCLE: the feed must be positive");
}

/// The peck depths of a pecking cycle (none on the others).
void set_pecks(const CycleParams& p, const std::string& words, int column, const Fail& fail, Cycle& c) {
  const bool pecking = c.kind == Cycle::Kind::deep || c.kind == Cycle::Kind::chip_break;
  if (p.step && p.sub_peck) fail(column, "CYCLE gives both a peck (STEP/INCR) and SUBPECK");
  c.peck_mm = p.step ? *p.step : p.sub_peck ? *p.sub_peck : p.first_peck ? *p.first_peck : 0.0;
  c.first_peck_mm = p.first_peck ? *p.first_peck : c.peck_mm;
  if (pecking && !(c.peck_mm > 0.0 && c.first_peck_mm > 0.0))
    fail(column,
         fmt::format("CYCLE/{}: a peck cycle without a positive peck depth (STEP, INCR, 1STPECK, SUBPECK)", words));
  if (!pecking && (p.step || p.sub_peck || p.first_peck))
    fail(column, fmt::format("CYCLE/{}: a peck depth on a cycle that does not peck", words));
}

/// The thread pitch of a tapping cycle (none on the others).
void set_thread(const CycleParams& p, const std::string& words, int column, const Fail& fail, Cycle& c) {
  if (p.tpi && p.pitch) fail(column, "CYCLE gives both TPI and PITCH");
  if (p.tpi) {
    if (!(*p.tpi > 0.0)) fail(column, "CYCLE: TPI must be positive");
    c.pitch_mm = kMmPerInch / *p.tpi;
  } else if (p.pitch) {
    c.pitch_mm = *p.pitch;
  }
  if (c.kind == Cycle::Kind::tap) {
    if (c.pitch_mm <= 0.0 && !(p.feed && c.feed_per_rev))
      fail(column, "CYCLE/TAP without the thread pitch (TPI, PITCH, or a feed per revolution MMPR/IPR)");
    if (c.pitch_mm <= 0.0)
      c.pitch_mm = *p.feed;  // the feed per revolution is the pitch
    else if (p.feed && c.feed_per_rev && std::abs(*p.feed - c.pitch_mm) > kPitchFeedRelTol * c.pitch_mm)
      fail(column,
           fmt::format("CYCLE/TAP: the feed per revolution {:.4f} mm is not the pitch {:.4f} mm", *p.feed, c.pitch_mm));
  } else if (c.pitch_mm > 0.0) {
    fail(column, fmt::format("CYCLE/{}: a thread pitch on a cycle that does not tap", words));
  }
}

}  // namespace

std::optional<Cycle> read_apt_cycle(const AptStatement& st, const AptCycleContext& ctx) {
  const std::string text = "CYCLE/" + st.raw_arguments;
  const Fail fail{st, ctx, text};
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
  Cycle c;
  c.where = st.where;
  c.text = st.raw_arguments;
  if (words == "OFF") {
    c.kind = Cycle::Kind::off;
    return c;
  }
  c.kind_word = words;
  bool known = false;
  for (const KindEntry& k : kKinds)
    if (words == k.words) c.kind = k.kind, known = true;
  if (!known)
    fail(args[0].column, fmt::format("cycle kind '{}' is not known (known: {}); its holes would be cut wrong, so "
                                     "the post stops: post the operation as explicit moves or as one of these kinds",
                                     words.empty() ? args[0].word : words, known_kinds()));
  const CycleParams p = read_params(args, i, ctx.mm_per_unit, fail, c);
  set_levels(p, ctx, st.where.column, fail, c);
  set_pecks(p, words, st.where.column, fail, c);
  set_thread(p, words, st.where.column, fail, c);
  return c;
}

}  // namespace ncpost::cl
