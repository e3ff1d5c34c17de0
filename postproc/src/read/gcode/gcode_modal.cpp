// SPDX-License-Identifier: Apache-2.0
// Modal interpretation of RS274 blocks (see gcode_modal.hpp for what is supported).
#include "ncpost/postproc/read/gcode/gcode_modal.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "ncpost/postproc/read/gcode/gcode_control_words.hpp"
#include "read/char_scan.hpp"
#include "ncpost/postproc/read/gcode/gcode_integer_words.hpp"
#include "read/gcode/gcode_tool_offsets.hpp"

namespace ncpost::gcode {
namespace {

using cl::kMaxDwellSeconds;
/// IntegerDwell::automatic: a time without a decimal point from this value on is milliseconds
/// (as seconds it would be a dwell of minutes); below it, down to 1, both readings are plausible.
constexpr double kSurelyMillisecondsFrom = 100.0;
/// Largest coordinate accepted (mm, or rad for rotary axes): beyond it arithmetic loses meaning.
constexpr double kMaxCoordinate = 1e9;
/// Largest feed, spindle speed and tool number accepted.
constexpr double kMaxWordValue = 1e9;
/// Largest offset register D accepted.
constexpr double kMaxRegister = 1e6;
/// Largest number of turns P of an arc accepted.
constexpr double kMaxArcTurns = 1e4;
/// A G or M number is one with at most one decimal (G43.4) within this slack ...
constexpr double kCodeDecimalSlack = 1e-6;
/// ... and at most this value times ten (G or M 9999.9).
constexpr double kMaxCode10 = 1e5;

/// Throws the InputError of a block.
struct Fail {
  const std::string& file;
  int line;
  std::string_view text;
  [[noreturn]] void operator()(int column, const std::string& what) const {
    throw InputError({file, line, column}, what, std::string(text));
  }
};

/// A G or M word: its code times ten (G43.4 -> 434) and its column.
struct Code {
  int code10 = 0;
  int column = 0;
};

std::string g_name(int code10) {
  return code10 % 10 == 0 ? fmt::format("G{}", code10 / 10) : fmt::format("G{}.{}", code10 / 10, code10 % 10);
}

enum GGroup : int {
  g_non_modal = 0,
  g_motion,
  g_plane,
  g_distance,
  g_arc_distance,
  g_feed,
  g_units,
  g_cutter,
  g_length,
  g_return,
  g_coordinates,
  g_path,
  g_dynamic_offset,
  g_group_count
};

/// A G code (x10: G54.1 is 541) and its modal group, or -1 with what it is, for the refusal.
struct GCodeGroup {
  int code10;
  int group;
  const char* refused;  ///< (group -1) what the code does that is not supported
};

constexpr GCodeGroup kGGroups[] = {
    {40, g_non_modal, nullptr},
    {100, g_non_modal, nullptr},
    {280, g_non_modal, nullptr},
    {300, g_non_modal, nullptr},
    {530, g_non_modal, nullptr},
    {520, g_non_modal, nullptr},
    {920, g_non_modal, nullptr},
    {0, g_motion, nullptr},
    {10, g_motion, nullptr},
    {20, g_motion, nullptr},
    {30, g_motion, nullptr},
    {800, g_motion, nullptr},
    {730, g_motion, nullptr},
    {740, g_motion, nullptr},
    {810, g_motion, nullptr},
    {820, g_motion, nullptr},
    {830, g_motion, nullptr},
    {840, g_motion, nullptr},
    {850, g_motion, nullptr},
    {860, g_motion, nullptr},
    {890, g_motion, nullptr},
    {170, g_plane, nullptr},
    {180, g_plane, nullptr},
    {190, g_plane, nullptr},
    {900, g_distance, nullptr},
    {910, g_distance, nullptr},
    {901, g_arc_distance, nullptr},
    {911, g_arc_distance, nullptr},
    {930, g_feed, nullptr},
    {940, g_feed, nullptr},
    {950, g_feed, nullptr},
    {200, g_units, nullptr},
    {210, g_units, nullptr},
    {400, g_cutter, nullptr},
    {410, g_cutter, nullptr},
    {420, g_cutter, nullptr},
    {430, g_length, nullptr},
    {431, g_length, nullptr},
    {434, g_length, nullptr},
    {435, g_length, nullptr},
    {490, g_length, nullptr},
    {2340, g_length, nullptr},
    {980, g_return, nullptr},
    {990, g_return, nullptr},
    {540, g_coordinates, nullptr},
    {541, g_coordinates, nullptr},
    {1540, g_coordinates, nullptr},  // Haas G154 P1 .. P99: G54.1 P1 .. P99
    {550, g_coordinates, nullptr},
    {560, g_coordinates, nullptr},
    {570, g_coordinates, nullptr},
    {580, g_coordinates, nullptr},
    {590, g_coordinates, nullptr},
    {591, g_coordinates, nullptr},
    {592, g_coordinates, nullptr},
    {593, g_coordinates, nullptr},
    {610, g_path, nullptr},
    {611, g_path, nullptr},
    {640, g_path, nullptr},
    {2540, g_dynamic_offset, nullptr},  // Haas DWO on/off
    {2550, g_dynamic_offset, nullptr},
    {411, -1, "dynamic cutter radius compensation"},
    {421, -1, "dynamic cutter radius compensation"},
    {330, -1, "threading"},
    {331, -1, "threading"},
    {760, -1,
     "fine boring with a spindle orientation and shift on Fanuc and Haas mills; threading on lathes and LinuxCNC"},
    {382, -1, "probing"},
    {383, -1, "probing"},
    {384, -1, "probing"},
    {385, -1, "probing"},
    {50, -1, "splines"},
    {51, -1, "splines"},
    {52, -1, "splines"},
    {53, -1, "splines"},
    {70, -1, "lathe diameter/radius mode"},
    {80, -1, "lathe diameter/radius mode"},
    {921, -1, "cancelling or restoring coordinate offsets (G92.1, G92.2, G92.3)"},
    {922, -1, "cancelling or restoring coordinate offsets (G92.1, G92.2, G92.3)"},
    {923, -1, "cancelling or restoring coordinate offsets (G92.1, G92.2, G92.3)"},
    {680, -1, "coordinate rotation"},
    {690, -1, "coordinate rotation"},
    {681, -1, "coordinate rotation"},
    {500, -1, "scaling"},
    {510, -1, "scaling"},
    {150, -1, "polar coordinates"},
    {160, -1, "polar coordinates"},
    {870, -1, "back boring and manual boring cycles"},
    {880, -1, "back boring and manual boring cycles"},
};

/// The modal group of a supported G code, or -1 with `why` naming what is not supported (null: unknown).
int g_group(int code10, const char*& why) {
  for (const GCodeGroup& g : kGGroups)
    if (g.code10 == code10) {
      why = g.refused;
      return g.group;
    }
  why = nullptr;
  return -1;
}

/// G80 beside G0 G1 G2 or G3 in one block (Fanuc's safe-start line `G00 G17 G40 G49 G80 G90`): on
/// Fanuc and Haas G80 is a group of its own (09), so the block cancels any canned cycle and sets the
/// motion mode — the motion code alone says both, since a motion mode ends a modal cycle. A cycle
/// beside G80 (or two motion codes) stays a contradiction.
bool cancels_cycle_beside(int code10_a, int code10_b) {
  const auto plain_motion = [](int c) { return c == 0 || c == 10 || c == 20 || c == 30; };
  return (code10_a == 800 && plain_motion(code10_b)) || (code10_b == 800 && plain_motion(code10_a));
}

/// A hole of the modal canned cycle: the cl::Cycle of the hole (distances from its R plane point,
/// where the motion ends) and the end of the motion at the R plane.
void cycle_hole(const ModalState& st, int line, int column, const Fail& fail, ProgramPoint& end, BlockEffect& fx) {
  const CycleModal& c = st.cycle;
  if (!c.bottom_z || !c.r_z) fail(column, "a canned cycle needs its Z (the bottom) and R (the R plane)");
  if (!(*c.bottom_z < *c.r_z)) fail(column, "canned cycle: the bottom Z is not below the R plane");
  using K = cl::Cycle::Kind;
  cl::Cycle k;
  k.where = {line, column};
  k.kind_word = g_name(c.code10);
  k.text = k.kind_word;
  switch (c.code10) {
    case 730:
      k.kind = K::chip_break;
      break;
    case 740:
      k.kind = K::tap, k.left_hand = true;
      break;
    case 810:
    case 820:
      k.kind = K::drill;
      break;
    case 830:
      k.kind = K::deep;
      break;
    case 840:
      k.kind = K::tap;
      break;
    case 850:
    case 890:
      k.kind = K::bore;
      break;
    case 860:
      k.kind = K::bore_drag;
      break;
    default:
      fail(column, fmt::format("{} is not supported", g_name(c.code10)));
  }
  k.depth_mm = *c.r_z - *c.bottom_z;
  k.rapid_to_mm = 0.0;
  if (!st.retract_to_r && c.initial_z > *c.r_z + 1e-9) k.retract_mm = c.initial_z - *c.r_z;
  if (k.kind == K::deep || k.kind == K::chip_break) {
    if (!c.q || !(*c.q > 0.0)) fail(column, fmt::format("{} needs a positive peck depth Q", g_name(c.code10)));
    k.peck_mm = k.first_peck_mm = *c.q;
  }
  if ((c.code10 == 820 || c.code10 == 890) && c.p_s) k.dwell_s = *c.p_s;
  if (st.feed_mode == FeedMode::inverse_time)
    fail(column, "canned cycles under inverse-time feed (G93) are not supported");
  if (!(st.feed > 0.0)) fail(column, "a canned cycle before any feed F");
  k.feed = st.feed;
  k.feed_per_rev = st.feed_mode == FeedMode::per_revolution;
  if (k.kind == K::tap) {
    if (k.feed_per_rev)
      k.pitch_mm = st.feed;
    else if (st.spindle_rpm > 0.0)
      k.pitch_mm = st.feed / st.spindle_rpm;
    else
      fail(column, "a tapping cycle before any spindle speed S: the pitch (F / S) is unknown");
  }
  end[2] = *c.r_z;
  fx.cycle = k;
}

/// A G2/G3 given by its centre words, before they are read (offsets along the plane's a1, a2; mm).
struct ArcGiven {
  const ProgramPoint& start;
  const ProgramPoint& end;
  Plane plane;
  bool clockwise;
  double offset1_mm, offset2_mm;
  int turns;

