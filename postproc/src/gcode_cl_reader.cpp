// G-code -> CL records: line source, block grammar, modal interpreter, then the nominal
// kinematics of the machine (see gcode_cl_reader.hpp).
#include "ncpost/postproc/gcode_cl_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/postproc/gcode_block.hpp"
#include "ncpost/postproc/gcode_line_source.hpp"
#include "ncpost/postproc/gcode_modal.hpp"

namespace ncpost::gcode {
namespace {

std::string axis_letters_of(const Machine& m) {
  std::string s = "XYZ";
  for (int k = 0; k < m.rotary_count(); ++k) s += m.rotary(k).letter;
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
  Interpreter interpreter;
  Block block;
  BlockEffect effect;
  std::array<int, 2> rotary_axis{};  ///< ProgramPoint index of machine rotary k

  std::vector<cl::Record> before;  ///< records of the current block before its motion
  std::size_t before_next = 0;
  std::vector<cl::Record> after;   ///< records after its motion
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
      : source(in, f), file(f), machine(m), setup(s), options(o), interpreter(f, axis_letters_of(m), o.default_inch) {
    for (int k = 0; k < machine.rotary_count() && k < 2; ++k) {
      const std::string letters = "XYZABC";
      rotary_axis[static_cast<std::size_t>(k)] = static_cast<int>(letters.find(machine.rotary(k).letter));
    }
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
      case InputKind::machine: return false;
      case InputKind::rtcp: return true;
      case InputKind::automatic: break;
    }
    return interpreter.state().rtcp != Rtcp::off;
  }

