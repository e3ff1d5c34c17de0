// SPDX-License-Identifier: Apache-2.0
// Meaning of APT statements: units, motions, feeds, tool, spindle, coolant, stops, dwells,
// circles, cycles, comments. Unknown statements become Unsupported records with a notice.
#include <fmt/format.h>
#include "ncpost/kinematics/units.hpp"

#include <cmath>
#include <deque>

#include "ncpost/postproc/read/line_source.hpp"
#include "ncpost/postproc/read/apt/apt_nurbs.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/read/apt/apt_cycle.hpp"
#include "read/char_scan.hpp"

#include <cctype>

namespace ncpost::cl {
namespace {

/// The largest DEGREE or ORDER read from a NURBS record (the curve check then wants 1 to 30).
constexpr double kMaxNurbsOrder = 1000.0;

constexpr double kMmPerMetre = 1000.0;  // SPINDL/v,SMM: v in m/min
constexpr double kMmPerFoot = 304.8;    // SPINDL/v,SFM: v in ft/min
constexpr double kSecondsPerMinute = 60.0;
constexpr double kMaxRpm = 1e6;  // a surface speed giving more is a slip (units, diameter)

/// The M functions by number (AUXFUN/n) that mean the same on every control.
enum class AuxFunction {
  stop = 0,
  optional_stop = 1,
  spindle_cw = 3,
  spindle_ccw = 4,
  spindle_off = 5,
  mist = 7,
  flood = 8,
  coolant_off = 9
};

bool has_word(const AptStatement& st, const char* w) {
  for (const auto& a : st.arguments)
    if (!a.is_number && a.word == w) return true;
  return false;
}

/// The numeric arguments into `v` (a buffer kept between statements: no allocation per GOTO).
const std::vector<double>& numbers_into(const AptStatement& st, std::vector<double>& v) {
  v.clear();
  for (const auto& a : st.arguments)
    if (a.is_number) v.push_back(a.number);
  return v;
}

std::vector<double> numbers_of(const AptStatement& st) {
  std::vector<double> v;
  return numbers_into(st, v);
}

/// The number following the word `w` in the arguments, if any.
std::optional<double> number_after(const AptStatement& st, const char* w) {
  for (std::size_t i = 0; i + 1 < st.arguments.size(); ++i)
    if (!st.arguments[i].is_number && st.arguments[i].word == w && st.arguments[i + 1].is_number)
      return st.arguments[i + 1].number;
  return std::nullopt;
}

bool is_binary_junk(std::string_view line) {
  for (unsigned char c : line)
    if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n') || c == 0x7f) return true;
  return false;
}

/// Largest coordinate accepted (mm): a CL point 10 km away is damaged input, not a part.
constexpr double kMaxCoordinateMm = 1e7;

}  // namespace

/// The position of the comma before "CNTRL/" in "KNOT/k,CNTRL/x,y,z", else npos.
std::size_t knot_with_control_point(const std::string& statement) {
  const std::size_t b = statement.find_first_not_of(" \t");
  if (b == std::string::npos || statement.size() < b + 4) return std::string::npos;
  for (std::size_t k = 0; k < 4; ++k)  // (every statement comes here: a GOTO leaves at its first letter)
    if (upper(statement[b + k]) != "KNOT"[k]) return std::string::npos;
  const std::string head = upper_of(std::string_view(statement).substr(b));
  const std::size_t c = head.find("CNTRL");
  if (c == std::string::npos) return std::string::npos;
  const std::size_t comma = head.find_last_of(',', c);
  if (comma == std::string::npos || head.find_first_not_of(" \t", comma + 1) != c) return std::string::npos;
  return b + comma;
}

struct AptReader::State {
  LineSource lines;
  std::string file;
  ReaderOptions options;
  double scale = 1.0;  // mm per file unit
  int line_number = 0;
  Vec3d axis = Vec3d::UnitZ();
  Vec3d position = Vec3d::Zero();
  bool multax = false;
  bool rapid_pending = false;
  // NX (recognised by its `TOOL PATH/` records) writes the CIRCLE axis so that the tool moves
  // clockwise about it (its own post writes G03 for axis 0,0,-1; all 181 arcs of the real NX files
  // are the short way round only so); APT and Creo move counter-clockwise about it.
  bool nx_circle_axis = false;
  std::deque<Record> pending;
  std::vector<std::string> notices;
  bool have_position = false;  ///< a motion has set `position`
  bool any_statement = false;
  bool last_was_end = false;                 ///< the last statement was FINI, END or END-OF-PATH
  std::optional<double> cutter_diameter_mm;  ///< of the last CUTTER/d,...
  Location cutter_where;
  double spindle_rpm = 0.0;      ///< the speed of the last SPINDL that gave one (0: none yet)
  bool spindle_turning = false;  ///< the last spindle statement turns it
  /// A 6-value CIRCLE (radius taken from the start point): the next motion must end on it.
  struct ArcCheck {
    Location where;
    Vec3d center_mm, axis;
    double radius_mm;
  };
  std::optional<ArcCheck> arc_check;
  /// NX MSYS: W = msys_origin + msys_R * (file coordinates) under Msys::apply.
  Vec3d msys_origin_mm = Vec3d::Zero();
  Eigen::Matrix3d msys_R = Eigen::Matrix3d::Identity();
  std::optional<Location> first_msys;
  std::optional<Location> rotating_msys;  ///< an MSYS that rotates, posted as written (ignore)
  /// The CYCLE/ statement in force (no CYCLE/OFF since): its GOTOs are holes.
  std::optional<Location> active_cycle;
  bool nx_short_nurbs_noted = false;
  bool units_stated = false;          ///< a UNITS/ statement was read (the lengths' unit is the file's word)
  std::optional<ClPoint> from_point;  ///< the FROM position (GOHOME alone returns there)
  /// NURBS/ ... KNOT/ ... CNTRL/ ...: the curve being collected.
  struct NurbsBlock {
    Location where;
    std::optional<int> degree;
    NurbsCurve curve;
  };
  std::optional<NurbsBlock> nurbs;

  State(std::istream& i, std::string f, ReaderOptions o)
      : lines(i, f, "APT CL statements, one per line"), file(std::move(f)), options(o) {
    if (o.default_inch) scale = kMmPerInch;
    if (!(options.curve_tolerance_mm > 0.0) || !std::isfinite(options.curve_tolerance_mm))
      throw InputError({file, 0, 0}, "the curve tolerance must be a positive number of mm");
  }

