// SPDX-License-Identifier: Apache-2.0
// G-code -> CL records: line source, block grammar, modal interpreter, then the nominal
// kinematics of the machine (see gcode_cl_reader.hpp).
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/postproc/solve/inverse_time.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "ncpost/postproc/read/gcode/gcode_macro.hpp"
#include "ncpost/postproc/read/line_source.hpp"
#include "ncpost/postproc/read/gcode/gcode_modal.hpp"

#include "read/gcode/gcode_framing.hpp"
#include "read/gcode/gcode_oword.hpp"
#include "read/gcode/gcode_oword_flow.hpp"
#include "read/gcode/gcode_program_flow.hpp"
#include "read/gcode/gcode_subprogram_calls.hpp"
#include "read/machine_points.hpp"
#include "read/units_evidence.hpp"

namespace ncpost::gcode {
namespace {

constexpr const char* kWhatALineIs = "a line of G-code";

std::string axis_letters_of(const Machine& m) {
  std::string s = "XYZ";
  for (int k = 0; k < m.rotary_count(); ++k) s += m.rotary(k).letter;
  return s;
}

/// The words the program may use: a serial machine's X Y Z and rotary letters, or every axis of a
/// word machine (GcodeReaderOptions::word_forward).
std::string program_letters(const Machine& m, const GcodeReaderOptions& o) {
  if (!o.word_forward) return axis_letters_of(m);
  std::string s;
  for (const Axis& a : m.axes) s += a.letter;
  return s;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::optional<InputKind> parse_input_kind(std::string_view text) {
  if (text == "auto") return InputKind::automatic;
  if (text == "machine") return InputKind::machine;
  if (text == "rtcp") return InputKind::rtcp;
  return std::nullopt;
}

std::string GcodeReaderOptions::validate() const {
  if (!(arc_chord_tolerance_mm >= 1e-6 && arc_chord_tolerance_mm <= 10.0))
    return fmt::format("the arc chord tolerance must be within 1e-6 .. 10 mm (is {})", arc_chord_tolerance_mm);
  return {};
}

struct GcodeClReader::State {
  LineSource source;
  std::string file;
  Machine machine;
  Setup setup;
  GcodeReaderOptions options;
  std::string letters;  ///< the axis words of the program (program_letters)
  Interpreter interpreter;
  Block block;
  BlockEffect effect;
  std::array<int, 2> rotary_axis{};  ///< ProgramPoint index of machine rotary k

  std::vector<cl::Record> before;  ///< records of the current block before its motion
  std::size_t before_next = 0;
  std::vector<cl::Record> after;  ///< records after its motion
  std::size_t after_next = 0;

  // the arc being expanded
  std::optional<ArcMove> arc;
  long arc_segments_total = 0;
  long arc_segment = 0;
  cl::Location arc_where;

  bool opened_percent = false;
  bool seen_content = false;
  bool done = false;
  bool last_rtcp = false;
  std::vector<std::string> notices;

  State(std::istream& in, std::string f, const Machine& m, const Setup& s, GcodeReaderOptions o)
      : source(in, f, kWhatALineIs),
        file(f),
        machine(m),
        setup(s),
        options(o),
        letters(program_letters(m, o)),
        interpreter(f, letters, o.default_inch, o.integer_dwell, o.arc_centre) {
    for (int k = 0; k < rotaries() && k < 2; ++k) {
      const std::string slot_letters = "XYZABC";
      rotary_axis[static_cast<std::size_t>(k)] = static_cast<int>(slot_letters.find(machine.rotary(k).letter));
    }
    interpreter.set_work_offsets(options.work_offsets, options.control);
    interpreter.set_tool_offset_writes(options.tool_offset_writes);
    interpreter.set_word_rules(options.tool_words, options.integer_words);
    std::vector<std::string> dirs;
    if (!options.subprogram_dir.empty()) dirs.push_back(options.subprogram_dir);
    const std::string own = std::filesystem::path(file).parent_path().string();
    dirs.push_back(own.empty() ? std::string(".") : own);
    calls.set_directories(std::move(dirs));
    if (!options.power_on.empty()) interpreter.power_on(options.power_on, options.power_on_source, options.units_given);
    interpreter.on_rtcp_switch([this](const ProgramPoint& p, bool rtcp_on) { return reframed(p, rtcp_on); });
  }

  /// The machine's position `p` in the words of the other reading when the program switches RTCP
  /// (Interpreter::on_rtcp_switch): the axes do not move, so machine X Y Z become the tip in W
  /// (switching on) or the tip becomes machine X Y Z (off), through the nominal kinematics and the
  /// job's set-up. Before every axis is programmed, or with the reading forced, `p` stays.
  ProgramPoint reframed(ProgramPoint p, bool rtcp_on) const {
    if (options.kind != InputKind::automatic || options.word_forward) return p;
    const ModalState& st = interpreter.state();
    for (std::size_t i = 0; i < 6; ++i)
      if (letters.find("XYZABC"[i]) != std::string::npos && !st.known[i]) return p;
    AxisPosition q = AxisPosition::zero(rotaries());
    for (int k = 0; k < rotaries(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])];
    const Vec3d xyz(p[0], p[1], p[2]);
    Vec3d now;
    if (rtcp_on) {
      q.linear_mm = xyz;
      now = nominal_table_T_tool(q).t - setup.workpiece_origin_mm;
    } else {
      now = linear_for(machine, q.rotary_rad, xyz, setup);
    }
    for (std::size_t i = 0; i < 3; ++i) p[i] = now[static_cast<int>(i)];
    return p;
  }

  /// The nominal chain's set-up at home (T(0), the identity for a nominal machine), cached.
  ChainPose<double> home = raw_chain_pose<double>(machine, AxisPosition{}, setup.tool_length_mm, NominalErrors{}, true);
  Rigidd home_table_inverse = home.bed_T_table.inverse();
  Rigidd home_tool_inverse = home.bed_T_tool.inverse();

  /// kinematics::forward (tool_pose with NominalErrors) with the home part computed once: the
  /// tool body in the table frame at command q.
  Rigidd nominal_table_T_tool(const AxisPosition& q) const {
    const ChainPose<double> at_q = raw_chain_pose<double>(machine, q, setup.tool_length_mm, NominalErrors{}, false);
    const ChainPose<double> actual{at_q.bed_T_table * home_table_inverse, at_q.bed_T_tool * home_tool_inverse};
    return actual.table_T_tool();
  }

  bool rtcp_now() {
    switch (options.kind) {
      case InputKind::machine:
        return false;
      case InputKind::rtcp:
        return true;
      case InputKind::automatic:
        break;
    }
    return interpreter.state().rtcp != Rtcp::off;
  }

  cl::Motion motion_at(const ProgramPoint& p, cl::Location where) {
    cl::Motion m;
    m.where = where;
    m.axis_given = true;
    m.rapid = effect.motion == MotionMode::rapid;
    m.inverse_time = effect.inverse_time;
    m.feed = effect.motion_feed;
    last_rtcp = rtcp_now();
    locate(m, p, last_rtcp);
    return m;
  }

  /// The tip, tool axis and angles of the program point `p` (RTCP or machine reading), checked
  /// against the machine's limits.
  void locate(cl::Motion& m, const ProgramPoint& p, bool rtcp) const {
    if (options.word_forward) {
      locate_words(m, p, rtcp);
      return;
    }
    AxisPosition q = AxisPosition::zero(rotaries());
    q.linear_mm = Vec3d(p[0], p[1], p[2]);
    for (int k = 0; k < rotaries(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])];
    if (rotaries() > 0) m.rotary_rad = q.rotary_rad;
    const Rigidd table_T_tool = nominal_table_T_tool(q);
    m.point.axis = table_T_tool.R.col(2);
    m.point.tip_mm = rtcp ? q.linear_mm : Vec3d(table_T_tool.t - setup.workpiece_origin_mm);
    if (options.check_limits)
      check_limits(rtcp ? AxisPosition{linear_for(machine, q.rotary_rad, q.linear_mm, setup), q.rotary_rad} : q, rtcp,
                   m.where);
  }