  bool fits(ArcCentre reading) const {
    const std::array<double, 2> c = arc_centre_of(reading, start, axes_of(plane), offset1_mm, offset2_mm);
    return arc_from_centre(start, end, plane, clockwise, c[0], c[1], turns).arc.has_value();
  }
  /// The radii at the start and at the end under `reading` (mm).
  std::array<double, 2> radii(ArcCentre reading) const {
    const PlaneAxes ax = axes_of(plane);
    const std::array<double, 2> c = arc_centre_of(reading, start, ax, offset1_mm, offset2_mm);
    const auto a1 = static_cast<std::size_t>(ax.a1), a2 = static_cast<std::size_t>(ax.a2);
    return {std::hypot(start[a1] - c[0], start[a2] - c[1]), std::hypot(end[a1] - c[0], end[a2] - c[1])};
  }
  /// Whether I and J fit as distances whose signs the writer dropped (a centre from some signs).
  bool fits_unsigned() const {
    for (const double sign1 : {1.0, -1.0})
      for (const double sign2 : {1.0, -1.0}) {
        const std::array<double, 2> c = arc_centre_of(ArcCentre::incremental, start, axes_of(plane),
                                                      sign1 * std::abs(offset1_mm), sign2 * std::abs(offset2_mm));
        if (arc_from_centre(start, end, plane, clockwise, c[0], c[1], turns).arc) return true;
      }
    return false;
  }
};

/// For an arc that the reading in force does not fit: the other readings it fits exactly (within
/// the arc's radius tolerance) and how to post with one, or that none does. Never a reading chosen
/// for the user: a program has one convention, and a full circle fits every one.
std::string other_readings_advice(const ArcGiven& arc, ArcCentre in_force, int set_at_line, std::string_view letters) {
  std::vector<ArcCentre> fitting;
  for (const ArcCentre r : {ArcCentre::incremental, ArcCentre::centre_to_start, ArcCentre::absolute})
    if (r != in_force && arc.fits(r)) fitting.push_back(r);
  if (fitting.empty()) {
    if (arc.fits_unsigned())
      return fmt::format(
          "; it fits only if {} are distances without their signs, a writing ncpost does not read (the "
          "centre is then a guess): post the CL data, or a program with signed {}",
          letters, letters);
    ArcCentre nearest = in_force;
    double nearest_mm = std::numeric_limits<double>::infinity();
    for (const ArcCentre r : {ArcCentre::incremental, ArcCentre::centre_to_start, ArcCentre::absolute}) {
      const std::array<double, 2> rr = arc.radii(r);
      if (r != in_force && std::abs(rr[1] - rr[0]) < nearest_mm) nearest = r, nearest_mm = std::abs(rr[1] - rr[0]);
    }
    const std::array<double, 2> rr = arc.radii(nearest);
    return fmt::format(
        "; no other reading of {} (from the start, from the centre, absolute, unsigned) fits it either "
        "(the nearest: if {}, radius {:.4f} mm at the start, {:.4f} mm at the end)",
        letters, arc_centre_meaning(nearest, letters), rr[0], rr[1]);
  }
  if (set_at_line) {
    std::string readings;
    for (const ArcCentre r : fitting) readings += (readings.empty() ? "" : ", or if ") + arc_centre_meaning(r, letters);
    return fmt::format("; it fits if {}, but G9{}.1 at line {} says {}", readings,
                       in_force == ArcCentre::absolute ? 0 : 1, set_at_line, arc_centre_meaning(in_force, letters));
  }
  if (fitting.size() == 1)
    return fmt::format("; it fits if {}: post with --arc-centre {}", arc_centre_meaning(fitting[0], letters),
                       arc_centre_name(fitting[0]));
  std::string readings;
  for (const ArcCentre r : fitting)
    readings += fmt::format("{}{} (--arc-centre {})", readings.empty() ? "" : ", or if ",
                            arc_centre_meaning(r, letters), arc_centre_name(r));
  return fmt::format("; it fits if {}: post with the one the program's control uses", readings);
}

}  // namespace

void BlockEffect::clear() {
  feed.reset();
  spindle.reset();
  tool_change.reset();
  length_offset.reset();
  tool_offset.reset();
  coolant.reset();
  cutter_comp.reset();
  before_motion.clear();
  has_motion = false;
  motion = MotionMode::none;
  arc.reset();
  assumed = {};
  programmed = {};
  machine_move.reset();
  dwell_s.reset();
  motion_feed.reset();
  inverse_time = false;
  after_motion.clear();
  program_end = false;
  call.reset();
  cycle.reset();
  cycle_off = false;
}

/// The words of one block sorted by letter (G and M codes listed apart).
struct Interpreter::Words {
  std::array<double, 26> value;
  std::array<int, 26> column;
  std::uint32_t present = 0;
  std::uint32_t point = 0;  ///< letters whose number has a decimal point
  std::array<Code, 16> g;
  int g_count = 0;
  std::array<Code, 8> m;
  int m_count = 0;
  double next_tool = 0.0;    ///< cl::ToolWords::load_next: the block's second T word (the tool pre-selected) ...
  int next_tool_column = 0;  ///< ... and its column (0: none)

  bool has(char c) const { return (present >> (c - 'A')) & 1u; }
  bool has_point(char c) const { return (point >> (c - 'A')) & 1u; }
  double get(char c) const { return value[static_cast<std::size_t>(c - 'A')]; }
  int col(char c) const { return column[static_cast<std::size_t>(c - 'A')]; }
};

Interpreter::Interpreter(std::string file_name, std::string axis_letters, bool default_inch, IntegerDwell integer_dwell,
                         ArcCentre arc_centre)
    : file_(std::move(file_name)),
      axis_letters_(std::move(axis_letters)),
      integer_dwell_(integer_dwell),
      arc_centre_option_(arc_centre) {
  state_.inch = state_.feed_inch = default_inch;
  state_.arc_centre = arc_centre;
  if (axis_letters_.find_first_of("UVW") != std::string::npos) {
    word_axes_ = true;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      slots_[i] = i < axis_letters_.size() ? axis_letters_[i] : '\0';
      slot_angle_[i] = false;
    }
  }
}

std::vector<std::string> Interpreter::take_notices() {
  std::vector<std::string> out;
  out.swap(notices_);
  return out;
}

void Interpreter::notice_once(const std::string& key, int line, int column, const std::string& text) {
  if (std::find(noticed_keys_.begin(), noticed_keys_.end(), key) != noticed_keys_.end()) return;
  noticed_keys_.push_back(key);
  notices_.push_back(fmt::format("{}:{}:{}: {}", file_, line, column, text));
}

/// One block being applied: where it is (errors, notices) and how to fail on it.
struct Interpreter::Context {
  const Block& block;
  int line_number;
  Fail fail;
  cl::Location at(int column) const { return cl::Location{line_number, column}; }
};

/// The G and M codes of a block by modal group, and a control's units word apart.
struct Interpreter::Codes {
  std::array<Code, g_group_count> group{};
  std::array<bool, g_group_count> in_group{};
  Code control_units{-1, 0};
  bool control_inch = false, control_feeds_too = false;
  Code m_stop{-1, 0}, m_spindle{-1, 0}, m_tool{-1, 0}, m_coolant{-1, 0}, m_rtcp{-1, 0}, m_call{-1, 0};

  bool in(int g) const { return in_group[static_cast<std::size_t>(g)]; }
  const Code& of(int g) const { return group[static_cast<std::size_t>(g)]; }
  bool is(int g, int code10) const { return in(g) && of(g).code10 == code10; }
};

namespace {

/// A coordinate written without a decimal point but with leading zeros (`X0019685`) is a fixed-format
/// (tape) value: where its decimal point stands is the control's input format (on a Fanuc, least
/// increments), not the program's; read as whole units it would be thousands of times too large.
void refuse_tape_format(const Block& block, std::string_view line, const Fail& fail) {
  for (const Word& word : block.words) {
    if (word.has_point || word.value == 0.0 || kIntegerWordLetters.find(word.letter) == std::string_view::npos)
      continue;
    std::size_t at = static_cast<std::size_t>(word.column);  // the character after the letter (1-based column)
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '+' || line[at] == '-')) ++at;
    if (!(at + 1 < line.size() && line[at] == '0' && is_digit(line[at + 1]))) continue;
    std::size_t end = at;
    while (end < line.size() && is_digit(line[end])) ++end;
    fail(word.column, fmt::format("{}{}: a number without a decimal point but with leading zeros is a fixed-format "
                                  "(tape) value whose decimal place the control's input format sets (on a Fanuc, "
                                  "least increments): not read; write the program with decimal points, or post "
                                  "with --integer-words increments (IS-B: 0.001 mm, 0.0001 in)",
                                  word.letter, line.substr(at, end - at)));
  }
}

}  // namespace