  /// A point / direction of the file (in mm) in W.
  Vec3d to_w(const Vec3d& p_mm) const {
    return options.msys == ReaderOptions::Msys::apply ? Vec3d(msys_origin_mm + msys_R * p_mm) : p_mm;
  }
  Vec3d dir_to_w(const Vec3d& v) const { return options.msys == ReaderOptions::Msys::apply ? Vec3d(msys_R * v) : v; }
  void check_coordinates(const AptStatement& st, const std::vector<double>& v, std::size_t count) const {
    for (std::size_t i = 0; i < count && i < v.size(); ++i)
      if (std::abs(v[i] * scale) > kMaxCoordinateMm)
        fail(st.where,
             fmt::format("{} coordinate {:.6g} mm is out of range (expected |x| <= {:g} mm)", st.major, v[i] * scale,
                         kMaxCoordinateMm),
             echo_of(st.major + "/" + st.raw_arguments));
  }

  [[noreturn]] void fail(Location w, const std::string& what, const std::string& text) const {
    throw InputError({file, w.line, w.column}, what, echo_for(text, w.column));
  }

  /// Next logical statement: continuation lines joined, CR stripped. False at end of file.
  std::string line;  ///< read buffers, kept between statements (no allocation per line)
  std::string text;
  std::string statement;

  bool read_logical(std::string& out, Location& where) {
    out.clear();
    bool continued = false;
    std::string_view physical;
    while (lines.next(physical)) {
      line_number = lines.line_number();
      if (is_binary_junk(physical)) fail({line_number, 1}, "binary or control characters (expected APT CL text)", "");
      line.assign(physical);
      if (!continued) {
        const auto b = line.find_first_not_of(" \t");
        if (b == std::string::npos) continue;  // blank line
        where = {line_number, static_cast<int>(b) + 1};
        line.erase(0, b);
      }
      const auto comment = line.find("$$");
      const std::size_t last_dollar = line.find_last_of('$');
      const bool continues =
          !line.empty() && line.back() == '$' && (comment == std::string::npos || last_dollar > comment + 1);
      if (continues) {
        out.append(line, 0, line.size() - 1);
        continued = true;
        continue;
      }
      out += line;
      return true;
    }
    if (continued) return true;  // a file ending in '$': take what we have
    return false;
  }

  std::vector<double> numbers;  ///< the numbers of the current motion statement

  /// The end of the input: an empty file, or one whose last statement is not FINI / END /
  /// END-OF-PATH (a cut copy would post a gouge) is refused.
  void end_of_file() const {
    if (!any_statement) fail({0, 0}, "the CL file is empty (no statements); expected APT CL data ending with FINI", "");
    if (!last_was_end && !options.allow_unterminated)
      fail(
          {line_number, 0},
          "file ends without FINI: truncated? (the last statement is not FINI, END or END-OF-PATH); check the copy, or "
          "give --allow-unterminated to post it as it is",
          "");
  }

  Motion motion(const AptStatement& st, bool relative) {
    const std::vector<double>& v = numbers_into(st, numbers);
    if (v.size() != st.arguments.size())
      fail(st.where, fmt::format("{} expects numbers only", st.major), st.major + "/" + st.raw_arguments);
    Motion m;
    m.where = st.where;
    if (relative) {
      check_coordinates(st, v, 3);
      if (v.size() == 3)
        position += dir_to_w(scale * Vec3d(v[0], v[1], v[2]));
      else if (v.size() == 1)
        position += scale * v[0] * axis;
      else
        fail(st.where, fmt::format("GODLTA expects 1 or 3 numbers, got {}", v.size()), "GODLTA/" + st.raw_arguments);
    } else {
      if (v.size() != 3 && v.size() != 6)
        fail(st.where, fmt::format("{} expects 3 or 6 numbers (x,y,z[,i,j,k]), got {}", st.major, v.size()),
             st.major + "/" + st.raw_arguments);
      check_coordinates(st, v, 3);
      position = to_w(scale * Vec3d(v[0], v[1], v[2]));
      if (v.size() == 6) {
        const Vec3d a(v[3], v[4], v[5]);
        if (a.norm() < 1e-9)
          fail(st.where, "tool axis (i, j, k) is zero (expected a unit vector)", st.major + "/" + st.raw_arguments);
        if (std::abs(a.norm() - 1.0) > 1e-3)
          notices.push_back(fmt::format("{}:{}: tool axis of length {:.6f} normalised", file, st.where.line, a.norm()));
        axis = dir_to_w(a.normalized());
        m.axis_given = true;
      }
    }
    m.point.tip_mm = position;
    m.point.axis = axis;
    m.rapid = rapid_pending;
    rapid_pending = false;
    have_position = true;
    if (arc_check) check_arc_end(*arc_check, st);
    arc_check.reset();
    return m;
  }

  /// GOHOME/x,y,z[,i,j,k] (NX: the move to the operation's home point) or GOHOME alone (back to the
  /// FROM point): a rapid move there, as the CAM systems' own posts write it. It was a comment
  /// before, and the move was lost.
  Motion go_home(const AptStatement& st) {
    refuse_inside_cycle(st, "GOHOME/" + st.raw_arguments, "a GOHOME");
    if (!st.arguments.empty()) {
      rapid_pending = true;
      return motion(st, false);
    }
    if (!from_point)
      fail(st.where,
           "GOHOME without a point and no FROM before it: the home position is not known; give it "
           "(GOHOME/x,y,z) or a FROM/x,y,z at the start",
           "GOHOME");
    Motion m;
    m.where = st.where;
    m.point = *from_point;
    m.rapid = true;
    position = m.point.tip_mm;
    axis = m.point.axis;
    rapid_pending = false;
    have_position = true;
    arc_check.reset();
    return m;
  }