  /// Rotary axes of a serial machine (none for a word machine).
  int rotaries() const { return options.word_forward ? 0 : machine.rotary_count(); }

  /// locate() on a word machine: the words through its forward kinematics, checked against its limits.
  void locate_words(cl::Motion& m, const ProgramPoint& p, bool rtcp) const {
    if (rtcp)
      throw InputError({file, m.where.line, m.where.column},
                       fmt::format("an RTCP (tool-tip) program on the machine {}, whose words {} are no Cartesian "
                                   "frame: not supported (post a program of machine words)",
                                   machine.name, program_letters(machine, options)));
    AxisPosition q = AxisPosition::zero(static_cast<int>(machine.axes.size()) - 3);
    for (std::size_t i = 0; i < machine.axes.size() && i < p.size(); ++i) q[static_cast<int>(i)] = p[i];
    if (options.check_limits) check_limits(q, false, m.where);
    std::string why;
    const std::optional<ToolPoseT<double>> pose = options.word_forward(q, &why);
    if (!pose)
      throw Infeasible(fmt::format("{}:{}:{}: the machine {} has no pose at these words: {}", file, m.where.line,
                                   m.where.column, machine.name, why));
    m.point.tip_mm = pose->tip_mm;
    m.point.axis = pose->axis;
  }

  // ---- a program without G20/G21 (or G70/G71/G700/G710) that looks like inches: X Y Z words
  // mostly written with 4 decimals (inch posts) where 3 would do for mm, and every position within
  // a 50-unit box (2 inches is 50.8 mm: an inch program read as mm shrinks 25.4 times). A notice.
  long words_4_decimals = 0, words_other_decimals = 0;
  // A metric design posted in inches: X Y Z words of 3 or 4 decimals (not whole hundredths) that
  // are whole half-millimetres divided by 25.4 (Y3.937 = 100 mm, Z.9843 = 25 mm), the rounding of
  // a 4-decimal inch word (0.00005 in = 0.00127 mm) allowed. A millimetre word does that by chance
  // about once in 170; most of the fine words of a program doing it is an inch program.
  static constexpr double kMmPerInch = 25.4;
  static constexpr double kRoundMetricMm = 0.5;
  static constexpr double kMetricInInchToleranceMm = 0.0015;
  static constexpr long kMetricInInchMinWords = 5;
  static constexpr double kMetricInInchShare = 0.6;
  long words_fine = 0, words_metric_in_inch = 0;
  struct {
    char letter = '?';
    double value = 0.0;
    int line = 0;
  } first_metric_in_inch;
  static bool is_whole(double v, double tolerance = 1e-9) { return std::abs(v - std::round(v)) <= tolerance; }
  Vec3d programmed_lo = Vec3d::Constant(1e300), programmed_hi = Vec3d::Constant(-1e300);
  bool units_hint_given = false;
  bool block_delete_noticed = false;