void Interpreter::apply(const Block& block, int line_number, std::string_view line, BlockEffect& fx) {
  fx.clear();
  const Context cx{block, line_number, Fail{file_, line_number, line}};
  if (integer_words_ != cl::IntegerWords::increments) refuse_tape_format(block, line, cx.fail);
  Words w = read_words(cx);
  Codes codes;
  group_g_codes(cx, w, codes);
  group_m_codes(cx, w, codes, fx);
  apply_units(cx, codes);
  read_integer_words(cx, codes, w);
  apply_feed_spindle_tool(cx, w, codes, fx);
  apply_cutter_comp(cx, w, codes, fx);
  apply_modal_settings(cx, w, codes, fx);
  apply_motion(cx, w, codes, fx);
  apply_stop(cx, codes, fx);
  apply_call(cx, w, codes, fx);
}

Interpreter::Words Interpreter::read_words(const Context& cx) const {
  const Fail& fail = cx.fail;
  Words w;
  // Haas G187 P E: its E (corner rounding) is the one E word the reader takes (and drops with it)
  const bool smoothing = std::any_of(cx.block.words.begin(), cx.block.words.end(),
                                     [](const Word& x) { return x.letter == 'G' && x.value == 187.0; });
  for (const Word& word : cx.block.words) {
    const char L = word.letter;
    if (L == 'E' && smoothing) continue;
    if (L == 'G' || L == 'M') {
      const double scaled = word.value * 10.0;
      const double rounded = std::round(scaled);
      if (word.value < 0.0 || std::abs(scaled - rounded) > kCodeDecimalSlack || rounded > kMaxCode10)
        fail(word.column, fmt::format("expected a {}-code number such as {}, found {}{}", L,
                                      L == 'G' ? "1 or 43.4" : "3", L, word.value));
      const Code code{static_cast<int>(rounded), word.column};
      if (L == 'G') {
        if (w.g_count == static_cast<int>(w.g.size())) fail(word.column, "too many G words in one block");
        w.g[static_cast<std::size_t>(w.g_count++)] = code;
      } else {
        if (code.code10 % 10 != 0) fail(word.column, fmt::format("expected an integer M code, found M{}", word.value));
        if (w.m_count == static_cast<int>(w.m.size())) fail(word.column, "too many M words in one block");
        w.m[static_cast<std::size_t>(w.m_count++)] = Code{code.code10 / 10, word.column};
      }
      continue;
    }
    if (L == 'N') continue;
    if (L == 'O') {
      if (&word != &cx.block.words.front())
        fail(word.column, "an O word (program number) must start its block; O-word control flow is not supported");
      continue;
    }
    check_letter(cx, word);
    if (L == 'T' && w.has('T')) {
      second_tool_word(cx, word, w);
      continue;
    }
    if (w.has(L)) fail(word.column, fmt::format("{} appears twice in the block", L));
    const auto i = static_cast<std::size_t>(L - 'A');
    w.present |= 1u << (L - 'A');
    if (word.has_point) w.point |= 1u << (L - 'A');
    w.value[i] = word.value;
    w.column[i] = word.column;
  }
  return w;
}

void Interpreter::check_letter(const Context& cx, const Word& word) const {
  const char L = word.letter;
  switch (L) {
    case 'E':
      cx.fail(word.column, "E words are not supported (and numbers have no exponent in G-code)");
    case 'U':
    case 'V':
    case 'W':
      if (!word_axes_ || axis_letters_.find(L) == std::string::npos)
        cx.fail(word.column, fmt::format("the {} axis is not supported", L));
      break;
    case 'A':
    case 'B':
    case 'C':
      if (axis_letters_.find(L) == std::string::npos)
        cx.fail(word.column, fmt::format("the machine has no {} axis (its axes are {})", L, axis_letters_));
      break;
    case 'X':
    case 'Y':
    case 'Z':
      if (word_axes_ && axis_letters_.find(L) == std::string::npos)
        cx.fail(word.column, fmt::format("the machine has no {} axis (its axes are {})", L, axis_letters_));
      break;
    case 'D':
    case 'F':
    case 'H':
    case 'I':
    case 'J':
    case 'K':
    case 'L':
    case 'P':
    case 'Q':
    case 'R':
    case 'S':
    case 'T':
      break;
    default:
      cx.fail(word.column, fmt::format("unknown word '{}'", L));
  }
}

// G codes by modal group (control-specific words apart: gcode_control_words.hpp)
void Interpreter::group_g_codes(const Context& cx, const Words& w, Codes& codes) {
  const Fail& fail = cx.fail;
  bool has_axis_words = false;
  for (const char L : slots_) has_axis_words = has_axis_words || (L && w.has(L));
  for (int k = 0; k < w.g_count; ++k) {
    const Code c = w.g[static_cast<std::size_t>(k)];
    const auto word_of = [&](char L) { return w.has(L) ? std::optional<double>(w.get(L)) : std::nullopt; };
    const ControlWord cw =
        classify_control_word(c.code10, has_axis_words, w.has('I') || w.has('J') || w.has('K') || w.has('R'),
                              word_of('P'), word_of('Q'), word_of('L'));
    if (cw.action != ControlWordAction::none) {
      if (cw.action == ControlWordAction::refuse) fail(c.column, cw.text);
      if (cw.action == ControlWordAction::drop) {
        if (!cw.text.empty()) notice_once(g_name(c.code10), cx.line_number, c.column, cw.text);
        continue;
      }
      const bool inch = cw.action == ControlWordAction::length_inch || cw.action == ControlWordAction::units_inch;
      if (codes.control_units.column)
        fail(c.column,
             fmt::format("{} and {} both set the units", g_name(codes.control_units.code10), g_name(c.code10)));
      codes.control_units = c;
      codes.control_inch = inch;
      codes.control_feeds_too = cw.action == ControlWordAction::units_inch || cw.action == ControlWordAction::units_mm;
      if (!cw.text.empty()) notice_once(g_name(c.code10), cx.line_number, c.column, cw.text);
      continue;
    }
    const char* why = nullptr;
    const int g = g_group(c.code10, why);
    if (g < 0) {
      if (why) fail(c.column, fmt::format("{} ({}) is not supported", g_name(c.code10), why));
      fail(c.column, fmt::format("{} is not supported", g_name(c.code10)));
    }
    const auto gi = static_cast<std::size_t>(g);
    if (codes.in_group[gi] && g == g_motion && cancels_cycle_beside(codes.group[gi].code10, c.code10)) {
      if (c.code10 != 800) codes.group[gi] = c;  // the motion code stays; it cancels the cycle itself
      continue;
    }
    if (codes.in_group[gi])
      fail(c.column,
           fmt::format("{} and {} are in the same modal group", g_name(codes.group[gi].code10), g_name(c.code10)));
    codes.in_group[gi] = true;
    codes.group[gi] = c;
  }
}

/// M91/M92 beside axis words: on Heidenhain (and the ISO programs NX writes for it) the block's
/// coordinates are machine coordinates; elsewhere the machine builder's. Either way not W.
constexpr const char* kMachineDatumM =
    "M{} with axis words: on Heidenhain controls the block's coordinates are then machine coordinates (M91: from "
    "the machine datum, M92: from a machine-defined position), which the reader does not place, and elsewhere M91/M92 "
    "are the machine builder's; post the CL data, or move in machine coordinates with G53";

bool Interpreter::has_axis_words(const Words& w) const {
  return std::any_of(slots_.begin(), slots_.end(), [&](char L) { return L && w.has(L); });
}

// M codes by group; the ones not acted on are passed through
void Interpreter::group_m_codes(const Context& cx, const Words& w, Codes& codes, BlockEffect& fx) {
  const auto take = [&](Code& slot, const Code& c) {
    if (slot.code10 >= 0)
      cx.fail(c.column, fmt::format("M{} and M{} are in the same modal group", slot.code10, c.code10));
    slot = c;
  };
  for (int k = 0; k < w.m_count; ++k) {
    const Code c = w.m[static_cast<std::size_t>(k)];
    switch (c.code10) {
      case 0:
      case 1:
      case 2:
      case 30:
      case 60:
        take(codes.m_stop, c);
        break;
      case 3:
      case 4:
      case 5:
        take(codes.m_spindle, c);
        break;
      case 6:
        take(codes.m_tool, c);
        break;
      case 7:
      case 8:
      case 9:
        take(codes.m_coolant, c);
        break;
      case 128:
      case 129:
      case 428:
      case 429:
        take(codes.m_rtcp, c);
        break;
      case 97:
      case 98:
      case 99:
        take(codes.m_call, c);
        break;
      case 91:
      case 92:
        if (has_axis_words(w)) cx.fail(c.column, fmt::format(kMachineDatumM, c.code10));
        [[fallthrough]];
      default:
        fx.after_motion.push_back(cl::Unsupported{cx.at(c.column), fmt::format("M{}", c.code10)});
        notice_once(fmt::format("M{}", c.code10), cx.line_number, c.column,
                    fmt::format("M{} is not acted on; passed through as a comment", c.code10));
    }
  }
}

// units first, so that every length word of the block is read in them
void Interpreter::apply_units(const Context& cx, const Codes& codes) {
  ModalState& st = state_;
  if (codes.control_units.column && codes.in(g_units))
    cx.fail(codes.control_units.column, fmt::format("{} and {} both set the units", g_name(codes.of(g_units).code10),
                                                    g_name(codes.control_units.code10)));
  if (codes.is(g_units, 200)) st.inch = st.feed_inch = true;
  if (codes.is(g_units, 210)) st.inch = st.feed_inch = false;
  if (codes.control_units.column) {
    st.inch = codes.control_inch;
    if (codes.control_feeds_too) st.feed_inch = codes.control_inch;
  }
  if (codes.in(g_units) || codes.control_units.column) st.units_programmed = true;
}