  /// NX's helical engage `CIRCLE/...,TIMES,n` (the centre at the level of the next GOTO, which lies
  /// deeper or higher along the axis than the start): n turns in all, the last one the arc to the
  /// GOTO — (n - 1) whole turns, then the arc, at one pitch, clockwise about (i,j,k) as every NX
  /// circle. Confirmed on the geometry of nx_APT_Project2's two records (TIMES,7, 0.3845 in deep,
  /// radius 0.1687 in, the arc to the GOTO 331.2 deg): 6.92 turns give a ramp of 3.0008 deg, NX's
  /// round ramp angle, in both; 7 turns and the arc would give 2.93 deg. Outside NX files (no
  /// `TOOL PATH/`) the count's convention is not known: refused.
  int helix_extra_turns(const AptStatement& st, const std::string& text) const {
    if (!has_word(st, "TIMES")) return 0;
    const auto n = number_after(st, "TIMES");
    if (!n || !(*n >= 1.0 && *n <= 10000.0) || *n != std::round(*n))
      fail(st.where, "CIRCLE ...,TIMES,n: n is the number of turns of the helix, a whole number from 1", echo_of(text));
    if (!nx_circle_axis)
      fail(st.where,
           fmt::format("CIRCLE ...,TIMES,{:g}: a helix of several turns outside an NX file (no TOOL PATH/ record): "
                       "whether the turns include the arc to the next GOTO is NX's convention, not known for this "
                       "file's CAM system; output the helix as GOTO points",
                       *n),
           echo_of(text));
    return static_cast<int>(*n) - 1;
  }

  /// The distance of `p` from the axis of a circle (its radius if `p` is on the circle).
  static double radius_at(const Vec3d& p, const Vec3d& center, const Vec3d& n) {
    const Vec3d r = p - center;
    return (r - r.dot(n) * n).norm();
  }

  /// The end of a 6-value CIRCLE (whose radius came from its start) must lie on the same circle.
  void check_arc_end(const ArcCheck& c, const AptStatement& end) const {
    const double r_end = radius_at(position, c.center_mm, c.axis);
    const double tol = options.curve_tolerance_mm;
    if (std::abs(r_end - c.radius_mm) > tol)
      fail(
          c.where,
          fmt::format("CIRCLE: the arc starts {:.4f} mm from its axis but ends {:.4f} mm from it at line {} (more than "
                      "the tolerance {:g} mm): the start point, centre or end point is wrong",
                      c.radius_mm, r_end, end.where.line, tol),
          "");
  }

  /// NX writes no UNITS record: an inch part says so only by its feeds (FEDRAT/IPM; its own posts
  /// write G20). Read as mm, the default, every length would be 25.4 times too small. A feed in
  /// inches in a file whose lengths are mm only by default is refused until --units says.
  void refuse_inch_feed_in_mm_default(const AptStatement& st) const {
    if (units_stated || options.default_inch || options.units_given) return;
    fail(st.where,
         fmt::format("FEDRAT/{} gives the feed in inches, and the file has no UNITS statement: its lengths are likely "
                     "inches too (NX writes no UNITS record and says inches by IPM) and would be read as mm; give "
                     "--units inch, or --units mm if the coordinates are mm",
                     st.raw_arguments),
         "FEDRAT/" + st.raw_arguments);
  }

  Feed feed(const AptStatement& st) {
    Feed f;
    f.where = st.where;
    const auto v = numbers_of(st);
    if (v.empty()) fail(st.where, "FEDRAT expects a feed value", "FEDRAT/" + st.raw_arguments);
    f.value = v[0];
    double unit = scale;
    if (has_word(st, "IPM") || has_word(st, "IPR")) refuse_inch_feed_in_mm_default(st);
    if (has_word(st, "IPM")) unit = kMmPerInch;
    if (has_word(st, "MMPM")) unit = 1.0;
    if (has_word(st, "IPR")) {
      unit = kMmPerInch;
      f.per_rev = true;
    }
    if (has_word(st, "MMPR")) {
      unit = 1.0;
      f.per_rev = true;
    }
    f.value *= unit;
    if (!(f.value > 0.0)) fail(st.where, "FEDRAT: the feed must be positive", "FEDRAT/" + st.raw_arguments);
    if (f.value > kMaxCoordinateMm)
      fail(st.where,
           fmt::format("FEDRAT: the feed {:.6g} is out of range (expected at most {:g} mm/min)", f.value,
                       kMaxCoordinateMm),
           "FEDRAT/" + st.raw_arguments);
    return f;
  }

  /// CIRCLE/xc,yc,zc,i,j,k,r[,...] (APT, NX, Creo) or CIRCLE/xc,yc,zc,i,j,k (SOLIDWORKS CAM: the
  /// radius is the start point's distance from the axis, and the end point must agree).
  Circle circle(const AptStatement& st, const std::string& text) {
    const auto v = numbers_of(st);
    if (v.size() != 6 && v.size() < 7)
      fail(st.where,
           fmt::format("CIRCLE expects 6 numbers (xc,yc,zc,i,j,k) or 7 and more (xc,yc,zc,i,j,k,r,...), got {}",
                       v.size()),
           echo_of(text));
    check_coordinates(st, v, 3);
    Circle c;
    c.extra_turns = helix_extra_turns(st, text);
    c.where = st.where;
    c.center_mm = to_w(scale * Vec3d(v[0], v[1], v[2]));
    const Vec3d a(v[3], v[4], v[5]);
    if (a.norm() < 1e-9) fail(st.where, "CIRCLE axis is zero", echo_of(text));
    c.axis = dir_to_w(nx_circle_axis ? Vec3d(-a.normalized()) : Vec3d(a.normalized()));
    if (v.size() >= 7) {
      c.radius_mm = scale * v[6];
      if (!(std::abs(c.radius_mm) <= kMaxCoordinateMm))
        fail(st.where, fmt::format("CIRCLE radius {:.6g} mm is out of range", c.radius_mm), echo_of(text));
      return c;
    }
    if (!have_position)
      fail(st.where, "CIRCLE without a radius before any motion: the radius is taken from the start point",
           echo_of(text));
    c.radius_mm = radius_at(position, c.center_mm, c.axis);
    if (c.radius_mm < 1e-6)
      fail(st.where, "CIRCLE: the start point lies on the circle's axis (radius 0)", echo_of(text));
    arc_check = ArcCheck{st.where, c.center_mm, c.axis, c.radius_mm};
    return c;
  }