  void observe_units(std::string_view line) {
    for (const Word& w : block.words) {
      if (w.letter != 'X' && w.letter != 'Y' && w.letter != 'Z') continue;
      std::size_t at = static_cast<std::size_t>(w.column);  // just after the letter
      while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '+' || line[at] == '-')) ++at;
      while (at < line.size() && line[at] >= '0' && line[at] <= '9') ++at;
      int decimals = 0;
      if (at < line.size() && line[at] == '.')
        while (++at < line.size() && line[at] >= '0' && line[at] <= '9') ++decimals;
      (decimals == 4 ? words_4_decimals : words_other_decimals) += 1;
      if (decimals >= 3 && !is_whole(w.value * 100.0)) {
        ++words_fine;
        if (is_whole(w.value * kMmPerInch / kRoundMetricMm, kMetricInInchToleranceMm / kRoundMetricMm)) {
          if (words_metric_in_inch++ == 0) first_metric_in_inch = {w.letter, w.value, source.line_number()};
        }
      }
    }
    if (effect.has_motion) {
      const ModalState& st = interpreter.state();
      for (int i = 0; i < 3; ++i)
        if (st.known[static_cast<std::size_t>(i)]) {
          programmed_lo[i] = std::min(programmed_lo[i], effect.end[static_cast<std::size_t>(i)]);
          programmed_hi[i] = std::max(programmed_hi[i], effect.end[static_cast<std::size_t>(i)]);
        }
    }
  }

  // A program without units words is read in the units --units gives (mm by default); where its
  // comments or its numbers speak inches it is refused rather than cut 25.4 times too small.
  void units_hint() {
    if (units_hint_given || options.units_given || options.default_inch || interpreter.state().units_programmed) return;
    units_hint_given = true;
    if (units_evidence.speaks_inches())
      throw InputError({file, units_evidence.first_inch_line(), 0},
                       fmt::format("the program has no G20/G21 (units) and its comments speak inches ('{}' at line {}, "
                                   "no millimetres named): the control's default units decide such a program; post "
                                   "with --units inch or --units mm (or add G20/G21)",
                                   units_evidence.first_inch_word(), units_evidence.first_inch_line()));
    if (words_metric_in_inch >= kMetricInInchMinWords &&
        static_cast<double>(words_metric_in_inch) >= kMetricInInchShare * static_cast<double>(words_fine))
      throw InputError(
          {file, first_metric_in_inch.line, 0},
          fmt::format("the program has no G20/G21 (units) and its positions look like a metric design "
                      "written in inches ({} of its {} X/Y/Z words with 3 or 4 decimals are whole "
                      "half-millimetres divided by 25.4, e.g. {}{} at line {} = {:.3f} mm): the control's "
                      "default units decide such a program; post with --units inch or --units mm (or add "
                      "G20/G21)",
                      words_metric_in_inch, words_fine, first_metric_in_inch.letter, first_metric_in_inch.value,
                      first_metric_in_inch.line, first_metric_in_inch.value * kMmPerInch));
    if (words_4_decimals < 5 || words_4_decimals <= 2 * words_other_decimals) return;
    for (int i = 0; i < 3; ++i)
      if (programmed_lo[i] <= programmed_hi[i] && (programmed_lo[i] < -50.0 || programmed_hi[i] > 50.0)) return;
    const Vec3d span = (programmed_hi - programmed_lo).cwiseMax(0.0);
    throw InputError(
        {file, 1, 0},
        fmt::format("the program has no G20/G21 (units) and looks like inches ({} of {} X/Y/Z words with "
                    "4 decimals, all positions within {:.4g} x {:.4g} x {:.4g}): the control's default "
                    "units decide such a program; post with --units inch or --units mm (or add G20/G21)",
                    words_4_decimals, words_4_decimals + words_other_decimals, span.x(), span.y(), span.z()));
  }
  UnitsEvidence units_evidence;

  // ---- arcs that the post can write as arcs (G2/G3 of its dialect): a single turn, planar
  // or helical (no P turns), the rotary axes still, not under G93: a cl::Circle (centre and axis in
  // W, counter-clockwise about the axis) before the end motion, as a CL file gives it. Others are
  // expanded into points (chord error <= arc_chord_tolerance_mm). The points between are still
  // checked against the axis limits.
  Vec3d tip_in_W(const ProgramPoint& p, bool rtcp) const {
    if (rtcp) return Vec3d(p[0], p[1], p[2]);
    AxisPosition q = AxisPosition::zero(rotaries());
    q.linear_mm = Vec3d(p[0], p[1], p[2]);
    for (int k = 0; k < rotaries(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])];
    return Vec3d(nominal_table_T_tool(q).t - setup.workpiece_origin_mm);
  }

  std::optional<cl::Circle> as_circle(const ArcMove& a, cl::Location where, long segments) {
    if (!options.circles || effect.inverse_time || std::abs(a.sweep_rad) > 2.0 * kPi + 1e-9) return std::nullopt;
    const auto normal = static_cast<std::size_t>(a.axes.normal);
    for (std::size_t i = 3; i < 6; ++i)
      if (a.end[i] != a.start[i]) return std::nullopt;
    if (std::abs(a.radius_start_mm - a.radius_end_mm) > 5e-4 || a.radius_start_mm < 1e-3) return std::nullopt;
    const bool rtcp = rtcp_now();
    if (options.check_limits)
      for (long i = 1; i < segments; ++i) {
        cl::Motion scratch;
        scratch.where = where;
        locate(scratch, unwrapped(a.at(static_cast<double>(i) / static_cast<double>(segments))), rtcp);
      }
    ProgramPoint centre = unwrapped(a.start);
    centre[static_cast<std::size_t>(a.axes.a1)] = a.centre1_mm;
    centre[static_cast<std::size_t>(a.axes.a2)] = a.centre2_mm;
    ProgramPoint above = centre;
    above[normal] += 1.0;
    cl::Circle c;
    c.where = where;
    c.center_mm = tip_in_W(centre, rtcp);
    const Vec3d up = tip_in_W(above, rtcp) - c.center_mm;
    c.axis = (a.sweep_rad > 0.0 ? 1.0 : -1.0) * up.normalized();
    c.radius_mm = a.radius_start_mm;
    return c;
  }

  // ---- G93 (inverse time): the source gives each block's time (1/F minutes). The post times a
  // block by the rule of inverse_time.hpp (the executed tip path in W over the feed; deg/min for a
  // pure reorientation), so each G93 motion is preceded by the cl::Feed that gives the source's
  // block the source's time under that rule: the same program re-posted keeps every block's time.
  std::optional<cl::Motion> pending_motion;  ///< an arc segment waiting behind its feed record
  std::optional<Vec3d> last_tip;
  RotaryAngles last_rotary;  ///< the programmed rotary angles (rad) of the last motion

  /// The machine commands (mm, rad) that put the tip on `tip_W` at the rotary angles `rotary_rad`
  /// on the nominal machine: the tip is affine in the linear axes at fixed rotary angles.
  AxisPosition commands_for(const Vec3d& tip_W, const RotaryAngles& rotary_rad) const {
    AxisPosition q = AxisPosition::zero(rotaries());
    for (int k = 0; k < rotaries(); ++k) q.rotary_rad[k] = rotary_rad[k];
    const Vec3d t0 = nominal_table_T_tool(q).t;
    Mat3d A;
    for (int i = 0; i < 3; ++i) {
      AxisPosition qi = q;
      qi.linear_mm[i] = 1.0;
      A.col(i) = nominal_table_T_tool(qi).t - t0;
    }
    q.linear_mm = A.partialPivLu().solve(tip_W + setup.workpiece_origin_mm - t0);
    return q;
  }

  /// The feed record of a G93 motion (nullopt otherwise); follows the last position in any case.
  std::optional<cl::Feed> source_time_feed(const cl::Motion& m) {
    std::optional<cl::Feed> out;
    const RotaryAngles rotary = m.rotary_rad ? *m.rotary_rad : RotaryAngles::Zero(rotaries());
    if (last_rotary.size() != rotary.size()) last_rotary = RotaryAngles::Zero(rotary.size());
    if (m.inverse_time && m.feed && *m.feed > 0.0 && last_tip) {
      const bool tip_moves = (m.point.tip_mm - *last_tip).norm() > kStillTipMm;
      double path_mm = (m.point.tip_mm - *last_tip).norm();  // RTCP input: the tip moves straight in W
      if (!last_rtcp && tip_moves) {                         // machine axes interpolated linearly
        const AxisPosition q0 = commands_for(*last_tip, last_rotary), q = commands_for(m.point.tip_mm, rotary);
        path_mm = tip_path_length_mm([&](double t) {
          return Vec3d(nominal_table_T_tool(nonlinear::lerp(q0, q, t)).t - setup.workpiece_origin_mm);
        });
      }
      const double travel_deg = max_abs_step(rotary, last_rotary) * 180.0 / kPi;
      const double feed = feed_for_minutes(path_mm, tip_moves, travel_deg, 1.0 / *m.feed);
      if (feed > 0.0) out = cl::Feed{m.where, feed, false};
    }
    last_tip = m.point.tip_mm;
    last_rotary = rotary;
    return out;
  }

  // ---- rollover: a continuous rotary axis whose values all lie within 0 .. 360 deg and that
  // jumps by more than 180 deg (C359.857 -> C7.501) was programmed for a control that turns the
  // short way across 0; the reader makes that turn explicit (C367.501), so the post, its G93 time
  // and --verify all turn the same way. A value outside 0 .. 360 marks a program that counts turns
  // (LinuxCNC's C-399.8): no unwrapping on that axis from then on.
  std::array<double, 2> wrap_offset_rad{};  ///< added to rotary axis k's programmed value
  std::array<bool, 2> counts_turns{};       ///< a value outside 0 .. 360 deg was seen
  std::array<std::optional<double>, 2> last_programmed_rad{};

  ProgramPoint unwrapped(ProgramPoint p) const {
    for (int k = 0; k < rotaries() && k < 2; ++k)
      p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])] +=
          wrap_offset_rad[static_cast<std::size_t>(k)];
    return p;
  }

  /// `may_unwrap`: false for arcs (their rotary words are followed, not unwrapped).
  void update_wrap(const BlockEffect& fx, int line, bool may_unwrap) {
    constexpr double kTurn = 2.0 * kPi;
    for (int k = 0; k < rotaries() && k < 2; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const double v = fx.end[static_cast<std::size_t>(rotary_axis[ku])];
      const auto previous = last_programmed_rad[ku];
      last_programmed_rad[ku] = v;
      if (!may_unwrap || !machine.rotary(k).continuous() || interpreter.state().incremental) continue;
      if (v < -1e-9 || v > kTurn + 1e-9) counts_turns[ku] = true;
      if (counts_turns[ku] || !previous || std::abs(v - *previous) <= kPi + 1e-12) continue;
      const double before = *previous + wrap_offset_rad[ku];
      double offset = wrap_offset_rad[ku];
      offset += kTurn * std::round((before - (v + offset)) / kTurn);  // |turn| <= 180 deg
      wrap_offset_rad[ku] = offset;
      if (!wrap_noticed[ku]) {
        wrap_noticed[ku] = true;
        notices.push_back(fmt::format(
            "{}:{}: {} {:.3f} -> {:.3f} deg read the short way ({:+.3f} deg across 0/360, as a rollover axis "
            "turns): written as {} {:.3f}",
            file, line, machine.rotary(k).letter, *previous * 180.0 / kPi, v * 180.0 / kPi,
            (v + offset - before) * 180.0 / kPi, machine.rotary(k).letter, (v + offset) * 180.0 / kPi));
      }
    }
  }
  std::array<bool, 2> wrap_noticed{};

  // ---- the start of the program: rapids before every axis is programmed are held back until
  // the axes they lack are programmed, then take those first values (the program starts where it
  // first says, never with a rapid to 0 the source did not make); a feed motion, an arc or the
  // end releases them with 0 for the axes still unknown (where a control starting at program zero
  // would be).
  static constexpr std::size_t kZSlot = 2;  ///< Z in a ProgramPoint (X Y Z A B C)
  struct HeldMotion {
    std::size_t index;  ///< into `held`
    ProgramPoint p;
    std::array<bool, 6> assumed;
    bool rtcp;
  };
  static constexpr std::size_t kMaxHeld = 4096;  ///< records; beyond, release (memory stays flat)
  std::vector<cl::Record> held;
  std::vector<HeldMotion> held_motions;
  bool start_settled = false;  ///< every axis known, or released: no more holding

  /// Moves the current block's records (`before`, `after`) into `held`, the motion not located yet.
  void hold_block(const BlockEffect& fx, cl::Location where) {
    for (auto& r : before) held.push_back(std::move(r));
    before.clear();
    cl::Motion m;
    m.where = where;
    m.axis_given = true;
    m.rapid = true;
    m.feed = fx.motion_feed;
    last_rtcp = rtcp_now();
    held_motions.push_back(HeldMotion{held.size(), unwrapped(fx.end), fx.assumed, last_rtcp});
    held.push_back(std::move(m));
    for (auto& r : after) held.push_back(std::move(r));
    after.clear();
  }

  /// Locates the held motions with the first programmed values of the axes they lacked (0 for
  /// those still unknown) and puts the held records before the current block's.
  /// `usable`: the axes whose first values may be taken (a feed motion that programs an axis for
  /// the first time starts from 0 in it, as the notice says; the held rapids end there too).
  /// `cutting_line`: the line of the feed motion or arc that releases them (0: the program end).
  void release_held(const std::array<bool, 6>& usable, int cutting_line = 0) {
    if (cutting_line > 0 || !held.empty()) refuse_unplaced_machine_moves(cutting_line);
    start_settled = true;
    if (held.empty()) return;
    for (HeldMotion& h : held_motions) {
      // Z first programmed by the cut that releases them: a rapid taken to Z0 would run to the work
      // offset's zero (the part's face) before the cut; where the tool stands is not known, so no
      // rapid is invented (a program that never programs Z, e.g. a plasma cutter's, stays at Z0)
      if (h.assumed[kZSlot] && !usable[kZSlot] && cutting_line > 0 && interpreter.state().known[kZSlot]) {
        const cl::Location at = std::get<cl::Motion>(held[h.index]).where;
        throw InputError({file, at.line, at.column},
                         fmt::format("this rapid does not say where Z goes, and Z is first programmed by the cutting "
                                     "motion at line {}: taken as Z0 it would run to the work offset's zero before "
                                     "the cut; program Z on the first rapid (a G0 Z.. above the part)",
                                     cutting_line));
      }
      for (std::size_t i = 0; i < 6; ++i)
        if (h.assumed[i]) h.p[i] = usable[i] ? first_value[i] : 0.0;
      locate(std::get<cl::Motion>(held[h.index]), h.p, h.rtcp);
      source_time_feed(std::get<cl::Motion>(held[h.index]));  // rapids: only the last position
    }
    before.insert(before.begin(), std::make_move_iterator(held.begin()), std::make_move_iterator(held.end()));
    held.clear();
    held_motions.clear();
  }

  /// Where a G28/G30/G53 left an axis at a position the program frame does not give: the line and the
  /// code of that move (line 0: the axis is placed), and whether it came before the program's start
  /// was settled. One rule, two moments (docs/choices.md, G-code input): before the start every axis
  /// the move named (but a rotary axis that lands where it is taken, lands_where_assumed) must be
  /// programmed absolutely before the start settles (refuse_unplaced_machine_moves, at the move's
  /// line; note_placed_axes clears it); after the start an axis sent to a reference point the machine
  /// file does not give must be programmed absolutely by the next motion (check_reference_axes, at
  /// the motion's line).
  struct Unplaced {
    int line = 0;
    std::string code;
    bool before_start = false;
  };
  std::array<Unplaced, 6> unplaced{};

  /// The axes of `unplaced` left before the start, as "X, Y".
  std::string unplaced_before_start() const {
    std::string axes;
    for (std::size_t i = 0; i < 6; ++i)
      if (unplaced[i].line && unplaced[i].before_start)
        axes += axes.empty() ? std::string(1, "XYZABC"[i]) : std::string(", ") + "XYZABC"[i];
    return axes;
  }

  /// The start settles with an axis where a G28/G30/G53 left it, at a position in the program frame
  /// nothing gives: taken from a first value or 0 it would be wrong, so the post stops there.
  void refuse_unplaced_machine_moves(int cutting_line) {
    const std::string axes = unplaced_before_start();
    if (axes.empty()) return;
    const auto first =
        std::find_if(unplaced.begin(), unplaced.end(), [](const Unplaced& u) { return u.line && u.before_start; });
    const int line = first->line;
    const std::string& code = first->code;
    const std::string then = cutting_line > 0 ? fmt::format("the cutting motion at line {}", cutting_line)
                                              : std::string("the rapids that follow");
    throw InputError({file, line, 0},
                     fmt::format("{} moves {} in machine coordinates before the program has given a position, and "
                                 "{} start{} there without programming {} again: where that is in the program frame "
                                 "is not known, so the posted program would start elsewhere; program {} absolutely "
                                 "after the {} (before the first cut), or post from the CL data",
                                 code, axes, then, cutting_line > 0 ? "s" : "", axes, axes, code));
  }

  /// A rotary axis not programmed yet is taken at 0 where the program first moves: right when the
  /// machine move puts it at angle 0 (its machine angle under G53, the machine file's reference
  /// under G28/G30), as the programs that turn the table home this way expect.
  bool lands_where_assumed(const MachineMove& mm, std::size_t i) const {
    if (i < 3 || known_before[i]) return false;
    const Axis& axis = machine.axes[static_cast<std::size_t>(machine.index_of("XYZABC"[i]))];
    if (mm.kind == MachineMove::Kind::machine) return mm.machine_value[i] == 0.0;
    const std::optional<double> ref = reference_point(axis, mm.code == "G30");
    return ref && *ref == 0.0;
  }

  /// After a block: an axis programmed absolutely (not by a G28/G30/G53) is placed again.
  void note_placed_axes(const BlockEffect& fx) {
    if (fx.machine_move || interpreter.state().incremental) return;
    for (std::size_t i = 0; i < 6; ++i)
      if (fx.programmed[i] && unplaced[i].before_start) unplaced[i] = {};
  }

  std::array<double, 6> first_value{};  ///< of each axis, once known (program units: mm, rad)
  std::array<bool, 6> known_before{};

  /// After a block: records the first values of the axes it programmed.
  void note_first_values() {
    const ModalState& st = interpreter.state();
    for (std::size_t i = 0; i < 6; ++i)
      if (st.known[i] && !known_before[i]) {
        first_value[i] = st.position[i];
        known_before[i] = true;
      }
  }

  /// Infeasible (exit 3) when the machine commands `q` of a motion lie beyond an axis limit: the
  /// re-posted program must fit the machine like one posted from CL data.
  void check_limits(const AxisPosition& q, bool rtcp, cl::Location where) const {
    // rotary axes first: in an RTCP program the linear commands follow from them
    const std::size_t n = machine.axes.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (k + 3) % n;
      const Axis& axis = machine.axes[i];
      const double v = q[static_cast<int>(i)];
      if (!axis.limits || axis.limits->contains(v, axis.is_rotary() ? 1e-9 : 1e-6)) continue;
      const bool rotary = axis.is_rotary();
      const double scale = rotary ? 180.0 / kPi : 1.0;
      const char* unit = rotary ? "deg" : "mm";
      const std::string subject = rtcp && !rotary ? fmt::format("the programmed tool tip needs machine {} {:.3f} {}",
                                                                axis.letter, v * scale, unit)
                                                  : fmt::format("{} {:.3f} {}", axis.letter, v * scale, unit);
      const std::string what_to_check = rotary ? "check the program's angles against the machine file"
                                        : rtcp ? "check --workpiece-origin and --tool-length, or the machine file"
                                               : "check --workpiece-origin, or the machine file";
      throw Infeasible(fmt::format(
          "{}:{}:{}: {}, beyond the {} axis limit {:.3f} {} (travel {:.3f} .. {:.3f} {}) of machine {}: the program "
          "does not fit the machine; {}",
          file, where.line, where.column, subject, axis.letter,
          (v > axis.limits->max ? axis.limits->max : axis.limits->min) * scale, unit, axis.limits->min * scale,
          axis.limits->max * scale, unit, machine.name, what_to_check));
    }
  }

  void check_rtcp_forced(int line) {
    if (options.kind == InputKind::machine && interpreter.state().rtcp != Rtcp::off)
      notice_once_for_rtcp(line, "the program switches RTCP on; read as a machine-axis program as asked");
  }
  bool rtcp_notice_given = false;
  void notice_once_for_rtcp(int line, const char* text) {
    if (rtcp_notice_given) return;
    rtcp_notice_given = true;
    notices.push_back(fmt::format("{}:{}: {}", file, line, text));
  }

  /// Lines before the opening '%' to skip (gcode_framing.hpp).
  int leader_lines = -1;  ///< -1: not looked for yet

  void find_leader() {
    const std::string_view head = source.peek(LineSource::kChunkBytes);
    Leader leader = gcode::find_leader(head, head.size() < LineSource::kChunkBytes, file, letters);
    leader_lines = leader.lines;
    if (!leader.notice.empty()) notices.push_back(std::move(leader.notice));
  }

  // ---- a program that moves nothing although its file has motion words is an input error (an
  // empty output with exit 0 would hide it), wherever those words stand: in the program, in
  // deleted blocks, before the opening '%' or after its end.
  long motions_returned = 0;
  int motion_words_line = 0;  ///< the first line read with motion words (0: none)

  void note_motion_words(int line_number) {
    if (!motion_words_line && has_motion_words(block, letters)) motion_words_line = line_number;
  }

  /// At the end of the records: InputError when nothing moved although some line has motion words.
  void check_something_moved() {
    if (motions_returned > 0) return;
    const int end_line = source.line_number();
    std::string_view line;
    while (!motion_words_line && source.next(line)) {
      try {
        parse_block(line, block, file, source.line_number());
        note_motion_words(source.line_number());
      } catch (const InputError&) {
        // text after the program's end is not read as G-code
      }
    }
    if (!motion_words_line) return;
    throw InputError(
        {file, motion_words_line, 0},
        fmt::format("this line has motion words, but the program read (ending at line {}) moves nothing: "
                    "{}",
                    end_line,
                    motion_words_line > end_line ? "the line stands after the program's end ('%' or M2/M30)"
                                                 : "the line is not part of the program (a deleted block "
                                                   "or a leader before the opening '%')"));
  }

  /// Reads and interprets the next block; false at the end of the program. An error inside a
  /// subprogram names the calls that led there.
  bool read_block() {
    try {
      return read_one_block();
    } catch (const InputError& e) {
      const std::string chain = calls.chain();
      if (chain.empty() || (e.detail().size() >= chain.size() &&
                            e.detail().compare(e.detail().size() - chain.size(), chain.size(), chain) == 0))
        throw;
      throw InputError(e.where(), e.detail() + chain, e.source_line());
    }
  }

  bool read_one_block() {
    if (leader_lines < 0) find_leader();
    std::string_view line;
    const std::uint64_t line_offset = source.next_line_offset();
    if (!source.next(line)) {
      if (calls.active())  // the rest of the caller would be lost
        throw InputError({source.file(), source.line_number(), 0},
                         fmt::format("{} ends at the end of its file without M99 (or endsub)", calls.innermost()));
      release_held(known_before);
      units_hint();
      finish_input();
      return false;
    }
    const int line_number = source.line_number();
    if (source.file() != file) {  // a subprogram's file, or back in the program's
      file = source.file();
      interpreter.set_file(file);
    }
    if (calls.in_main_file() && line_number <= leader_lines) return true;
    if (const std::optional<OWord> o = read_o_word(line)) {
      seen_content = true;
      oword_flow.follow(*o, line, line_offset, line_number);
      return true;
    }
    MacroFlow flow;
    const bool computed_line = may_hold_macro(line);
    if (computed_line) {
      if (options.block_delete && is_deleted(line)) return skip_deleted(line_number);
      current_position_parameters();
      flow = apply_macro_line(line, parameters, macro_line, file, line_number);
      line = macro_line;
    }
    parse_block(line, block, file, line_number);
    block.computed = computed_line;
    if (block.empty()) {
      program_flow.follow(flow, line_offset, line_number, leader_lines + 1);
      return true;
    }
    note_motion_words(line_number);
    if (block.percent) {
      if (!seen_content && !opened_percent) {
        opened_percent = true;
        return true;
      }
      if (calls.active())
        throw InputError({file, line_number, block.column},
                         fmt::format("{} ends at the '%' without M99 (or endsub)", calls.innermost()));
      release_held(known_before);
      units_hint();
      return false;  // the closing '%': the rest of the file is not part of the program
    }
    seen_content = true;
    if (block.deleted && options.block_delete) return skip_deleted(line_number);
    const bool goes_on = interpret_block(line, line_number);
    if (goes_on && effect.call)
      follow_call(*effect.call, line_number, std::string(line));
    else if (goes_on)
      program_flow.follow(flow, line_offset, line_number, leader_lines + 1);
    return goes_on;
  }

  // ---- subprograms: M98/M97/M99 (the block's effect) and o-word statements (their own lines)
  SubprogramCalls calls{source, file};
  OWordFlow oword_flow{source, file, parameters, calls};

  /// `text`: the calling line, for the caret of an error (the call re-reads the file).
  void follow_call(const SubprogramCall& c, int line_number, const std::string& text) {
    const SubprogramCalls::Position back{source.next_line_offset(), line_number + 1};
    try {
      if (c.m == 98)
        calls.call_program(c.p, c.times, back, line_number, c.column);
      else if (c.m == 97)
        calls.call_block(static_cast<int>(c.p), c.times, back, line_number, c.column);
      else
        calls.leave(true, parameters, line_number, c.column, static_cast<int>(c.p));
    } catch (const InputError& e) {
      if (!e.source_line().empty()) throw;
      throw InputError(e.where(), e.detail(), text);
    }
  }

  static bool is_deleted(std::string_view line) {
    const auto first = line.find_first_not_of(" \t");
    return first != std::string_view::npos && line[first] == '/';
  }

  bool skip_deleted(int line_number) {
    seen_content = true;
    if (!block_delete_noticed)
      notices.push_back(
          fmt::format("{}:{}: blocks that start with '/' (block delete) are left out, as the control "
                      "leaves them out with its block-skip switch on",
                      file, line_number));
    block_delete_noticed = true;
    return true;
  }

  // ---- macro statements: parameters, expressions, jumps and loops (gcode_macro.hpp)
  Parameters parameters;

  // LinuxCNC's #5420-#5425: the current position (X Y Z in program units, A B C in degrees) in the
  // active coordinate system with every offset (work offset, G52/G92) applied, where the blocks
  // before this line left it; an axis not programmed yet has none (refused where read). Other
  // controls number their position variables otherwise: none given.
  void current_position_parameters() {
    if (options.control != cl::ControlFamily::linuxcnc || interpreter.word_axes()) return;
    const ModalState& st = interpreter.state();
    const std::array<double, 6>& shift = interpreter.work_frames().shift();
    constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
    for (std::size_t i = 0; i < 6; ++i) {
      std::optional<double> v;
      if (st.known[i]) v = (st.position[i] - shift[i]) * (i < 3 ? 1.0 / (st.inch ? kMmPerInch : 1.0) : kDegPerRad);
      parameters.set_system(5420 + static_cast<int>(i), v);
    }
  }
  std::string macro_line;  ///< the line with its expressions evaluated
  ProgramFlow program_flow{source, file};

  /// The records of one parsed block, queued in `before`/`after` (or held while the program's
  /// start is not settled); false when the block ends the program.
  bool interpret_block(std::string_view line, int line_number) {
    for (const BlockComment& c : block.comments) {
      before.push_back(cl::Comment{cl::Location{line_number, c.column}, std::string(trim(c.text))});
      if (!options.units_given && !options.default_inch && !interpreter.state().units_programmed)
        units_evidence.scan_comment(c.text, line_number);  // (units_hint reads it only then)
    }
    interpreter.apply(block, line_number, line, effect);
    observe_units(line);
    const std::array<bool, 6> known_prior = known_before;
    note_first_values();
    check_rtcp_forced(line_number);
    for (auto& n : interpreter.take_notices()) notices.push_back(std::move(n));
    const BlockEffect& fx = effect;
    note_placed_axes(fx);
    queue_modal_records(fx, line_number);
    const cl::Location where{line_number, block.column};
    if (fx.has_motion && !fx.machine_move) check_reference_axes(fx, where, line);
    if (fx.machine_move) {
      queue_machine_move(fx, where, line, known_prior);
    } else if (fx.has_motion && fx.cycle) {
      queue_cycle_hole(fx, where, line);
    } else if (fx.has_motion && fx.arc) {
      queue_arc(fx, where, line, known_prior);
    } else if (fx.has_motion && !start_settled && fx.motion == MotionMode::rapid && held.size() < kMaxHeld) {
      return hold_rapid(fx, where);
    } else if (fx.has_motion) {
      queue_linear(fx, where, known_prior);
    }
    for (const auto& u : fx.after_motion) after.push_back(u);
    if (fx.program_end) return end_program(where);
    if (!held.empty()) {  // a block without motion between held rapids keeps its place
      for (auto& r : before) held.push_back(std::move(r));
      for (auto& r : after) held.push_back(std::move(r));
      before.clear();
      after.clear();
    }
    return true;
  }

  // ---- moves in the machine's own coordinates: G28/G30 (reference point), G53 ----------------
  /// A motion while an axis stands at a reference point of unknown position must program it.
  void check_reference_axes(const BlockEffect& fx, cl::Location where, std::string_view line) {
    for (std::size_t i = 0; i < 6; ++i) {
      if (!unplaced[i].line || unplaced[i].before_start) continue;
      const char L = "XYZABC"[i];
      if (!fx.programmed[i] || interpreter.state().incremental)
        throw InputError({file, where.line, where.column},
                         fmt::format("{} stands at its reference point since line {} (G28/G30/G53), a position the "
                                     "machine file does not give: this motion does not say where {} goes (program "
                                     "{} absolutely on the first motion after the return, or give the machine file "
                                     "[axes.{}] reference = ...)",
                                     L, unplaced[i].line, L, L, L),
                         std::string(line));
      unplaced[i] = {};
    }
  }

  /// The program point `p` with the machine's linear axes given by `machine_mm` (where set):
  /// machine reading takes them as they are; a tool-tip (RTCP) reading goes through the machine.
  ProgramPoint with_machine_linear(ProgramPoint p, const std::array<std::optional<double>, 3>& machine_mm) {
    if (!rtcp_now()) {
      for (std::size_t i = 0; i < 3; ++i)
        if (machine_mm[i]) p[i] = *machine_mm[i];
      return p;
    }
    AxisPosition q = AxisPosition::zero(rotaries());
    for (int k = 0; k < rotaries(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])];
    q.linear_mm = linear_for(machine, q.rotary_rad, Vec3d(p[0], p[1], p[2]), setup);
    for (int i = 0; i < 3; ++i)
      if (machine_mm[static_cast<std::size_t>(i)]) q.linear_mm[i] = *machine_mm[static_cast<std::size_t>(i)];
    const Vec3d tip = nominal_table_T_tool(q).t - setup.workpiece_origin_mm;
    for (int i = 0; i < 3; ++i) p[static_cast<std::size_t>(i)] = tip[i];
    return p;
  }

  /// Where G28 (`second`: G30) puts the axis, in M (mm or rad): the machine file's `reference`
  /// (`reference2`); Z without `reference` goes to the top of its travel. nullopt where not given.
  std::optional<double> reference_point(const Axis& axis, bool second) const {
    return second ? axis.reference2 : reference_or_top(axis);
  }

  /// What G28 / G30 / G53 do with the machine axes: the point, the machine's linear axes placed, and
  /// the notice's parts (the axes placed, the axes whose reference is not known).
  struct Placement {
    ProgramPoint p;
    std::array<std::optional<double>, 3> machine_mm{};
    bool moves = false;
    std::string placed, unknown;
  };

  /// Axis `i` of a G28 / G30 / G53 block placed at its reference (plus the G53 value), or noted as unknown.
  void place_axis(const MachineMove& mm, std::size_t i, cl::Location where, std::string_view line, Placement& to) {
    const bool given = mm.kind == MachineMove::Kind::machine;
    const bool second = mm.code == "G30";
    const char L = "XYZABC"[i];
    const int ai = machine.index_of(L);
    if (ai < 0) return;  // G28 alone names X Y Z; the interpreter refuses letters the machine lacks
    const Axis& axis = machine.axes[static_cast<std::size_t>(ai)];
    const std::optional<double> ref = reference_point(axis, second);
    const double offset = given ? mm.machine_value[i] : 0.0;
    if (second && !ref)
      throw InputError({file, where.line, mm.column},
                       fmt::format("G30 {}: the second reference point of {} is not in the machine file {}: give "
                                   "it as [axes.{}] reference2 = ... ({})",
                                   L, L, machine.name, L, axis.is_rotary() ? "deg" : "mm"),
                       std::string(line));
    const double scale = axis.is_rotary() ? 180.0 / kPi : 1.0;
    if (ref || (given && axis.is_rotary())) {
      const double target = ref.value_or(0.0) + offset;
      if (i < 3)
        to.machine_mm[i] = target;
      else
        to.p[i] = target;
      to.moves = true;
      const char* unit = axis.is_rotary() ? "deg" : "mm";
      const std::string from = !ref            ? std::string("its machine angle")
                               : offset != 0.0 ? fmt::format("{:.3f} {} from", offset * scale, unit)
                                               : std::string("at");
      const std::string point = L == 'Z' && !axis.reference && !second ? "the top of its travel (machine file)"
                                : second                               ? "its second reference point (machine file)"
                                                                       : "its reference point (machine file)";
      to.placed += fmt::format("{}{} goes to {:.3f} {}, {}{}", to.placed.empty() ? "" : "; ", L, target * scale, unit,
                               from, ref ? " " + point : std::string());
    } else {
      unplaced[i] = {where.line, mm.code, false};
      to.unknown += to.unknown.empty() ? std::string(1, L) : fmt::format(", {}", L);
    }
  }

  /// G28/G30 (the intermediate point, then the named axes to their reference point) or G53 (the
  /// motion to machine coordinates, counted from the reference point): the machine file's
  /// `reference`/`reference2` place them (Z's reference is the top of its travel when not given).
  /// An axis whose reference the file does not give must be programmed on the next motion (G28,
  /// G53; a rotary axis under G53 takes its machine angle); G30 without `reference2` is refused.
  /// Before the program's start is settled nothing is known of where the tool stands: the move
  /// is a comment and the first programmed values place the start.
  void queue_machine_move(const BlockEffect& fx, cl::Location where, std::string_view line,
                          const std::array<bool, 6>& known_prior) {
    const MachineMove& mm = *fx.machine_move;
    if (options.word_forward)
      throw InputError({file, where.line, mm.column},
                       fmt::format("{} on the machine {}, whose words {} are no Cartesian frame: not supported",
                                   mm.code, machine.name, program_letters(machine, options)),
                       std::string(line));
    if (!start_settled) {
      for (std::size_t i = 0; i < 6; ++i)
        if (mm.axes[i] && machine.index_of("XYZABC"[i]) >= 0 && !lands_where_assumed(mm, i))
          unplaced[i] = {where.line, mm.code, true};
      notices.push_back(
          fmt::format("{}:{}:{}: {} before the first programmed position moves nothing in the "
                      "posted program (where the tool stands is not known yet): the program's first "
                      "positions place the tool",
                      file, where.line, mm.column, mm.code));
      if (mm.kind == MachineMove::Kind::reference && fx.has_motion) hold_rapid(fx, where);
      return;
    }
    if (mm.kind == MachineMove::Kind::reference && fx.has_motion) queue_linear(fx, where, known_prior);
    Placement to{interpreter.state().position};
    for (std::size_t i = 0; i < 6; ++i)
      if (mm.axes[i]) place_axis(mm, i, where, line, to);
    const bool given = mm.kind == MachineMove::Kind::machine;
    const std::string& placed = to.placed;
    const std::string& unknown = to.unknown;
    notices.push_back(fmt::format(
        "{}:{}:{}: {}: {}{}", file, where.line, mm.column, mm.code,
        placed.empty() ? std::string("Z does not move") : placed + ", as a rapid",
        unknown.empty() ? ""
                        : fmt::format("; {} go(es) to (or count(s) from) a reference point the machine file does not "
                                      "give ([axes.{}] reference): the next motion must program it",
                                      unknown, unknown.front())));
    if (!to.moves) return;
    const ProgramPoint p = with_machine_linear(to.p, to.machine_mm);
    cl::Motion m = motion_at(p, where);
    m.rapid = !given || fx.motion == MotionMode::rapid;
    if (!m.rapid) {
      if (auto f = source_time_feed(m)) before.push_back(*f);
    }
    before.push_back(std::move(m));
    interpreter.moved_to(p);
  }

  // ---- tool offsets the program sets (G10 L1/L10/L12, gcode_tool_offsets.hpp): the post writes
  // them again; on a machine whose tip depends on the tool length (a rotary axis in the head, the
  // program read as machine axes) a length set for the register of G43 H must be the one the
  // reading uses (--tool-length), else the tip would be placed off by the difference.
  std::map<int, double> length_set_mm;  ///< by register, as the program set it

  void note_tool_offset(const cl::ToolOffset& t) {
    if (t.length_mm) length_set_mm[t.register_number] = *t.length_mm;
    before.push_back(t);
  }

  void check_length_set(int register_number, cl::Location where) {
    const auto set = length_set_mm.find(register_number);
    if (set == length_set_mm.end() || options.word_forward || rtcp_now()) return;
    const bool head = std::any_of(machine.axes.begin(), machine.axes.end(),
                                  [](const Axis& a) { return a.is_rotary() && a.side == Side::tool; });
    if (!head || std::abs(set->second - setup.tool_length_mm) <= 5e-4) return;
    throw InputError({file, where.line, where.column},
                     fmt::format("H{}: the program set this register's tool length to {:.4f} mm (G10), but the "
                                 "machine {} turns the tool in its head and the program is read for a tool length of "
                                 "{:.4f} mm (--tool-length): post with --tool-length {:.4f}",
                                 register_number, set->second, machine.name, setup.tool_length_mm, set->second));
  }

  /// Feed, tool, spindle, coolant, compensation and the other records before the block's motion.
  void queue_modal_records(const BlockEffect& fx, int line_number) {
    if (fx.feed) before.push_back(*fx.feed);
    if (fx.tool_change) before.push_back(*fx.tool_change);
    if (fx.tool_offset) note_tool_offset(*fx.tool_offset);
    if (fx.length_offset) check_length_set(fx.length_offset->register_number, fx.length_offset->where);
    if (fx.length_offset) before.push_back(*fx.length_offset);
    if (fx.spindle) before.push_back(*fx.spindle);
    if (fx.coolant) before.push_back(*fx.coolant);
    if (fx.cutter_comp) before.push_back(*fx.cutter_comp);
    for (const auto& u : fx.before_motion) before.push_back(u);
    if (fx.dwell_s) before.push_back(cl::Dwell{{line_number, block.column}, *fx.dwell_s});
    if (fx.cycle_off) {
      cl::Cycle off;  // kind off
      off.where = {line_number, block.column};
      before.push_back(off);
    }
  }

  /// A canned-cycle hole: its cycle, then the hole at its R plane (the cycle runs along machine Z).
  void queue_cycle_hole(const BlockEffect& fx, cl::Location where, std::string_view line) {
    cl::Motion m = motion_at(fx.end, where);
    ProgramPoint below = fx.end;
    below[2] -= 1.0;
    const cl::Motion d = motion_at(below, where);
    if ((m.point.tip_mm - d.point.tip_mm - m.point.axis).norm() > 1e-6)
      throw InputError({file, where.line, where.column},
                       "a canned cycle where machine Z is not the tool axis (a tilted head) is not supported",
                       std::string(line));
    before.push_back(*fx.cycle);
    before.push_back(m);
  }

  /// An arc: a CIRCLE record and its end point where it is one, else points along it (next()).
  void queue_arc(const BlockEffect& fx, cl::Location where, std::string_view line,
                 const std::array<bool, 6>& known_prior) {
    update_wrap(fx, where.line, false);
    if (!start_settled) release_held(known_prior, where.line);  // an arc starts from the held position
    const long n = arc_segments(*fx.arc, options.arc_chord_tolerance_mm);
    if (n > kMaxArcSegments)
      throw InputError({file, where.line, where.column},
                       fmt::format("the arc would need more than {} points at a chord tolerance of {} mm",
                                   kMaxArcSegments, options.arc_chord_tolerance_mm),
                       std::string(line));
    if (auto circle = as_circle(*fx.arc, where, n)) {
      before.push_back(*circle);
      cl::Motion m = motion_at(unwrapped(fx.arc->end), where);
      source_time_feed(m);  // not G93 (as_circle): follows the position
      before.push_back(std::move(m));
    } else {
      arc = fx.arc;
      arc_segments_total = n;
      arc_segment = 0;
      arc_where = where;
      if (fx.inverse_time && fx.motion_feed) effect.motion_feed = *fx.motion_feed * static_cast<double>(n);
    }
  }

  /// A rapid before the program's start is settled is held (the axes it leaves out are taken from
  /// their first programmed values); false when the block ends the program.
  bool hold_rapid(const BlockEffect& fx, cl::Location where) {
    update_wrap(fx, where.line, true);
    for (const auto& u : fx.after_motion) after.push_back(u);
    hold_block(fx, where);
    if (std::none_of(fx.assumed.begin(), fx.assumed.end(), [](bool b) { return b; })) release_held(known_before);
    if (fx.program_end) return end_program(where);
    return true;
  }

  /// A G0/G1 motion (with its source-time feed where the program runs in inverse time).
  void queue_linear(const BlockEffect& fx, cl::Location where, const std::array<bool, 6>& known_prior) {
    update_wrap(fx, where.line, true);
    if (!start_settled)
      release_held(known_prior,
                   fx.motion == MotionMode::rapid ? 0 : where.line);  // a feed motion starts from the held position
    cl::Motion m = motion_at(unwrapped(fx.end), where);
    if (auto f = source_time_feed(m)) before.push_back(*f);
    before.push_back(std::move(m));
  }

  /// M2/M30: the held records out, the units hint, the End record; always false.
  bool end_program(cl::Location where) {
    release_held(known_before);
    units_hint();
    after.push_back(cl::End{where, true});
    return false;
  }

  void finish_input() {
    const int line = source.line_number();
    if (opened_percent && !interpreter.state().ended)
      throw InputError({file, line, 0},
                       "the program starts with '%' but ends without the closing '%' or M2/M30 (truncated file?)");
    if (!opened_percent && !interpreter.state().ended && seen_content)
      notices.push_back(fmt::format("{}:{}: the program ends without M2/M30 or '%'", file, line));
  }

  cl::Record counted(cl::Record r) {
    if (std::holds_alternative<cl::Motion>(r)) ++motions_returned;
    return r;
  }

  std::optional<cl::Record> next() {
    for (;;) {
      if (before_next < before.size()) return counted(std::move(before[before_next++]));
      if (pending_motion) {
        cl::Motion m = std::move(*pending_motion);
        pending_motion.reset();
        ++motions_returned;
        return m;
      }
      if (arc) {
        ++arc_segment;
        const double t = static_cast<double>(arc_segment) / static_cast<double>(arc_segments_total);
        cl::Motion m = motion_at(unwrapped(arc->at(t)), arc_where);
        ++motions_returned;
        if (arc_segment >= arc_segments_total) arc.reset();
        if (auto f = source_time_feed(m)) {
          pending_motion = std::move(m);
          return *f;
        }
        return m;
      }
      if (after_next < after.size()) return counted(std::move(after[after_next++]));
      before.clear();
      before_next = 0;
      after.clear();
      after_next = 0;
      if (done) {
        check_something_moved();
        return std::nullopt;
      }
      if (!read_block()) done = true;
    }
  }
};