// feed mode and F; S, T, M6, M3-M5, M7-M9
void Interpreter::apply_feed_spindle_tool(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  const Fail& fail = cx.fail;
  if (codes.in(g_feed)) {
    const int c = codes.of(g_feed).code10;
    st.feed_mode = c == 930 ? FeedMode::inverse_time : c == 940 ? FeedMode::per_minute : FeedMode::per_revolution;
  }
  if (w.has('F')) {
    double f = w.get('F');
    if (f < 0.0 || f > kMaxWordValue) fail(w.col('F'), "expected a feed within 0 .. 1e9");
    if (st.feed_mode != FeedMode::inverse_time) {
      f *= st.feed_inch ? kMmPerInch : 1.0;
      fx.feed = cl::Feed{cx.at(w.col('F')), f, st.feed_mode == FeedMode::per_revolution};
    }
    st.feed = f;
    if (st.feed_mode != FeedMode::per_revolution) fx.motion_feed = f;  // per-rev feeds live in cl::Feed only
  }
  if (w.has('S')) {
    if (w.get('S') < 0.0 || w.get('S') > kMaxWordValue) fail(w.col('S'), "expected a spindle speed within 0 .. 1e9");
    st.spindle_rpm = w.get('S');
    if (st.spindle != cl::Spindle::Direction::off)
      fx.spindle = cl::Spindle{cx.at(w.col('S')), st.spindle, st.spindle_rpm};
  }
  change_tool(cx, w, codes, fx);
  if (codes.m_spindle.code10 >= 0) {
    using D = cl::Spindle::Direction;
    st.spindle = codes.m_spindle.code10 == 3 ? D::cw : codes.m_spindle.code10 == 4 ? D::ccw : D::off;
    fx.spindle = cl::Spindle{cx.at(codes.m_spindle.column), st.spindle, st.spindle_rpm};
  }
  if (codes.m_coolant.code10 >= 0) {
    const int c = codes.m_coolant.code10;
    fx.coolant = cl::Coolant{cx.at(codes.m_coolant.column), c != 9, c == 7 ? "MIST" : c == 8 ? "FLOOD" : "OFF"};
  }
}

// A second T word: with cl::ToolWords::load_next the tool pre-selected for the next change
void Interpreter::second_tool_word(const Context& cx, const Word& word, Words& w) const {
  if (tool_words_ != cl::ToolWords::load_next)
    cx.fail(word.column,
            "a second T word in the block: on a Mazak (and in NX's Mazak posts, T01 T02 M06) the first "
            "is the tool this M06 loads and the second the tool pre-selected for the next change; post "
            "with --tool-words load-next to read it so");
  if (w.next_tool_column) cx.fail(word.column, "a third T word in the block (a tool to load and one pre-selected)");
  w.next_tool = word.value;
  w.next_tool_column = word.column;
}

// T and M6 (cl::ToolWords::load_next: `T01 T02 M06` loads T01 and pre-selects T02, which the next change must load)
void Interpreter::change_tool(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  const auto tool_number = [&](double t, int column) {
    if (t < 0.0 || t != std::floor(t) || t > kMaxWordValue) cx.fail(column, "expected a tool number (an integer >= 0)");
    return static_cast<int>(t);
  };
  const bool change = codes.m_tool.code10 == 6;
  if (w.next_tool_column && !change)
    cx.fail(w.next_tool_column,
            "two T words without M06: the second pre-selects the tool of the next change, which "
            "is read only beside the M06 that loads the first");
  if (w.has('T')) st.tool = tool_number(w.get('T'), w.col('T'));
  if (!change) {
    if (w.has('T')) st.preselected_line = 0;  // the program selects anew
    return;
  }
  if (st.preselected_line && w.has('T') && st.tool != st.preselected_tool)
    cx.fail(w.col('T'), fmt::format("this M06 loads T{}, but the change at line {} pre-selected T{} for the next "
                                    "change (its second T word, --tool-words load-next): the program does not follow "
                                    "that reading",
                                    st.tool, st.preselected_line, st.preselected_tool));
  fx.tool_change = cl::ToolChange{cx.at(codes.m_tool.column), st.tool, std::nullopt};
  st.preselected_line = 0;
  if (!w.next_tool_column) return;
  st.preselected_tool = st.tool = tool_number(w.next_tool, w.next_tool_column);
  st.preselected_line = cx.line_number;
  notice_once("T pre-selected", cx.line_number, w.next_tool_column,
              fmt::format("T{} after the T of the change is the tool pre-selected for the next change "
                          "(--tool-words load-next): the posted program calls each tool at its change",
                          st.preselected_tool));
}

void Interpreter::set_word_rules(cl::ToolWords tool_words, cl::IntegerWords integer_words) {
  tool_words_ = tool_words;
  integer_words_ = integer_words;
  integer_evidence_.reset();
  if (integer_words == cl::IntegerWords::automatic) integer_evidence_.emplace();
}

// coordinates without a decimal point (gcode_integer_words.hpp): whole units, least increments, or
// (automatic) units unless the program also writes whole numbers with a decimal point
void Interpreter::read_integer_words(const Context& cx, const Codes& codes, Words& w) {
  const bool dwell = codes.is(g_non_modal, 40);  // G4's X is its time
  if (integer_evidence_) {
    if (const auto refusal = integer_evidence_->note(cx.block, cx.fail.text, file_, cx.line_number, dwell))
      cx.fail(refusal->column, refusal->text);
    return;
  }
  if (integer_words_ != cl::IntegerWords::increments) return;
  const auto read = [&](char L) {
    if (!w.has(L) || w.has_point(L) || (dwell && L == 'X')) return;
    const auto i = static_cast<std::size_t>(L - 'A');
    w.value[i] = in_least_increments(w.value[i], L, state_.inch);
    w.point |= 1u << (L - 'A');
  };
  for (const char L : kIntegerWordLetters) read(L);
  read('Q');  // a canned cycle's peck (only they read it)
}

// cutter radius compensation (G40, G41/G42 with D)
void Interpreter::apply_cutter_comp(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  if (!codes.in(g_cutter)) return;
  const Code c = codes.of(g_cutter);
  cl::CutterComp comp;
  comp.where = cx.at(c.column);
  comp.side = c.code10 == 410   ? cl::CutterComp::Side::left
              : c.code10 == 420 ? cl::CutterComp::Side::right
                                : cl::CutterComp::Side::off;
  comp.text = g_name(c.code10);
  if (w.has('D') && c.code10 != 400) {
    const double d = w.get('D');
    if (d < 0.0 || d != std::floor(d) || d > kMaxRegister)
      cx.fail(w.col('D'), "expected an offset register D (an integer >= 0)");
    comp.offset_register = static_cast<int>(d);
    comp.text += fmt::format(" D{}", static_cast<int>(d));
  }
  state_.cutter = comp.side;
  fx.cutter_comp = std::move(comp);
}

// dwell, plane, tool length and RTCP, work offsets, distance modes, the motion mode and the cycle's words
void Interpreter::apply_modal_settings(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  const int line_number = cx.line_number;
  if (codes.is(g_non_modal, 40)) read_dwell(cx, w, codes, fx);
  if (codes.in(g_plane)) {
    const int c = codes.of(g_plane).code10;
    st.plane = c == 170 ? Plane::xy : c == 180 ? Plane::zx : Plane::yz;
  }
  apply_tool_length(cx, w, codes, fx);
  apply_rtcp(cx, codes);
  apply_work_offset(cx, w, codes);
  if (codes.is(g_dynamic_offset, 2540))
    notice_once("G254", line_number, codes.of(g_dynamic_offset).column,
                "G254 (Haas dynamic work offset) is ignored: coordinates are taken in W as written");
  if (codes.in(g_distance)) st.incremental = codes.of(g_distance).code10 == 910;
  // after G90/G91 of the same block: under G91 both are refused
  if (codes.is(g_non_modal, 100) && w.has('L') && is_tool_offset_form(w.get('L')))
    apply_tool_offset(cx, w, codes, fx);
  else if (codes.is(g_non_modal, 100))
    apply_g10(cx, w, codes);
  if (codes.is(g_non_modal, 520) || codes.is(g_non_modal, 920)) apply_local_offset(cx, w, codes);
  apply_arc_distance(cx, codes);
  if (codes.in(g_return)) st.retract_to_r = codes.of(g_return).code10 == 990;
  apply_motion_mode(codes, fx);
  if (st.motion == MotionMode::cycle) read_cycle_words(cx, w, codes);
}

// G90.1/G91.1: the program says how its I J K read; beside --arc-centre other than incremental
// (the standard's reading, which G90.1 may switch) a different word contradicts the user's reading
void Interpreter::apply_arc_distance(const Context& cx, const Codes& codes) {
  if (!codes.in(g_arc_distance)) return;
  const Code c = codes.of(g_arc_distance);
  const ArcCentre said = c.code10 == 901 ? ArcCentre::absolute : ArcCentre::incremental;
  if (arc_centre_option_ != ArcCentre::incremental && said != arc_centre_option_)
    cx.fail(c.column, fmt::format("{} says I, J and K {} ({}), which contradicts --arc-centre {}: post without "
                                  "--arc-centre {} (the program says how it writes arc centres)",
                                  g_name(c.code10),
                                  said == ArcCentre::absolute ? "are the centre's coordinates"
                                                              : "are the vector from the start to the centre",
                                  arc_centre_name(said), arc_centre_name(arc_centre_option_),
                                  arc_centre_name(arc_centre_option_)));
  state_.arc_centre = said;
  state_.arc_centre_line = cx.line_number;
}