  /// MSYS/x,y,z, xi,xj,xk, yi,yj,yk: the MCS in the absolute frame.
  void msys(const AptStatement& st, const std::string& text) {
    const auto v = numbers_of(st);
    if (v.size() != 9)
      fail(st.where, fmt::format("MSYS expects 9 numbers (origin, X axis, Y axis), got {}", v.size()), echo_of(text));
    check_coordinates(st, v, 3);
    const Vec3d x(v[3], v[4], v[5]), y(v[6], v[7], v[8]);
    if (std::abs(x.norm() - 1.0) > 1e-4 || std::abs(y.norm() - 1.0) > 1e-4 || std::abs(x.dot(y)) > 1e-4)
      fail(st.where, "MSYS: the X and Y axes must be orthogonal unit vectors", echo_of(text));
    Eigen::Matrix3d r;
    r.col(0) = x.normalized();
    r.col(2) = x.cross(y).normalized();
    r.col(1) = r.col(2).cross(r.col(0));
    const Vec3d origin = scale * Vec3d(v[0], v[1], v[2]);
    const bool same = (r - msys_R).cwiseAbs().maxCoeff() < 1e-6 && (origin - msys_origin_mm).norm() < 1e-6;
    const bool rotates = (r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6;
    if (options.msys == ReaderOptions::Msys::ignore) {
      if (first_msys && !same)
        fail(st.where,
             fmt::format(
                 "MSYS differs from the one at line {}: the operations' GOTOs are written in different MCSs, which "
                 "--msys ignore would post in one frame; use --msys apply to post them all in the absolute frame",
                 first_msys->line),
             echo_of(text));
      if (rotates && !rotating_msys) {
        rotating_msys = st.where;
        notices.push_back(
            fmt::format("{}:{}: MSYS rotates the MCS (its Z axis is {:.6f}, {:.6f}, {:.6f} in the absolute "
                        "frame); the GOTOs are posted as written, in the MCS (--msys ignore)",
                        file, st.where.line, r(0, 2), r(1, 2), r(2, 2)));
      }
    }
    if (!first_msys) first_msys = st.where;
    msys_R = r;
    msys_origin_mm = origin;
  }

  /// NURBS/[degree] starts a curve; KNOT/k... and CNTRL/x,y,z[,w] or x,y,z,i,j,k[,w] fill it.
  void nurbs_record(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    if (w == "NURBS") {
      nurbs = NurbsBlock{st.where, std::nullopt, {}};
      const auto v = numbers_of(st);
      // a whole number of a sensible size before it becomes an int (1.7e17 must not overflow the cast)
      const auto whole = [&](double x, const char* word) {
        if (!(x >= 0.0 && x <= kMaxNurbsOrder && x == std::floor(x)))
          fail(st.where, fmt::format("NURBS: {} must be a whole number from 0 to {}", word, kMaxNurbsOrder),
               echo_of(text));
        return static_cast<int>(x);
      };
      if (auto d = number_after(st, "DEGREE"))
        nurbs->degree = whole(*d, "DEGREE");
      else if (auto o = number_after(st, "ORDER"))
        nurbs->degree = whole(*o, "ORDER") - 1;
      else if (!v.empty())
        fail(st.where, "NURBS: a number without DEGREE or ORDER before it", echo_of(text));
      return;
    }
    if (!nurbs) fail(st.where, fmt::format("{} outside a NURBS/ curve", w), echo_of(text));
    const auto v = numbers_of(st);
    if (v.size() != st.arguments.size()) fail(st.where, fmt::format("{} expects numbers only", w), echo_of(text));
    if (w == "KNOT") {
      if (v.empty()) fail(st.where, "KNOT expects one or more knot values", echo_of(text));
      nurbs->curve.knots.insert(nurbs->curve.knots.end(), v.begin(), v.end());
      return;
    }
    // CNTRL
    if (v.size() != 3 && v.size() != 4 && v.size() != 6 && v.size() != 7)
      fail(st.where, fmt::format("CNTRL expects x,y,z[,w] or x,y,z,i,j,k[,w], got {} numbers", v.size()),
           echo_of(text));
    check_coordinates(st, v, 3);
    NurbsCurve& c = nurbs->curve;
    if (!c.points_mm.empty() && (c.axes.empty() != (v.size() < 6)))
      fail(st.where, "CNTRL: a tool axis on some control points but not on others", echo_of(text));
    c.points_mm.push_back(to_w(scale * Vec3d(v[0], v[1], v[2])));
    c.weights.push_back(v.size() == 4 ? v[3] : v.size() == 7 ? v[6] : 1.0);
    if (v.size() >= 6) {
      const Vec3d a(v[3], v[4], v[5]);
      if (a.norm() < 1e-9) fail(st.where, "CNTRL: tool axis is zero", echo_of(text));
      c.axes.push_back(dir_to_w(a.normalized()));
    }
  }

  /// NX CLSF's short NURBS form: `GOTO/start`, `NURBS/`, `KNOT/` with the knots after 0 (the interior
  /// ones and the end, each end once), `CNTRL/` with the control points after the first, which is
  /// the tool position (HumMan/CLSFProcessor samples/nurbs.clsf: 70 curves, every one tangent to the
  /// lines before and after it read so, and starting up to 22 mm off read any other way). Completes
  /// the curve to the full clamped form; returns its degree (control points − interior knots).
  int nx_short_form(NurbsBlock& b) {
    NurbsCurve& c = b.curve;
    for (const double w : c.weights)
      if (w != 1.0)
        fail(b.where,
             "NURBS: weighted control points in NX's short form (no start knots, the curve from the tool "
             "position): the weight of the start point is not written; expected weights of 1",
             "");
    const int interior = static_cast<int>(c.knots.size()) - 1;
    const int degree = static_cast<int>(c.points_mm.size()) - interior;
    if (degree < 1) return degree;  // the curve check names the defect
    const double u_end = c.knots.back();
    std::vector<double> knots(static_cast<std::size_t>(degree) + 1, 0.0);
    knots.insert(knots.end(), c.knots.begin(), c.knots.end() - 1);
    knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, u_end);
    c.knots = std::move(knots);
    c.points_mm.insert(c.points_mm.begin(), position);
    c.weights.insert(c.weights.begin(), 1.0);
    if (!c.axes.empty()) c.axes.insert(c.axes.begin(), axis);
    if (!nx_short_nurbs_noted) {
      notices.push_back(
          fmt::format("{}:{}: NURBS in NX's short form (the knots after 0, the curve starting at the tool "
                      "position): read as a clamped curve of degree {}",
                      file, b.where.line, degree));
      nx_short_nurbs_noted = true;
    }
    return degree;
  }