GcodeClReader::GcodeClReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                             GcodeReaderOptions options) {
  if (const std::string why = options.validate(); !why.empty()) throw std::invalid_argument(why);
  state_ = std::make_unique<State>(in, std::move(file_name), machine, setup, options);
}

GcodeClReader::~GcodeClReader() = default;

std::optional<cl::Record> GcodeClReader::next() { return state_->next(); }

std::vector<std::string> GcodeClReader::take_notices() {
  std::vector<std::string> out;
  out.swap(state_->notices);
  return out;
}

std::vector<std::string> GcodeClReader::header_notes() const {
  const GcodeReaderOptions& o = state_->options;
  if (o.power_on.empty()) return {};
  return {fmt::format("G-code input read from the power-on state {} ({})", o.power_on, o.power_on_source)};
}

bool GcodeClReader::last_motion_rtcp() const { return state_->last_rtcp; }
int GcodeClReader::lines_read() const { return state_->source.line_number(); }

namespace {

/// A reader that owns its file stream.
class FileGcodeReader final : public cl::Reader {
 public:
  FileGcodeReader(std::unique_ptr<std::ifstream> in, const std::string& path, const Machine& m, const Setup& s,
                  GcodeReaderOptions o)
      : in_(std::move(in)), reader_(*in_, path, m, s, o) {}
  std::optional<cl::Record> next() override { return reader_.next(); }
  std::vector<std::string> take_notices() override { return reader_.take_notices(); }
  std::vector<std::string> header_notes() const override { return reader_.header_notes(); }

 private:
  std::unique_ptr<std::ifstream> in_;
  GcodeClReader reader_;
};

}  // namespace

std::unique_ptr<cl::Reader> open_gcode(const std::string& path, const Machine& machine, const Setup& setup,
                                       GcodeReaderOptions options) {
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) throw InputError({path, 0, 0}, "cannot open the file for reading");
  return std::make_unique<FileGcodeReader>(std::move(in), path, machine, setup, options);
}

}  // namespace ncpost::gcode