  cl::Motion motion_at(const ProgramPoint& p, cl::Location where) {
    cl::Motion m;
    m.where = where;
    m.axis_given = true;
    m.rapid = effect.motion == MotionMode::rapid;
    AxisPosition q;
    q.linear_mm = Vec3d(p[0], p[1], p[2]);
    for (int k = 0; k < machine.rotary_count(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_axis[static_cast<std::size_t>(k)])];
    if (machine.rotary_count() > 0) m.rotary_rad = Eigen::Vector2d(q.rotary_rad);
    last_rtcp = rtcp_now();
    const Rigidd table_T_tool = nominal_table_T_tool(q);
    m.point.axis = table_T_tool.R.col(2);
    m.point.tip_mm = last_rtcp ? q.linear_mm : Vec3d(table_T_tool.t - setup.workpiece_origin_mm);
    m.inverse_time = effect.inverse_time;
    m.feed = effect.motion_feed;
    return m;
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

  /// Lines before the opening '%' that are not G-code (a tape leader, NX's listing header).
  int leader_lines = -1;  ///< -1: not looked for yet

  /// Looks at the head of the input: when a '%' line follows non-blank lines that do not parse
  /// as G-code, those lines are a leader and are skipped (Fanuc ignores what precedes the first
  /// '%').
  void find_leader() {
    leader_lines = 0;
    const std::string_view head = source.peek(LineSource::kChunkBytes);
    std::size_t at = 0;
    int line = 0;
    bool content = false, bad = false;
    Block scratch;
    while (at < head.size()) {
      std::size_t end = head.find('\n', at);
      if (end == std::string_view::npos) return;  // no complete '%' line within the head
      std::string_view text = head.substr(at, end - at);
      ++line;
      if (line == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
      const auto first = text.find_first_not_of(" \t\r");
      if (first != std::string_view::npos && text[first] == '%') {
        if (content && bad) {
          leader_lines = line - 1;
          notices.push_back(fmt::format("{}:1: {} line(s) before the opening '%' are not G-code: skipped as a leader",
                                        file, leader_lines));
        }
        return;
      }
      if (first != std::string_view::npos) {
        content = true;
        try {
          parse_block(text, scratch, file, line);
        } catch (const InputError&) {
          bad = true;
        }
      }
      at = end + 1;
    }
  }

  /// Reads and interprets the next block; false at the end of the program.
  bool read_block() {
    if (leader_lines < 0) find_leader();
    std::string_view line;
    if (!source.next(line)) {
      finish_input();
      return false;
    }
    const int line_number = source.line_number();
    if (line_number <= leader_lines) return true;
    parse_block(line, block, file, line_number);
    if (block.empty()) return true;
    if (block.percent) {
      if (!seen_content && !opened_percent) {
        opened_percent = true;
        return true;
      }
      return false;  // the closing '%': the rest of the file is not part of the program
    }
    seen_content = true;
    if (block.deleted && options.block_delete) return true;
    for (const BlockComment& c : block.comments)
      before.push_back(cl::Comment{cl::Location{line_number, c.column}, std::string(trim(c.text))});
    interpreter.apply(block, line_number, line, effect);
    check_rtcp_forced(line_number);
    for (auto& n : interpreter.take_notices()) notices.push_back(std::move(n));
    const BlockEffect& fx = effect;
    if (fx.feed) before.push_back(*fx.feed);
    if (fx.tool_change) before.push_back(*fx.tool_change);
    if (fx.spindle) before.push_back(*fx.spindle);
    if (fx.coolant) before.push_back(*fx.coolant);
    for (const auto& u : fx.before_motion) before.push_back(u);
    if (fx.cycle_off) {
      cl::Cycle off;  // kind off
      off.where = {line_number, block.column};
      before.push_back(off);
    }
    if (fx.has_motion && fx.cycle) {
      // a canned-cycle hole: its cycle, then the hole at its R plane (the cycle runs along machine Z)
      const cl::Location where{line_number, block.column};
      cl::Motion m = motion_at(fx.end, where);
      ProgramPoint below = fx.end;
      below[2] -= 1.0;
      const cl::Motion d = motion_at(below, where);
      if ((m.point.tip_mm - d.point.tip_mm - m.point.axis).norm() > 1e-6)
        throw InputError({file, line_number, block.column},
                         "a canned cycle where machine Z is not the tool axis (a tilted head) is not supported",
                         std::string(line));
      before.push_back(*fx.cycle);
      before.push_back(m);
    } else if (fx.has_motion) {
      const cl::Location where{line_number, block.column};
      if (fx.arc) {
        const long n = arc_segments(*fx.arc, options.arc_chord_tolerance_mm);
        if (n > kMaxArcSegments)
          throw InputError({file, line_number, block.column},
                           fmt::format("the arc would need more than {} points at a chord tolerance of {} mm",
                                       kMaxArcSegments, options.arc_chord_tolerance_mm),
                           std::string(line));
        arc = fx.arc;
        arc_segments_total = n;
        arc_segment = 0;
        arc_where = where;
        if (fx.inverse_time && fx.motion_feed) effect.motion_feed = *fx.motion_feed * static_cast<double>(n);
      } else {
        before.push_back(motion_at(fx.end, where));
      }
    }
    for (const auto& u : fx.after_motion) after.push_back(u);
    if (fx.program_end) {
      after.push_back(cl::End{cl::Location{line_number, block.column}, true});
      return false;
    }
    return true;
  }

  void finish_input() {
    const int line = source.line_number();
    if (opened_percent && !interpreter.state().ended)
      throw InputError({file, line, 0},
                       "the program starts with '%' but ends without the closing '%' or M2/M30 (truncated file?)");
    if (!opened_percent && !interpreter.state().ended && seen_content)
      notices.push_back(fmt::format("{}:{}: the program ends without M2/M30 or '%'", file, line));
  }

  std::optional<cl::Record> next() {
    for (;;) {
      if (before_next < before.size()) return std::move(before[before_next++]);
      if (arc) {
        ++arc_segment;
        const double t = static_cast<double>(arc_segment) / static_cast<double>(arc_segments_total);
        cl::Motion m = motion_at(arc->at(t), arc_where);
        if (arc_segment >= arc_segments_total) arc.reset();
        return m;
      }
      if (after_next < after.size()) return std::move(after[after_next++]);
      before.clear();
      before_next = 0;
      after.clear();
      after_next = 0;
      if (done) return std::nullopt;
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