  /// The GOTO after a curve, when it stands at the curve's end `end`: the curve's last motion, whose
  /// axis (if given) ends the curve.
  struct CurveEnd {
    bool consumed = false;
    Location where;
    std::optional<Vec3d> axis;
  };
  CurveEnd curve_end(const AptStatement* next, const Vec3d& end, Location curve_where, double tol) {
    CurveEnd e;
    e.where = curve_where;
    if (!next || next->major != "GOTO") return e;
    const std::vector<double>& v = numbers_into(*next, numbers);
    if ((v.size() == 3 || v.size() == 6) && v.size() == next->arguments.size() &&
        (to_w(scale * Vec3d(v[0], v[1], v[2])) - end).norm() <= tol) {
      e.consumed = true;
      e.where = next->where;
      if (v.size() == 6 && Vec3d(v[3], v[4], v[5]).norm() > 1e-9)
        e.axis = dir_to_w(Vec3d(v[3], v[4], v[5]).normalized());
    }
    return e;
  }

  /// Ends the NURBS curve being collected: its chords become motions. `next` is the statement
  /// after the curve: a GOTO at the curve's end is the curve's last motion (its axis ends it).
  /// Returns true if `next` was consumed so.
  bool finish_nurbs(const AptStatement* next) {
    NurbsBlock b = std::move(*nurbs);
    nurbs.reset();
    NurbsCurve& c = b.curve;
    if (c.weights.size() < c.points_mm.size()) c.weights.resize(c.points_mm.size(), 1.0);
    if (!b.degree) b.degree = static_cast<int>(c.knots.size()) - static_cast<int>(c.points_mm.size()) - 1;
    if (*b.degree < 1 && !c.knots.empty() && have_position) b.degree = nx_short_form(b);
    c.degree = *b.degree;
    if (const std::string d = c.defect(); !d.empty()) fail(b.where, "NURBS: " + d, "");
    if (!have_position) fail(b.where, "NURBS before any motion: the curve must start where the tool is", "");
    const Vec3d start = c.point_at(c.u_begin());
    const double tol = std::max(options.curve_tolerance_mm, 1e-3);
    if ((start - position).norm() > tol)
      fail(
          b.where,
          fmt::format("NURBS starts {:.4f} mm away from the tool position ({:.4f}, {:.4f}, {:.4f}); expected the curve "
                      "to start where the previous motion ended",
                      (start - position).norm(), position.x(), position.y(), position.z()),
          "");
    const CurveEnd ending = curve_end(next, c.point_at(c.u_end()), b.where, tol);
    const std::optional<Vec3d>& end_axis = ending.axis;
    const bool consumed = ending.consumed;
    const Location end_where = ending.where;
    const Vec3d axis0 = axis;
    const Vec3d axis1 = end_axis.value_or(axis0);
    const std::vector<double> us = linearize(c, options.curve_tolerance_mm);
    if (us.empty())
      fail(b.where,
           fmt::format("NURBS: more than a million chords would be needed within {:g} mm (extreme weights or "
                       "a damaged curve?)",
                       options.curve_tolerance_mm),
           "");
    const double u0 = c.u_begin(), u1 = c.u_end();
    const bool rapid = rapid_pending;
    rapid_pending = false;
    for (std::size_t i = 1; i < us.size(); ++i) {
      const bool last = i + 1 == us.size();
      Motion m;
      m.where = last ? end_where : b.where;
      m.point.tip_mm = last && consumed ? to_w(scale * Vec3d(numbers[0], numbers[1], numbers[2])) : c.point_at(us[i]);
      if (auto a = c.axis_at(us[i])) {
        m.point.axis = *a;
        m.axis_given = true;
      } else {
        const double t = (us[i] - u0) / (u1 - u0);
        const Vec3d blend = (1.0 - t) * axis0 + t * axis1;  // the file gives the ends only
        m.point.axis = blend.norm() > 1e-9 ? Vec3d(blend.normalized()) : axis1;
        m.axis_given = end_axis.has_value();
      }
      m.rapid = rapid;
      position = m.point.tip_mm;
      axis = m.point.axis;
      pending.push_back(m);
    }
    return consumed;
  }

  /// Applies a statement: queues the records it produces (none for modal settings).
  void apply(const AptStatement& st, const std::string& text) {
    any_statement = true;
    if (nurbs && st.major != "KNOT" && st.major != "CNTRL") {
      if (finish_nurbs(&st)) {
        last_was_end = false;
        return;
      }
    }
    const bool is_end = st.major == "END-OF-PATH" || st.major == "END" || st.major == "FINI";
    // lines of an NX listing around the data ("Tool Path Listing has 81 lines.") are no statements
    if (is_end || st.has_slash || st.major == "RAPID") last_was_end = is_end;
    apply_statement(st, text);
  }

  void apply_statement(const AptStatement& st, const std::string& text) {
    if (apply_motion_word(st) || apply_modal_setting(st, text) || apply_machine_function(st, text) ||
        apply_program_function(st, text) || apply_geometry_record(st, text) || apply_text_record(st, text))
      return;
    notices.push_back(fmt::format("{}:{}:{}: '{}' is not acted on; passed through as a comment", file, st.where.line,
                                  st.where.column, st.major));
    pending.push_back(Unsupported{st.where, text});
  }

  /// GOTO, FROM, GOHOME, GODLTA, RAPID.
  bool apply_motion_word(const AptStatement& st) {
    const std::string& w = st.major;
    if (w == "GOTO" || w == "FROM") {
      Motion m = motion(st, false);
      m.from = (w == "FROM");
      if (m.from) from_point = m.point;
      pending.push_back(m);
    } else if (w == "GOHOME") {
      pending.push_back(go_home(st));
    } else if (w == "GODLTA") {
      pending.push_back(motion(st, true));
    } else if (w == "RAPID") {
      rapid_pending = true;
    } else {
      return false;
    }
    return true;
  }

  /// FEDRAT, UNITS, MULTAX, TLAXIS: settings for the motions that follow.
  bool apply_modal_setting(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    const Location at = st.where;
    if (w == "FEDRAT") {
      pending.push_back(feed(st));
    } else if (w == "UNITS" || w == "UNIT") {
      units_stated = true;
      if (has_word(st, "MM"))
        scale = 1.0;
      else if (has_word(st, "INCHES") || has_word(st, "INCH") || has_word(st, "IN"))
        scale = kMmPerInch;
      else
        fail(at, "UNITS expects MM or INCHES", text);
    } else if (w == "MULTAX") {
      multax = !has_word(st, "OFF");
    } else if (w == "TLAXIS") {
      const auto v = numbers_of(st);
      if (v.size() >= 3 && Vec3d(v[0], v[1], v[2]).norm() > 1e-9)
        axis = dir_to_w(Vec3d(v[0], v[1], v[2]).normalized());
      else
        fail(at, "TLAXIS expects i, j, k of a non-zero vector", text);
    } else {
      return false;
    }
    return true;
  }