// G54-G59, G54.1 P<n>, G59.1-G59.3: the offset in force at the first motion places W (the job's
// --workpiece-origin); the coordinates under another are shifted into its frame by the offsets'
// values (work_frames.hpp), and refused where those are not known.
void Interpreter::apply_work_offset(const Context& cx, const Words& w, const Codes& codes) {
  ModalState& st = state_;
  if (!codes.in(g_coordinates)) return;
  const Code c = codes.of(g_coordinates);
  std::string name = g_name(c.code10);
  if (c.code10 == 541 || c.code10 == 1540) {
    const bool haas = c.code10 == 1540;  // Haas G154 P1 .. P99 is G54.1 P1 .. P99
    const std::optional<std::string> n = w.has('P') && (!haas || w.get('P') <= 99.0)
                                             ? work_offset_name(fmt::format("G54.1 P{}", w.get('P')))
                                             : std::optional<std::string>();
    if (!n)
      cx.fail(w.has('P') ? w.col('P') : c.column,
              haas ? "G154 needs P1 .. P99 (the number of the Haas extended work offset, G54.1 P1 .. P99)"
                   : "G54.1 needs P1 .. P300 (the number of the extended work offset)");
    name = *n;
  }
  const bool fixed = frames_.fixed();
  const std::string base = WorkFrames::named(frames_.base());
  const int moved_line = st.work_offset_line;
  if (name != st.work_offset) st.work_offset_line = cx.line_number;
  st.work_offset = name;
  if (word_axes_ && fixed && name != frames_.base())
    cx.fail(c.column, fmt::format("{}: a second work offset on the machine {}, whose words are no Cartesian frame: "
                                  "post the operations of each set-up apart",
                                  name, axis_letters_));
  if (const std::string why = frames_.select(name); !why.empty())
    cx.fail(c.column, moved_line ? fmt::format("{} (selected at line {})", why, moved_line) : why);
  if (fixed && name != frames_.base()) {
    const std::array<double, 6>& d = frames_.shift();
    notice_once("work-offset " + name, cx.line_number, c.column,
                fmt::format("{}: its coordinates are placed in the frame of {} (the posted program's W), shifted by "
                            "X{:+.4f} Y{:+.4f} Z{:+.4f} mm{} (the offsets' values from {})",
                            name, base, d[0], d[1], d[2],
                            d[3] != 0.0 || d[4] != 0.0 || d[5] != 0.0
                                ? fmt::format(" A{:+.4f} B{:+.4f} C{:+.4f} deg", rad_to_deg(d[3]), rad_to_deg(d[4]),
                                              rad_to_deg(d[5]))
                                : std::string(),
                            frames_.source_of(name)));
  } else if (c.code10 != 540) {
    notice_once(
        "work-offset", cx.line_number, c.column,
        fmt::format("{} work offset: coordinates are taken in W as written (the job's workpiece origin places W)",
                    name));
  }
}

// The first motion in work coordinates fixes the posted frame; where the program's own G10 set
// that offset's values, the posted program (which does not set them) needs them on the control
void Interpreter::note_moved(const Context& cx) {
  if (frames_.fixed()) return;
  frames_.moved();
  const std::string source = frames_.source_of(frames_.base());
  if (source.rfind("G10", 0) == 0)
    notice_once("base-g10", cx.line_number, cx.block.column,
                fmt::format("the posted program moves in the frame of {}, whose values the input's {} sets: the posted "
                            "program does not set them (set {} on the control as the input does before running it)",
                            WorkFrames::named(frames_.base()), source, WorkFrames::named(frames_.base())));
}

void Interpreter::set_work_offsets(std::shared_ptr<const WorkOffsetTable> table, cl::ControlFamily control) {
  std::array<bool, 6> used{};
  for (std::size_t i = 0; i < 6; ++i) used[i] = !word_axes_ && axis_letters_.find("XYZABC"[i]) != std::string::npos;
  frames_ = WorkFrames(std::move(table), used);
  control_ = control;
}

void Interpreter::power_on(const std::string& codes, const std::string& source, bool units_given) {
  Block block;
  parse_block(codes, block, source, 1);
  const bool inch = state_.inch, feed_inch = state_.feed_inch;
  BlockEffect scratch;  // cancel words (G40, G49, G80) change nothing to post
  apply(block, 0, codes, scratch);
  if (scratch.has_motion)
    throw InputError({source, 1, 0}, "the power-on state moves the machine: expected G codes only");
  if (units_given) state_.inch = inch, state_.feed_inch = feed_inch;
  state_.units_programmed = false;
  state_.work_offset_line = 0;
  notices_.clear();
  noticed_keys_.clear();
}

// The offset a G10 L2/L20 P<n> names on the program's control (docs/formats.md "Work offsets")
std::string Interpreter::g10_offset_name(const Context& cx, const Words& w, int kind, int column) const {
  using F = cl::ControlFamily;
  const double p = w.has('P') ? w.get('P') : -1.0;
  if (p < 0.0 || p != std::floor(p) || p > 1000.0)
    cx.fail(w.has('P') ? w.col('P') : column, fmt::format("G10 L{} needs P, the number of the offset it sets", kind));
  const int n = static_cast<int>(p);
  const auto control_needed = [&](const char* what) {
    cx.fail(column, fmt::format("G10 L{} P{} {}: say which control the program is for with --dialect (a dialect whose "
                                "[input] control is \"fanuc\" or \"linuxcnc\")",
                                kind, n, what));
  };
  if (kind == 20 && control_ == F::fanuc) {
    if (const std::optional<std::string> name = work_offset_name(fmt::format("G54.1 P{}", n))) return *name;
    cx.fail(w.col('P'), "G10 L20 (Fanuc, Haas) sets an extended work offset G54.1 P1 .. P300: expected P1 .. P300");
  }
  if (kind == 20 && control_ == F::unknown)
    control_needed("sets G54.1 P<n> on Fanuc and Haas, but on LinuxCNC makes the current position read the values");
  if (n == 0) {
    if (control_ == F::linuxcnc) return frames_.active();
    if (control_ == F::fanuc)
      cx.fail(w.col('P'),
              "G10 L2 P0 sets the external work offset (added to every offset): not supported; remove it "
              "and give its values in the offsets of --work-offsets");
    control_needed("is the active offset on LinuxCNC but the external offset on Fanuc");
  }
  if (const std::optional<std::string> name = work_offset_of_register(n)) return *name;
  cx.fail(w.col('P'), fmt::format("G10 L{} P{}: expected P1 .. P9 (G54 .. G59, G59.1 .. G59.3){}", kind, n,
                                  control_ == F::linuxcnc ? " or P0 (the active offset)" : ""));
}

// G10 L2 P<n> (the offset's values, machine coordinates) and G10 L20 (Fanuc, Haas: G54.1 P<n>'s
// values; LinuxCNC: the values that make the current position read the words)
void Interpreter::apply_g10(const Context& cx, const Words& w, const Codes& codes) {
  ModalState& st = state_;
  const int column = codes.of(g_non_modal).column;
  const int kind = static_cast<int>(w.get('L'));  // 2 or 20 (classify_control_word refuses the others)
  if (st.incremental)
    cx.fail(column, "G10 under G91: Fanuc adds the values to the offset, LinuxCNC sets them; write G90 before it");
  if (w.has('R')) cx.fail(w.col('R'), "G10 with R (a rotated coordinate system) is not supported");
  const std::string name = g10_offset_name(cx, w, kind, column);
  const bool reading = kind == 20 && control_ == cl::ControlFamily::linuxcnc;
  const double length_scale = st.inch ? kMmPerInch : 1.0;
  std::array<std::optional<double>, 6> values{};
  for (std::size_t i = 0; i < 6; ++i) {
    const char L = slots_[i];
    if (!L || !w.has(L)) continue;
    values[i] = slot_angle_[i] ? deg_to_rad(w.get(L)) : w.get(L) * length_scale;
    if (!(std::abs(*values[i]) <= kMaxCoordinate)) cx.fail(w.col(L), fmt::format("{} is out of range", L));
    if (reading && !st.known[i])
      cx.fail(w.col(L), fmt::format("G10 L20 sets {} so that the current position reads {}, and where {} stands is "
                                    "not known yet (no motion has programmed it)",
                                    L, w.get(L), L));
  }
  if (word_axes_)
    cx.fail(column,
            fmt::format("G10 on the machine {}, whose words are no Cartesian frame: not supported", axis_letters_));
  const std::string why = reading ? frames_.set_reading(name, st.position, values) : frames_.set_value(name, values);
  if (!why.empty()) cx.fail(column, why);
  frames_.note_source(name, fmt::format("G10 at line {}", cx.line_number));
}

// G10 L1, L10 .. L13: a tool offset set in the program, as the dialect's [input] tool_offsets reads it
void Interpreter::apply_tool_offset(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ToolOffsetBlock b;
  b.l = static_cast<int>(w.get('L'));
  b.column = codes.of(g_non_modal).column;
  const auto word = [&](char c) {
    return w.has(c) ? std::optional<ToolOffsetWord>(ToolOffsetWord{w.get(c), w.col(c)}) : std::nullopt;
  };
  b.p = word('P');
  b.r = word('R');
  b.z = word('Z');
  for (char c = 'A'; c <= 'Z' && !b.other; ++c)
    if (w.has(c) && std::string_view("GLNPRZ").find(c) == std::string_view::npos)
      b.other = c, b.other_column = w.col(c);
  b.incremental = state_.incremental;
  b.mm_per_unit = state_.inch ? kMmPerInch : 1.0;
  if (word_axes_)
    cx.fail(b.column,
            fmt::format("G10 on the machine {}, whose words are no Cartesian frame: not supported", axis_letters_));
  fx.tool_offset = read_tool_offset(tool_offset_writes_, b, file_, cx.line_number, cx.fail.text);
}