  /// SPINDL, COOLNT, LOADTL / LOAD/TOOL, CUTCOM.
  bool apply_machine_function(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    if (w == "SPINDL")
      pending.push_back(spindle(st, text));
    else if (w == "COOLNT")
      pending.push_back(coolant(st));
    else if (w == "LOADTL" || (w == "LOAD" && has_word(st, "TOOL"))) {
      refuse_inside_cycle(st, text, "a tool change");
      pending.push_back(tool_change(st, text));
    } else if (w == "CUTCOM")
      pending.push_back(cutter_comp(st, text));
    else
      return false;
    return true;
  }

  /// SPINDL/[RPM,]n,CLW|CCLW, SPINDL/OFF, or a surface speed SPINDL/v,SMM|SFM,... (turned into rpm
  /// with the CUTTER diameter).
  Spindle spindle(const AptStatement& st, const std::string& text) {
    Spindle s;
    s.where = st.where;
    if (has_word(st, "OFF"))
      s.direction = Spindle::Direction::off;
    else if (has_word(st, "CCLW"))
      s.direction = Spindle::Direction::ccw;
    const auto v = numbers_of(st);
    const bool smm = has_word(st, "SMM"), sfm = has_word(st, "SFM");
    if (!v.empty()) s.rpm = smm || sfm ? surface_speed_rpm(st, text, v[0], smm ? kMmPerMetre : kMmPerFoot) : v[0];
    spindle_turning = s.direction != Spindle::Direction::off;
    if (s.rpm > 0.0) spindle_rpm = s.rpm;
    return s;
  }

  /// The whole rpm of the surface speed `v` (m/min or ft/min: `mm_per_unit`) at the CUTTER
  /// diameter: n = v * mm_per_unit / (pi * d_mm).
  double surface_speed_rpm(const AptStatement& st, const std::string& text, double v, double mm_per_unit) {
    const char* unit = mm_per_unit == kMmPerMetre ? "SMM" : "SFM";
    if (!cutter_diameter_mm)
      fail(st.where,
           fmt::format("SPINDL/{:g},{}: surface speed needs the tool diameter (CUTTER/...): give CUTTER/d "
                       "before it, or the speed in rpm (SPINDL/RPM,n)",
                       v, unit),
           echo_of(text));
    if (!(v > 0.0))
      fail(st.where, fmt::format("SPINDL: the surface speed must be positive, got {:g} {}", v, unit), echo_of(text));
    const double rpm = std::round(v * mm_per_unit / (kPi * *cutter_diameter_mm));
    if (!(rpm >= 1.0 && rpm <= kMaxRpm))
      fail(st.where,
           fmt::format("SPINDL: {:g} {} on the {:g} mm cutter (CUTTER at line {}) is {:.6g} rpm (expected 1 to "
                       "{:g}): check the speed and the CUTTER diameter",
                       v, unit, *cutter_diameter_mm, cutter_where.line, rpm, kMaxRpm),
           echo_of(text));
    notices.push_back(
        fmt::format("{}:{}:{}: SPINDL: {:g} {} on the {:g} mm cutter (CUTTER at line {}) is posted as {:.0f} rpm", file,
                    st.where.line, st.where.column, v, unit, *cutter_diameter_mm, cutter_where.line, rpm));
    return rpm;
  }

  /// CUTTER/d[,r,...]: the diameter, for a surface speed; kept as a comment.
  void cutter(const AptStatement& st) {
    const auto v = numbers_of(st);
    if (!v.empty() && v[0] > 0.0 && v[0] * scale <= kMaxCoordinateMm) {
      cutter_diameter_mm = v[0] * scale;
      cutter_where = st.where;
    }
  }

  static Coolant coolant(const AptStatement& st) {
    Coolant c;
    c.where = st.where;
    c.on = !has_word(st, "OFF");
    c.mode = st.arguments.empty() || st.arguments[0].is_number ? "ON" : st.arguments[0].word;
    return c;
  }

  ToolChange tool_change(const AptStatement& st, const std::string& text) const {
    ToolChange t;
    t.where = st.where;
    const auto v = numbers_of(st);
    if (v.empty()) fail(st.where, "LOADTL expects a tool number", text);
    if (!(v[0] >= 0.0 && v[0] <= 1e6)) fail(st.where, "LOADTL: tool number out of range (expected 0 to 1000000)", text);
    t.number = static_cast<int>(v[0]);
    if (auto l = number_after(st, "LENGTH")) t.length_mm = *l * scale;
    return t;
  }

  CutterComp cutter_comp(const AptStatement& st, const std::string& text) const {
    CutterComp c;
    c.where = st.where;
    c.text = st.raw_arguments;
    if (has_word(st, "LEFT"))
      c.side = CutterComp::Side::left;
    else if (has_word(st, "RIGHT"))
      c.side = CutterComp::Side::right;
    else if (!has_word(st, "OFF"))
      fail(st.where, "CUTCOM expects LEFT, RIGHT or OFF", text);
    const auto v = numbers_of(st);
    if (!v.empty() && v[0] >= 0.0 && v[0] <= 1e6) c.offset_register = static_cast<int>(v[0]);
    return c;
  }

  /// STOP, OPSTOP, DELAY, AUXFUN, PREFUN.
  bool apply_program_function(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    if (w == "STOP" || w == "OPSTOP")
      pending.push_back(Stop{st.where, w == "OPSTOP", operator_message(st)});
    else if (w == "DELAY")
      pending.push_back(delay(st, text));
    else if (w == "AUXFUN")
      pending.push_back(aux_function(st, text));
    else if (w == "PREFUN")
      fail(st.where,
           fmt::format("PREFUN/{} (a G function by number) is not posted: its meaning depends on the control; "
                       "write the APT statement it stands for, or remove it where the machine needs none",
                       st.raw_arguments),
           echo_of(text));
    else
      return false;
    return true;
  }

  /// INSERT/ text is literal NC output; INSERT/STOP [text] and INSERT/OPSTOP [text] (SOLIDWORKS CAM's
  /// "INSERT/STOP  change fixture") ask for a program stop: posted as one, the rest of the text as
  /// the operator's message, not as a comment the machine runs past.
  static std::optional<Stop> inserted_stop(const AptStatement& st) {
    const std::string& t = st.raw_arguments;
    const std::size_t b = t.find_first_not_of(" \t");
    if (b == std::string::npos) return std::nullopt;
    std::size_t e = t.find_first_of(" \t,(", b);
    if (e == std::string::npos) e = t.size();
    std::string first = t.substr(b, e - b);
    for (char& c : first) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (first != "STOP" && first != "OPSTOP") return std::nullopt;
    std::string rest = t.substr(e);
    const std::size_t rb = rest.find_first_not_of(" \t,");
    rest = rb == std::string::npos ? std::string() : rest.substr(rb);
    if (rest.size() >= 2 && rest.front() == '(' && rest.back() == ')') rest = rest.substr(1, rest.size() - 2);
    const std::size_t re = rest.find_last_not_of(" \t");
    rest = re == std::string::npos ? std::string() : rest.substr(0, re + 1);
    return Stop{st.where, first == "OPSTOP", rest};
  }

  /// The text of STOP/(text) or STOP/text, without the parentheses ("" for STOP alone).
  static std::string operator_message(const AptStatement& st) {
    std::string t = st.raw_arguments;
    if (t.size() >= 2 && t.front() == '(' && t.back() == ')') t = t.substr(1, t.size() - 2);
    const auto b = t.find_first_not_of(" \t"), e = t.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : t.substr(b, e - b + 1);
  }

  /// DELAY/t (seconds) or DELAY/REV,n (spindle revolutions at the speed in force).
  Dwell delay(const AptStatement& st, const std::string& text) {
    const auto v = numbers_of(st);
    const bool revolutions = has_word(st, "REV");
    if (v.size() != 1 || st.arguments.size() != (revolutions ? 2u : 1u))
      fail(st.where, "DELAY expects a time in seconds (DELAY/t) or in spindle revolutions (DELAY/REV,n)",
           echo_of(text));
    double seconds = v[0];
    if (revolutions) {
      if (!spindle_turning || !(spindle_rpm > 0.0))
        fail(st.where,
             "DELAY/REV: a dwell in spindle revolutions needs the spindle turning at a known speed (SPINDL/n "
             "before it); give the dwell in seconds (DELAY/t)",
             echo_of(text));
      seconds = v[0] * kSecondsPerMinute / spindle_rpm;
    }
    if (!(seconds >= 0.0 && seconds <= kMaxDwellSeconds))
      fail(st.where, fmt::format("DELAY: expected a dwell from 0 to {:g} s, got {:g} s", kMaxDwellSeconds, seconds),
           echo_of(text));
    if (revolutions)
      notices.push_back(
          fmt::format("{}:{}:{}: DELAY/REV,{:g}: {:g} revolutions at {:g} rpm are posted as a dwell of {:.3f} s", file,
                      st.where.line, st.where.column, v[0], v[0], spindle_rpm, seconds));
    return Dwell{st.where, seconds};
  }

  /// AUXFUN/n: the M functions with one meaning on every control (AuxFunction) as records; any
  /// other is refused (its meaning is the machine's own).
  Record aux_function(const AptStatement& st, const std::string& text) {
    const auto v = numbers_of(st);
    if (v.size() != 1 || st.arguments.size() != 1 || v[0] != std::floor(v[0]) || !(v[0] >= 0.0 && v[0] <= 9999.0))
      fail(st.where, "AUXFUN expects one M function number (AUXFUN/n)", echo_of(text));
    const int n = static_cast<int>(v[0]);
    switch (static_cast<AuxFunction>(n)) {
      case AuxFunction::stop:
        return Stop{st.where, false, {}};
      case AuxFunction::optional_stop:
        return Stop{st.where, true, {}};
      case AuxFunction::spindle_cw:
      case AuxFunction::spindle_ccw:
        return aux_spindle(st, text, n);
      case AuxFunction::spindle_off:
        spindle_turning = false;
        return Spindle{st.where, Spindle::Direction::off, 0.0};
      case AuxFunction::mist:
        return Coolant{st.where, true, "MIST"};
      case AuxFunction::flood:
        return Coolant{st.where, true, "FLOOD"};
      case AuxFunction::coolant_off:
        return Coolant{st.where, false, "OFF"};
    }
    fail(st.where,
         fmt::format("AUXFUN/{} (M{}) is not posted: its meaning depends on the machine (ncpost writes AUXFUN/0, "
                     "1, 3, 4, 5, 7, 8, 9); write the APT statement it stands for (COOLNT/..., SPINDL/..., "
                     "LOADTL/...), or remove it where the machine needs none",
                     n, n),
         echo_of(text));
  }

  /// AUXFUN/3 or /4: the spindle on at the speed of the last SPINDL.
  Spindle aux_spindle(const AptStatement& st, const std::string& text, int n) {
    if (!(spindle_rpm > 0.0))
      fail(st.where,
           fmt::format("AUXFUN/{} (M{}, spindle on) before any spindle speed: give SPINDL/n,{} instead", n, n,
                       n == 3 ? "CLW" : "CCLW"),
           echo_of(text));
    spindle_turning = true;
    return Spindle{st.where, n == 3 ? Spindle::Direction::cw : Spindle::Direction::ccw, spindle_rpm};
  }

  /// A tool change or an arc while a CYCLE/ is in force: the GOTOs after it would be drilled as
  /// holes with the cycle of the operation before (SOLIDWORKS CAM files without CYCLE/OFF, whose
  /// end milling went out as G81 holes). Whether the cycle goes on is not written: refused.
  void refuse_inside_cycle(const AptStatement& st, const std::string& text, const char* what) const {
    if (!active_cycle) return;
    fail(st.where,
         fmt::format("{} while the CYCLE of line {} is in force (no CYCLE/OFF since): the GOTOs after it would be "
                     "drilled as holes of that cycle; end the cycle with CYCLE/OFF where its holes end (and repeat the "
                     "CYCLE/ statement after the tool change if the new tool drills too)",
                     what, active_cycle->line),
         echo_of(text));
  }