// G52 (the local shift is the words) and G92 (the local shift that makes the current position read
// the words): added to every absolute coordinate after it, in every work offset (work_frames.hpp).
// The posted program carries the shift in its coordinates and writes neither word.
void Interpreter::apply_local_offset(const Context& cx, const Words& w, const Codes& codes) {
  ModalState& st = state_;
  const Code c = codes.of(g_non_modal);
  const int code = c.code10 / 10;  // 52 or 92
  if (st.incremental)
    cx.fail(c.column, fmt::format("G{} under G91: write G90 before it (controls differ on incremental values)", code));
  if (word_axes_)
    cx.fail(c.column, fmt::format("G{} on the machine {}, whose words are no Cartesian frame: not supported", code,
                                  axis_letters_));
  const std::array<double, 6>& local = frames_.local();
  const bool shifted = std::any_of(local.begin(), local.end(), [](double v) { return v != 0.0; });
  if (shifted && local_code_ != 0 && local_code_ != code)
    cx.fail(c.column, fmt::format("G{} while the shift of G{} (line {}) is in force: Fanuc keeps the two apart, "
                                  "LinuxCNC shares one offset; cancel it first (G{} with zeros)",
                                  code, local_code_, local_line_, local_code_));
  const double length_scale = st.inch ? kMmPerInch : 1.0;
  std::array<std::optional<double>, 6> values{};
  std::string words;
  for (std::size_t i = 0; i < 6; ++i) {
    const char L = slots_[i];
    if (!L || !w.has(L)) continue;
    values[i] = slot_angle_[i] ? deg_to_rad(w.get(L)) : w.get(L) * length_scale;
    if (!(std::abs(*values[i]) <= kMaxCoordinate)) cx.fail(w.col(L), fmt::format("{} is out of range", L));
    if (code == 92 && !st.known[i])
      cx.fail(w.col(L), fmt::format("G92 makes the current position read {}{}, and where {} stands is not known yet "
                                    "(no motion has programmed it)",
                                    L, w.get(L), L));
    words += fmt::format(" {}{}", L, w.get(L));
  }
  if (words.empty()) cx.fail(c.column, fmt::format("G{} without axis words", code));
  if (code == 52)
    frames_.set_local(values);
  else
    frames_.set_local_reading(st.position, values);
  local_code_ = code;
  local_line_ = cx.line_number;
  const std::array<double, 6>& d = frames_.local();
  notice_once(fmt::format("G{}", code), cx.line_number, c.column,
              fmt::format("G{}{}: the coordinates after it are shifted by X{:+.4f} Y{:+.4f} Z{:+.4f} mm into the "
                          "posted program's frame (which writes the shift into its coordinates, not the G{}); "
                          "later G{} blocks the same way",
                          code, words, d[0], d[1], d[2], code, code));
}

// G43 H<n> (and G43.4, G43.5, G234): the tool's length from register n, which the post writes
// (cl::LengthOffset); G49 or H0 cancels the length: a later motion is refused (check_length_in_force)
void Interpreter::apply_tool_length(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  if (!codes.in(g_length)) return;
  const Code c = codes.of(g_length);
  const bool cancel = c.code10 == 490 || (w.has('H') && w.get('H') == 0.0);
  if (cancel) {
    if (st.length == ModalState::Length::on) {
      st.length = ModalState::Length::cancelled;
      st.length_cancelled_line = cx.line_number;
    }
    return;
  }
  st.length = ModalState::Length::on;
  if (!w.has('H')) return;  // the length in force (LinuxCNC: the tool's)
  const double h = w.get('H');
  if (h < 0.0 || h != std::floor(h) || h > kMaxRegister)
    cx.fail(w.col('H'), fmt::format("expected a tool length register H from 0 to {:g} (a whole number)", kMaxRegister));
  fx.length_offset = cl::LengthOffset{cx.at(w.col('H')), static_cast<int>(h)};
}

// Once a program has used a tool length, a cut after G49 (or H0) is refused: its Z would name the
// spindle's gauge point, the post's the tool tip. Rapids (positioning between tools, before the
// next G43) are taken as the rapids before the first G43 are, the tip where the words say — for a
// Z rapid that is the tool length above where the source would put it — with a notice.
void Interpreter::check_length_in_force(const Context& cx, const Words& w, MotionMode motion, int column) {
  if (state_.length != ModalState::Length::cancelled) return;
  if (motion == MotionMode::rapid) {
    if (w.has('Z'))
      notice_once("rapid-after-G49", cx.line_number, column,
                  fmt::format("a rapid in Z with the tool length cancelled (G49 or H0 at line {}) is posted with the "
                              "length in force: the tool tip at the programmed Z (a tool length above the spindle's "
                              "gauge point there)",
                              state_.length_cancelled_line));
    return;
  }
  cx.fail(column, fmt::format("a cutting motion with the tool length cancelled (G49 or H0 at line {}): the post places "
                              "the tool tip with the tool's length; program G43 H.. before it, or move in machine "
                              "coordinates (G28, G53)",
                              state_.length_cancelled_line));
}

// tool length and RTCP/TCPM: G43.4/G43.5/G234 ... G43/G49, M128/M129, M428/M429, TRAORI/TRAFOOF
void Interpreter::apply_rtcp(const Context& cx, const Codes& codes) {
  ModalState& st = state_;
  const bool was_on = st.rtcp != Rtcp::off;
  if (codes.in(g_length)) {
    const int c = codes.of(g_length).code10;
    if (c == 434 || c == 435)
      st.rtcp = Rtcp::g43_4;
    else if (c == 2340)
      st.rtcp = Rtcp::g234;
    else if (st.rtcp == Rtcp::g43_4 || st.rtcp == Rtcp::g234)
      st.rtcp = Rtcp::off;  // G43, G43.1, G49
  }
  if (codes.m_rtcp.code10 == 428) st.rtcp = Rtcp::m428;
  if (codes.m_rtcp.code10 == 429 && st.rtcp == Rtcp::m428) st.rtcp = Rtcp::off;
  if (codes.m_rtcp.code10 == 128) st.rtcp = Rtcp::m128;
  if (codes.m_rtcp.code10 == 129 && st.rtcp == Rtcp::m128) st.rtcp = Rtcp::off;
  for (const BlockKeyword& k : cx.block.keywords) {
    if (k.keyword == Keyword::traori) st.rtcp = Rtcp::traori;
    if (k.keyword == Keyword::trafoof && st.rtcp == Rtcp::traori) st.rtcp = Rtcp::off;
  }
  const bool is_on = st.rtcp != Rtcp::off;
  if (reframe_ && is_on != was_on) st.position = reframe_(st.position, is_on);
}

// the motion group: G0 G1 G2 G3 G80 and the canned cycles (a new cycle starts from where the tool stands)
void Interpreter::apply_motion_mode(const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  if (!codes.in(g_motion)) return;
  const int code = codes.of(g_motion).code10;
  if (st.motion == MotionMode::cycle && code != st.cycle.code10) fx.cycle_off = true;  // G80, another motion or cycle
  if (code == 730 || code == 740 || (code >= 810 && code <= 890)) {
    if (st.motion != MotionMode::cycle || st.cycle.code10 != code) {
      st.cycle = CycleModal{};
      st.cycle.code10 = code;
      st.cycle.initial_z = st.position[2];
    }
  }
  switch (code) {
    case 0:
      st.motion = MotionMode::rapid;
      break;
    case 10:
      st.motion = MotionMode::linear;
      break;
    case 20:
      st.motion = MotionMode::arc_cw;
      break;
    case 30:
      st.motion = MotionMode::arc_ccw;
      break;
    case 800:
      st.motion = MotionMode::none;
      break;
    default:
      st.motion = MotionMode::cycle;
      break;  // G73 G74 G81-G86 G89
  }
}

// the cycle's words are modal within it (Z bottom, R plane, Q peck, P dwell)
void Interpreter::read_cycle_words(const Context& cx, const Words& w, const Codes& codes) {
  ModalState& st = state_;
  const Fail& fail = cx.fail;
  const double length_scale = st.inch ? kMmPerInch : 1.0;
  if (st.incremental)
    fail(codes.of(g_motion).column ? codes.of(g_motion).column : cx.block.column,
         "canned cycles under G91 (incremental Z and R) are not supported");
  if (w.has('Z')) st.cycle.bottom_z = w.get('Z') * length_scale + frames_.shift()[2];
  if (w.has('R')) st.cycle.r_z = w.get('R') * length_scale + frames_.shift()[2];
  if (w.has('Q')) st.cycle.q = w.get('Q') * length_scale;
  const bool call = codes.m_call.code10 == 97 || codes.m_call.code10 == 98;  // P and L are the call's
  if (w.has('P') && !call) st.cycle.p_s = dwell_seconds(cx, w, 'P', g_name(st.cycle.code10));
  if ((w.has('L') && !call) || w.has('K'))
    fail(w.col(w.has('L') ? 'L' : 'K'), "repeated canned cycles (L or K) are not supported");
}