  /// CIRCLE, CYCLE, NURBS (KNOT, CNTRL), MSYS and the ends (END-OF-PATH, END, FINI).
  bool apply_geometry_record(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    if (w == "CIRCLE") {
      refuse_inside_cycle(st, text, "a CIRCLE (arc motion)");
      pending.push_back(circle(st, text));
    } else if (w == "CYCLE") {
      if (auto c = read_apt_cycle(st, {file, scale, nx_circle_axis})) {
        if (c->kind == Cycle::Kind::off)
          active_cycle.reset();
        else
          active_cycle = st.where;
        pending.push_back(std::move(*c));
      }
    } else if (w == "END-OF-PATH" || w == "END" || w == "FINI") {
      pending.push_back(End{st.where, w == "FINI"});
    } else if (w == "NURBS" || w == "KNOT" || w == "CNTRL") {
      nurbs_record(st, text);
    } else if (w == "MSYS") {
      msys(st, text);
      pending.push_back(Comment{st.where, w + "/" + st.raw_arguments});
    } else {
      return false;
    }
    return true;
  }

  /// PPRINT, INSERT, TPRINT, PARTNO, NX's TOOL PATH and OPERATION NAME, and the information for
  /// the post that does not change the motion (CSYS, TLDATA, CUTTER, ...): kept as comments.
  bool apply_text_record(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    auto comment = [&](std::string t) { pending.push_back(Comment{st.where, std::move(t)}); };
    if (w == "INSERT") {
      if (auto stop = inserted_stop(st))
        pending.push_back(std::move(*stop));
      else
        comment(st.raw_arguments.empty() ? w : st.raw_arguments);
    } else if (w == "PPRINT" || w == "TPRINT" || w == "TOOL PATH" || w == "OPERATION NAME") {
      if (w == "TOOL PATH") nx_circle_axis = true;
      comment(st.raw_arguments.empty() ? w : (w == "PPRINT" ? st.raw_arguments : w + ": " + st.raw_arguments));
    } else if (w.rfind("PARTNO", 0) == 0) {
      // PARTNO/text, or PARTNO text (which may hold a '/' of its own)
      std::string rest = w == "PARTNO" ? st.raw_arguments : text.substr(std::min(text.size(), std::size_t(6)));
      rest.erase(0, std::min(rest.size(), rest.find_first_not_of(" \t/")));
      comment("PARTNO " + rest);
    } else if (w == "CSYS" || w == "TLDATA" || w == "CUTTER" || w == "TOOLNO" || w == "PAINT" || w == "MACHIN" ||
               w == "CLRSRF" || w == "SELCTL") {
      if (w == "CUTTER") cutter(st);
      if (w != "PAINT") comment(w + (st.has_slash ? "/" + st.raw_arguments : ""));
    } else {
      return false;
    }
    return true;
  }
};

AptReader::AptReader(std::istream& in, std::string file_name, ReaderOptions options)
    : state_(std::make_unique<State>(in, std::move(file_name), options)) {}

AptReader::~AptReader() = default;

std::optional<Record> AptReader::next() {
  State& s = *state_;
  std::string& text = s.text;
  Location where;
  while (s.pending.empty()) {
    if (!s.read_logical(text, where)) {
      if (s.nurbs) {
        s.finish_nurbs(nullptr);
        s.last_was_end = false;
        continue;
      }
      s.end_of_file();
      return std::nullopt;
    }
    s.any_statement = true;
    if (text.rfind("$$", 0) == 0) {
      std::string c = text.substr(2);
      const auto b = c.find_first_not_of(" \t");
      s.pending.push_back(Comment{where, b == std::string::npos ? std::string() : c.substr(b)});
      continue;
    }
    // an inline `$$` comment after a statement
    std::string& statement = s.statement;
    statement.assign(text, 0, text.find("$$"));
    if (statement.find_first_not_of(" \t") == std::string::npos) continue;
    // NX may write a knot and a control point in one record: KNOT/k,CNTRL/x,y,z
    if (const std::size_t cntrl = knot_with_control_point(statement); cntrl != std::string::npos) {
      const std::string second = statement.substr(cntrl + 1);
      statement.resize(cntrl);
      s.apply(parse_apt_statement(statement, s.file, where), statement);
      s.apply(parse_apt_statement(second, s.file, {where.line, where.column + static_cast<int>(cntrl) + 1}), second);
      continue;
    }
    s.apply(parse_apt_statement(statement, s.file, where), statement);
  }
  Record r = std::move(s.pending.front());
  s.pending.pop_front();
  return r;
}

std::string AptReader::failure_hint() const {
  const State& s = *state_;
  if (!s.rotating_msys) return {};
  return fmt::format(
      "{}:{}: the file's MSYS rotates the MCS and the GOTOs were posted as written (--msys ignore): MSYS is "
      "the likely cause; try --msys apply",
      s.file, s.rotating_msys->line);
}

std::vector<std::string> AptReader::take_notices() {
  std::vector<std::string> out;
  out.swap(state_->notices);
  return out;
}

bool looks_like_apt(const std::string& head) {
  // An APT statement starts a line with its major word (then '/', or alone as RAPID / MULTAX);
  // the words may also appear inside G-code comments, e.g. "(ncpost 0.1.0 from part.cls)".
  static const char* const kMajor[] = {"GOTO",   "FROM",   "TOOL PATH", "PARTNO", "MULTAX", "LOADTL",
                                       "$$",     "FEDRAT", "UNITS",     "UNIT",   "CIRCLE", "SPINDL",
                                       "COOLNT", "RAPID",  "TLAXIS",    "CUTTER", "MSYS",   "PPRINT"};
  std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a UTF-8 byte order mark
  while (start < head.size()) {
    std::size_t end = head.find_first_of("\n\r", start);  // LF, CRLF or CR-only line ends
    if (end == std::string::npos) end = head.size();
    std::size_t b = head.find_first_not_of(" \t", start);
    if (b < end) {
      std::string line;
      for (std::size_t i = b; i < end; ++i)
        line += static_cast<char>(std::toupper(static_cast<unsigned char>(head[i])));
      while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.pop_back();
      if (line.rfind("$$", 0) == 0) return true;
      for (const char* key : kMajor) {
        const std::size_t n = std::char_traits<char>::length(key);
        if (line.compare(0, n, key) != 0) continue;
        // the major word then '/' (blanks allowed between), or the word alone on its line (RAPID)
        const std::size_t after = line.find_first_not_of(" \t", n);
        if (after == std::string::npos ? line.size() == n : line[after] == '/') return true;
      }
    }
    start = end + 1;
  }
  return false;
}

}  // namespace ncpost::cl