// G4: the dwell from X (Fanuc, Haas) or P (all); the block moves nothing (X is the time, not an axis)
void Interpreter::read_dwell(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  const int column = codes.of(g_non_modal).column;
  for (const char L : {'Y', 'Z', 'A', 'B', 'C', 'I', 'J', 'K', 'R'})
    if (w.has(L)) cx.fail(w.col(L), fmt::format("{} in a G4 (dwell) block: a dwell moves nothing", L));
  if (w.has('X') && w.has('P')) cx.fail(w.col('P'), "G4 takes the time either in X or in P, not both");
  const char t = w.has('X') ? 'X' : 'P';
  if (!w.has(t)) cx.fail(column, "G4 (dwell) without its time (expected P or X)");
  fx.dwell_s = dwell_seconds(cx, w, t, "G4");
}

// A dwell time in seconds: with a decimal point it is seconds on every control; without one it
// is milliseconds on Fanuc and Haas but seconds on LinuxCNC (IntegerDwell says which, or how to guess)
double Interpreter::dwell_seconds(const Context& cx, const Words& w, char letter, std::string_view code) {
  const double v = w.get(letter);
  const int column = w.col(letter);
  const auto check = [&](double seconds) {
    if (!(seconds >= 0.0 && seconds <= kMaxDwellSeconds))
      cx.fail(column, fmt::format("expected a dwell time from 0 to {} s, got {}{} ({} s)", kMaxDwellSeconds, letter, v,
                                  seconds));
    return seconds;
  };
  if (!(v > 0.0) || w.has_point(letter) || integer_dwell_ == IntegerDwell::seconds) return check(v);
  if (integer_dwell_ == IntegerDwell::milliseconds) return check(v / 1000.0);
  if (v >= kSurelyMillisecondsFrom) {
    notice_once(
        "dwell-ms", cx.line_number, column,
        fmt::format("{} {}{} (no decimal point) is read as {} ms, as Fanuc and Haas read it: as seconds it would "
                    "be a dwell of {:.1f} min (--dwell-p s reads it so)",
                    code, letter, v, v, v / 60.0));
    return check(v / 1000.0);
  }
  cx.fail(column, fmt::format("{} {}{} (no decimal point) is {} ms on Fanuc and Haas but {} s on LinuxCNC: say which "
                              "with --dwell-p ms or --dwell-p s, or write the time in seconds with a decimal point",
                              code, letter, v, v, v));
  return 0.0;
}

// G28/G30: the axes named (all of X Y Z when none is) go to their reference point after the
// block's motion to the intermediate point; the reader places that through the machine
void Interpreter::note_reference_return(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  const Code c = codes.of(g_non_modal);
  MachineMove mm;
  mm.kind = MachineMove::Kind::reference;
  mm.code = g_name(c.code10);
  mm.column = c.column;
  bool any = false;
  for (std::size_t i = 0; i < 6; ++i)
    if (slots_[i] && w.has(slots_[i])) mm.axes[i] = any = true;
  if (!any) mm.axes[0] = mm.axes[1] = mm.axes[2] = true;  // RS274NGC: G28 alone returns every axis
  fx.before_motion.push_back(cl::Unsupported{cx.at(c.column), mm.code + " (return to the reference point)"});
  fx.machine_move = std::move(mm);
}

// G53: the block's axis words are machine coordinates (absolute, whatever G90/G91)
void Interpreter::note_machine_coordinates(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  const double length_scale = state_.inch ? kMmPerInch : 1.0;
  MachineMove mm;
  mm.kind = MachineMove::Kind::machine;
  mm.code = "G53";
  mm.column = codes.of(g_non_modal).column;
  for (std::size_t i = 0; i < 6; ++i) {
    const char L = slots_[i];
    if (!L || !w.has(L)) continue;
    mm.axes[i] = true;
    mm.machine_value[i] = slot_angle_[i] ? deg_to_rad(w.get(L)) : w.get(L) * length_scale;
    if (!(std::abs(mm.machine_value[i]) <= kMaxCoordinate))
      cx.fail(w.col(L), fmt::format("{} is out of range (expected a coordinate within +-1e9)", L));
  }
  fx.machine_move = std::move(mm);
}

void Interpreter::apply_motion(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  ModalState& st = state_;
  const Fail& fail = cx.fail;
  int first_axis_column = 0;
  bool has_axis = false;
  for (const char L : slots_)
    if (L && w.has(L)) {
      has_axis = true;
      if (!first_axis_column || w.col(L) < first_axis_column) first_axis_column = w.col(L);
    }
  const int axis_column = first_axis_column ? first_axis_column : cx.block.column;
  // G4: X is its time; G10, G52, G92: offset values
  if (codes.is(g_non_modal, 40) || codes.is(g_non_modal, 100) || codes.is(g_non_modal, 520) ||
      codes.is(g_non_modal, 920))
    return;
  const bool home_return = codes.is(g_non_modal, 280) || codes.is(g_non_modal, 300);
  if (home_return) note_reference_return(cx, w, codes, fx);
  if (codes.is(g_non_modal, 530)) note_machine_coordinates(cx, w, codes, fx);
  const bool is_arc = st.motion == MotionMode::arc_cw || st.motion == MotionMode::arc_ccw;
  const bool arc_words = !(st.motion == MotionMode::cycle) && (w.has('I') || w.has('J') || w.has('K') || w.has('R'));
  // a block of I J K alone under a modal G2/G3 is a full circle on a Fanuc-family control (the end
  // point left out is the start; NX's Makino posts write N2250 G03 ..., N2260 I-.9193 J0.0);
  // LinuxCNC's behaviour there is not confirmed: refused under its dialect, as before
  const bool modal_full_circle =
      is_arc && !has_axis && !w.has('R') && arc_words && control_ != cl::ControlFamily::linuxcnc;
  if (arc_words && !(is_arc && (codes.in(g_motion) || has_axis || modal_full_circle)) && !home_return) {
    const char c = w.has('I') ? 'I' : w.has('J') ? 'J' : w.has('K') ? 'K' : 'R';
    fail(w.col(c), fmt::format("{} without an arc (expected G2 or G3)", c));
  }
  // the intermediate point of G28/G30 where its axes are known (else the return alone)
  bool intermediate_known = true;
  for (std::size_t i = 0; i < 6; ++i)
    if (slots_[i] && w.has(slots_[i]) && !st.known[i]) intermediate_known = false;
  const bool moves = home_return ? has_axis && intermediate_known
                                 : (has_axis || (is_arc && (codes.in(g_motion) || modal_full_circle) && arc_words));
  if (!moves) return;
  if (fx.machine_move && !home_return) return machine_coordinates_motion(cx, w, codes, fx);
  if (home_return) return intermediate_motion(cx, w, axis_column, fx);
  programmed_motion(cx, w, codes, {axis_column, first_axis_column}, fx);
}

/// G53: the reader places the machine coordinates; the block's motion holds the modal mode.
void Interpreter::machine_coordinates_motion(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  const ModalState& st = state_;
  if (st.motion != MotionMode::rapid && st.motion != MotionMode::linear)
    cx.fail(codes.of(g_non_modal).column, "G53 (machine coordinates) with an arc or a canned cycle: expected G0 or G1");
  if (st.motion == MotionMode::linear && st.feed_mode == FeedMode::inverse_time)
    cx.fail(codes.of(g_non_modal).column, "G53 G1 under inverse-time feed (G93) is not supported: use G0 or G94");
  fx.has_motion = true;
  fx.motion = st.motion;
  fx.start = fx.end = st.position;
  for (std::size_t i = 0; i < 6; ++i) fx.programmed[i] = slots_[i] && w.has(slots_[i]);
}

/// G28 / G30: the intermediate point, a rapid whatever the modal motion (G28 is non-modal).
void Interpreter::intermediate_motion(const Context& cx, const Words& w, int axis_column, BlockEffect& fx) {
  ModalState& st = state_;
  fx.has_motion = true;
  fx.motion = MotionMode::rapid;
  fx.start = st.position;
  fx.end = motion_end(cx, w, axis_column, fx);
  st.position = fx.end;
  fx.has_motion = fx.end != fx.start;  // G91 G28 Z0: no intermediate move
  if (fx.has_motion) check_length_in_force(cx, w, MotionMode::rapid, axis_column);
  st.moved_in_work = st.moved_in_work || fx.has_motion;
  if (fx.has_motion) note_moved(cx);
}

/// A motion in the modal mode (G0 G1 G2 G3, a canned cycle's hole) to the block's axis words.
void Interpreter::programmed_motion(const Context& cx, const Words& w, const Codes& codes, AxisColumns columns,
                                    BlockEffect& fx) {
  ModalState& st = state_;
  const Fail& fail = cx.fail;
  const int axis_column = columns.first_or_block;
  const bool is_arc = st.motion == MotionMode::arc_cw || st.motion == MotionMode::arc_ccw;
  if (st.motion == MotionMode::none)
    fail(axis_column,
         "axis words without a motion mode (expected G0, G1, G2 or G3): the control's power-on mode "
         "(G0 or G1, a machine parameter on Fanuc) is not in the program; write G0 or G1 in the block, or "
         "post with a dialect whose [input] power_on names it (fanuc, haas: G0)");
  if (!word_axes_) check_length_in_force(cx, w, st.motion, axis_column);
  st.moved_in_work = true;
  note_moved(cx);
  if (word_axes_ && (is_arc || st.motion == MotionMode::cycle))
    fail(codes.in(g_motion) ? codes.of(g_motion).column : cx.block.column,
         fmt::format("{} on a machine with the axes {}: arcs and canned cycles need X, Y and Z (post the moves "
                     "as G0/G1 blocks)",
                     is_arc ? "an arc" : "a canned cycle", axis_letters_));
  fx.has_motion = true;
  fx.motion = st.motion;
  fx.start = st.position;
  ProgramPoint end = motion_end(cx, w, axis_column, fx);
  if (is_arc) read_arc(cx, w, codes, end, fx);
  if (st.motion != MotionMode::rapid && st.feed_mode == FeedMode::inverse_time) {
    if (!w.has('F')) fail(axis_column, "inverse-time feed (G93): every G1, G2, G3 block needs an F word");
    fx.inverse_time = true;
  }
  if (st.motion == MotionMode::cycle)
    cycle_hole(st, cx.line_number, w.has('Z') ? w.col('Z') : columns.first_axis, fail, end, fx);
  fx.end = end;
  st.position = end;
  if (st.motion == MotionMode::cycle)
    st.position[2] = st.retract_to_r ? *st.cycle.r_z : std::max(st.cycle.initial_z, *st.cycle.r_z);
}

// the end of the motion from the axis words (absolute or incremental), with the notices of axes
// not programmed before the first motion
ProgramPoint Interpreter::motion_end(const Context& cx, const Words& w, int axis_column, BlockEffect& fx) {
  ModalState& st = state_;
  const double length_scale = st.inch ? kMmPerInch : 1.0;
  ProgramPoint end = st.position;
  const std::array<double, 6>& shift = frames_.shift();
  if (st.rtcp != Rtcp::off && (shift[3] != 0.0 || shift[4] != 0.0 || shift[5] != 0.0))
    cx.fail(axis_column, fmt::format("{} turns the rotary axes against {} (a rotary value in the offsets), and the "
                                     "program moves the tool tip (RTCP): not supported; post the operations of each "
                                     "set-up apart",
                                     st.work_offset, frames_.base()));
  std::string assumed, incremental;  // axes not programmed yet; axes moved incrementally from an unknown start
  const auto add = [](std::string& list, char L) { list += list.empty() ? std::string(1, L) : std::string(", ") + L; };
  for (std::size_t i = 0; i < 6; ++i) {
    const char L = slots_[i];
    if (!L) continue;
    const bool used = axis_letters_.find(L) != std::string::npos;
    if (w.has(L)) {
      fx.programmed[i] = true;
      const double v = slot_angle_[i] ? deg_to_rad(w.get(L)) : w.get(L) * length_scale;
      end[i] = st.incremental ? st.position[i] + v : v + frames_.shift()[i];
      if (!(std::abs(end[i]) <= kMaxCoordinate))
        cx.fail(w.col(L), fmt::format("{} is out of range (expected a coordinate within +-1e9)", L));
    }
    if (!used || st.known[i]) continue;
    if (!w.has(L)) {
      fx.assumed[i] = true;
      add(assumed, L);
    } else {
      if (st.incremental) add(incremental, L);
      st.known[i] = true;
    }
  }
  if (!assumed.empty())
    notice_once("unknown-axes", cx.line_number, axis_column,
                fmt::format("{} not programmed before the first motion: each is taken from its first programmed "
                            "value (the program starts where it first says), or as 0 where a feed motion or the "
                            "end comes first",
                            assumed));
  if (!incremental.empty())
    notice_once("incremental-unknown", cx.line_number, axis_column,
                fmt::format("{} moved incrementally (G91) before any absolute position: taken from 0", incremental));
  return end;
}

// G2/G3: the arc from R or from its centre (I J K, incremental unless G90.1), P turns
void Interpreter::read_arc(const Context& cx, const Words& w, const Codes& codes, const ProgramPoint& end,
                           BlockEffect& fx) {
  const ModalState& st = state_;
  const Fail& fail = cx.fail;
  const double length_scale = st.inch ? kMmPerInch : 1.0;
  const PlaneAxes ax = axes_of(st.plane);
  const char offset_letter[3] = {'I', 'J', 'K'};
  const char normal_letter = offset_letter[ax.normal];
  if (w.has(normal_letter))
    fail(w.col(normal_letter), fmt::format("{} is not used by an arc in the {} plane", normal_letter,
                                           st.plane == Plane::xy   ? "G17"
                                           : st.plane == Plane::zx ? "G18"
                                                                   : "G19"));
  int turns = 1;
  if (w.has('P')) {
    const double p = w.get('P');
    if (p < 1.0 || p != std::floor(p) || p > kMaxArcTurns)
      fail(w.col('P'), "expected a number of turns P (an integer >= 1)");
    turns = static_cast<int>(p);
  }
  const bool clockwise = st.motion == MotionMode::arc_cw;
  const int column = codes.in(g_motion) ? codes.of(g_motion).column : cx.block.column;
  ArcOutcome outcome;
  if (w.has('R')) {
    if (w.has(offset_letter[ax.a1]) || w.has(offset_letter[ax.a2]))
      fail(w.col('R'), "an arc takes either R or I, J, K, not both");
    const double r = w.get('R') * length_scale;
    if (!(std::abs(r) <= kMaxCoordinate)) fail(w.col('R'), "R is out of range (expected a radius within 1e9 mm)");
    outcome = arc_from_radius(fx.start, end, st.plane, clockwise, r, turns);
  } else {
    const char l1 = offset_letter[ax.a1], l2 = offset_letter[ax.a2];
    if (!w.has(l1) && !w.has(l2)) {
      fail(column, fmt::format("an arc needs {} and {} (its centre) or R{}", l1, l2, not_modal_hint()));
    }
    const double o1 = w.has(l1) ? w.get(l1) * length_scale : 0.0;
    const double o2 = w.has(l2) ? w.get(l2) * length_scale : 0.0;
    if (!(std::abs(o1) <= kMaxCoordinate && std::abs(o2) <= kMaxCoordinate))
      fail(w.col(std::abs(o1) <= kMaxCoordinate ? l2 : l1), "arc centre out of range (expected within +-1e9 mm)");
    // G90.1: the centre is a point of the offset's frame (shifted into the base frame like the end)
    const bool absolute = st.arc_centre == ArcCentre::absolute;
    const std::array<double, 2> centre = arc_centre_of(
        st.arc_centre, fx.start, ax, o1 + (absolute ? frames_.shift()[static_cast<std::size_t>(ax.a1)] : 0.0),
        o2 + (absolute ? frames_.shift()[static_cast<std::size_t>(ax.a2)] : 0.0));
    outcome = arc_from_centre(fx.start, end, st.plane, clockwise, centre[0], centre[1], turns);
    if (!outcome.arc) {
      const ArcGiven given{fx.start, end, st.plane, clockwise, o1, o2, turns};
      fail(column, outcome.error + other_readings_advice(given, st.arc_centre, st.arc_centre_line,
                                                         fmt::format("{} and {}", l1, l2)));
    }
  }
  if (!outcome.arc) fail(column, outcome.error);
  fx.arc = outcome.arc;
  last_arc_line_ = cx.line_number;
  last_arc_words_ = w.has('R') ? "R" : fmt::format("{} and {}", offset_letter[ax.a1], offset_letter[ax.a2]);
}

// NX posts for some controls leave the centre words out where they equal the last arc's: they are not modal
std::string Interpreter::not_modal_hint() const {
  if (!last_arc_line_) return {};
  return fmt::format(
      "; they are not modal: the {} of the arc at line {} {} not carried over (write the centre or R on every arc)",
      last_arc_words_, last_arc_line_, last_arc_words_ == "R" ? "is" : "are");
}

// M2/M30 end the program; M0/M1 stop it (after the block's motion: RS274NGC order); M60 (a pallet
// change with a stop) is refused: dropped, the rest of the program would cut on the wrong pallet
void Interpreter::apply_stop(const Context& cx, const Codes& codes, BlockEffect& fx) {
  const Code& m_stop = codes.m_stop;
  if (m_stop.code10 == 2 || m_stop.code10 == 30) {
    fx.program_end = true;
    state_.ended = true;
  } else if (m_stop.code10 == 0 || m_stop.code10 == 1) {
    fx.after_motion.push_back(cl::Stop{cx.at(m_stop.column), m_stop.code10 == 1, {}});
  } else if (m_stop.code10 >= 0) {
    cx.fail(m_stop.column, fmt::format("M{} (pallet change and program stop) is not supported: without it the rest "
                                       "of the program would cut on the wrong pallet; post each pallet's part apart",
                                       m_stop.code10));
  }
}

// M98 P<program> L<times>, M97 P<block> L<times>, M99: followed by the reader after the block
void Interpreter::apply_call(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx) {
  const Code c = codes.m_call;
  if (c.code10 < 0) return;
  if (fx.program_end) cx.fail(c.column, fmt::format("M{} beside M2/M30", c.code10));
  SubprogramCall call;
  call.m = c.code10;
  call.column = c.column;
  if (c.code10 == 99) {  // P: the block of the calling program to return to (0: the one after the call)
    if (w.has('P')) call.p = w.get('P');
    if (w.has('P') && !(call.p >= 1.0 && call.p <= 99999.0 && call.p == std::floor(call.p)))
      cx.fail(w.col('P'), "M99 P: expected the block number N1 .. N99999 to return to");
    fx.call = call;
    return;
  }
  if (!w.has('P'))
    cx.fail(c.column, fmt::format("M{} needs P (the {} it calls)", c.code10, c.code10 == 98 ? "program" : "block"));
  call.p = w.get('P');
  if (c.code10 == 97 && !(call.p >= 1.0 && call.p <= 99999.0 && call.p == std::floor(call.p)))
    cx.fail(w.col('P'), "M97 P: expected a block number N1 .. N99999");
  if (w.has('L')) {
    const double l = w.get('L');
    if (!(l >= 1.0 && l <= 9999.0 && l == std::floor(l))) cx.fail(w.col('L'), "expected a repeat count L1 .. L9999");
    call.times = static_cast<int>(l);
  }
  fx.call = call;
}

}  // namespace ncpost::gcode
