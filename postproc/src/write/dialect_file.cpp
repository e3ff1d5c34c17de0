// SPDX-License-Identifier: Apache-2.0
// Reading a dialect file (TOML, postproc/dialects/*.toml): every key known, every value of the
// expected type and range, every placeholder known, or an InputError at file:line:column.
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/toml_input.hpp"
#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost {
namespace {

using toml_input::at;

/// One [section] of the file: typed reads that name the key, its section and what was expected.
class Section {
 public:
  Section(const std::string& file, const toml::table& root, const std::string& name) : file_(file), name_(name) {
    const toml::node* n = root.get(name);
    if (!n)
      throw InputError({file, 1, 1}, fmt::format("missing section [{}]; expected every section of fanuc.toml", name));
    t_ = n->as_table();
    if (!t_) throw InputError(at(file, n->source()), fmt::format("'{}' must be a table [{}]", name, name));
  }

  void known(const std::set<std::string>& keys) const {
    for (const auto& [key, node] : *t_)
      if (!keys.count(std::string(key.str()))) {
        std::string list;
        for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
        throw InputError(at(file_, key.source()),
                         fmt::format("unknown key '{}' in [{}] (expected one of: {})", key.str(), name_, list));
      }
  }

  const toml::node& node(const char* key) const {
    const toml::node* n = t_->get(key);
    if (!n) throw InputError(at(file_, t_->source()), fmt::format("missing key '{}' in [{}]", key, name_));
    return *n;
  }
  bool has(const char* key) const { return t_->contains(key); }

  bool boolean(const char* key) const {
    const toml::node& n = node(key);
    if (auto v = n.value_exact<bool>()) return *v;
    throw wrong(n, key, "true or false");
  }

  std::string text(const char* key) const {
    const toml::node& n = node(key);
    if (auto v = n.value_exact<std::string>()) {
      check_printable(n, key, *v);
      return *v;
    }
    throw wrong(n, key, "a string");
  }

  long long integer(const char* key, long long lo, long long hi) const {
    const toml::node& n = node(key);
    auto v = n.value_exact<int64_t>();
    if (!v) throw wrong(n, key, fmt::format("an integer from {} to {}", lo, hi));
    if (*v < lo || *v > hi)
      throw InputError(at(file_, n.source()),
                       fmt::format("{} in [{}] is {}: expected {} to {}", key, name_, *v, lo, hi));
    return *v;
  }

  /// A string in which `placeholders` are the only "{...}" allowed.
  std::string text(const char* key, const std::set<std::string>& placeholders) const {
    const std::string v = text(key);
    check_placeholders(node(key), key, v, placeholders);
    return v;
  }

  /// A list of blocks; `placeholders` are the only "{...}" allowed in them.
  std::vector<std::string> blocks(const char* key, const std::set<std::string>& placeholders) const {
    const toml::node& n = node(key);
    const toml::array* a = n.as_array();
    if (!a) throw wrong(n, key, "a list of blocks, e.g. [\"M30\"]");
    std::vector<std::string> out;
    for (const toml::node& e : *a) {
      auto v = e.value_exact<std::string>();
      if (!v) throw wrong(e, key, "a string (one block)");
      check_printable(e, key, *v);
      check_placeholders(e, key, *v, placeholders);
      out.push_back(*v);
    }
    return out;
  }

  /// `placeholder` must appear in `blocks` (read from `key`): else the word it stands for would be lost.
  void require(const char* key, const std::vector<std::string>& blocks, const std::string& placeholder,
               const std::string& why) const {
    for (const auto& b : blocks)
      if (b.find(placeholder) != std::string::npos) return;
    throw InputError(at(file_, node(key).source()),
                     fmt::format("{} in [{}] names no {}: {}", key, name_, placeholder, why));
  }

  InputError wrong(const toml::node& n, const char* key, const std::string& expected) const {
    return InputError(at(file_, n.source()), fmt::format("{} in [{}]: expected {}", key, name_, expected));
  }

 private:
  void check_placeholders(const toml::node& n, const char* key, const std::string& v,
                          const std::set<std::string>& placeholders) const {
    for (std::size_t open = v.find('{'); open != std::string::npos; open = v.find('{', open + 1)) {
      const std::size_t close = v.find('}', open);
      const std::string p = close == std::string::npos ? v.substr(open) : v.substr(open, close - open + 1);
      if (!placeholders.count(p)) {
        std::string list;
        for (const auto& k : placeholders) list += (list.empty() ? "" : ", ") + k;
        throw InputError(at(file_, n.source()), fmt::format("unknown placeholder '{}' in {} of [{}] (expected {})", p,
                                                            key, name_, list.empty() ? "none" : list));
      }
    }
  }

  /// Text written into the program: printable ASCII, one line (a newline would be a block of its own).
  void check_printable(const toml::node& n, const char* key, const std::string& v) const {
    for (const char c : v)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
        throw InputError(
            at(file_, n.source()),
            fmt::format("{} in [{}]: only printable ASCII on one line may be written into a program", key, name_));
  }

  const std::string& file_;
  std::string name_;
  const toml::table* t_ = nullptr;
};

/// A word written into a block: not empty.
std::string word(const Section& s, const char* key) {
  std::string v = s.text(key, {});
  if (v.empty()) throw s.wrong(s.node(key), key, "a word (not empty)");
  return v;
}

void read_blocks(const Section& s, Dialect& d) {
  s.known({"line_numbers", "number_format", "number_start", "number_step", "number_comments", "linear_decimals",
           "angle_decimals", "plus_sign"});
  d.line_numbers = s.boolean("line_numbers");
  d.numbers.format = s.text("number_format", {"{n}"});
  if (d.numbers.format.find("{n}") == std::string::npos)
    throw s.wrong(s.node("number_format"), "number_format", "the number's place \"{n}\", e.g. \"N{n} \"");
  d.numbers.start = static_cast<long>(s.integer("number_start", 0, 99999));
  d.numbers.step = static_cast<long>(s.integer("number_step", 1, 1000));
  d.numbers.comments = s.boolean("number_comments");
  d.linear_decimals = static_cast<int>(s.integer("linear_decimals", 0, 6));
  d.angle_decimals = static_cast<int>(s.integer("angle_decimals", 0, 6));
  d.motion.plus_sign = s.boolean("plus_sign");
}

void read_motion(const Section& s, Dialect& d) {
  s.known({"rapid", "linear", "modal", "rapid_feed", "feed_letter", "feed_decimals", "feed_modal", "per_minute",
           "inverse_time", "inverse_time_decimals"});
  MotionWords& m = d.motion;
  m.rapid = word(s, "rapid");
  m.linear = word(s, "linear");
  m.modal = s.boolean("modal");
  if (m.modal && m.rapid == m.linear)
    throw s.wrong(s.node("modal"), "modal",
                  "false when rapid and linear are the same word (a rapid would not be "
                  "told from a feed move)");
  m.rapid_feed = s.text("rapid_feed", {});
  if (m.rapid == m.linear && m.rapid_feed.empty())
    throw s.wrong(s.node("rapid_feed"), "rapid_feed", "a word (rapid and linear are the same word)");
  m.feed_letter = word(s, "feed_letter");
  m.feed_decimals = static_cast<int>(s.integer("feed_decimals", 0, 4));
  m.feed_modal = s.boolean("feed_modal");
  m.per_minute = s.text("per_minute", {});
  m.inverse_time = s.text("inverse_time", {});
  m.inverse_time_decimals = static_cast<int>(s.integer("inverse_time_decimals", 1, 6));
}

void read_arcs(const Section& s, Dialect& d) {
  s.known({"native", "clockwise", "counter_clockwise", "planes", "centre_letters"});
  if (!s.boolean("native")) return;
  ArcWords a;
  a.clockwise = word(s, "clockwise");
  a.counter_clockwise = word(s, "counter_clockwise");
  const std::vector<std::string> planes = s.blocks("planes", {});
  if (planes.size() != 3)
    throw s.wrong(s.node("planes"), "planes", "three words: XY, ZX, YZ, e.g. [\"G17\", \"G18\", \"G19\"]");
  for (std::size_t i = 0; i < 3; ++i) a.planes[i] = planes[i];
  a.centre_letters = s.text("centre_letters", {});
  if (a.centre_letters.size() != 3)
    throw s.wrong(s.node("centre_letters"), "centre_letters", "three letters (along X, Y, Z), e.g. \"IJK\"");
  d.arcs = a;
}

void read_spindle(const Section& s, Dialect& d, bool call_takes_speed) {
  s.known({"start", "after_call", "stop", "clockwise", "counter_clockwise"});
  SpindleWords& w = d.spindle;
  w.start = s.blocks("start", {"{rpm}", "{turn}"});
  s.require("start", w.start, "{rpm}", "the speed would not be written");
  s.require("start", w.start, "{turn}", "the direction would not be written");
  if (call_takes_speed) {
    w.after_call = s.blocks("after_call", {"{rpm}", "{turn}"});
    s.require("after_call", w.after_call, "{turn}", "the direction would not be written");
  } else if (s.has("after_call")) {
    throw s.wrong(s.node("after_call"), "after_call", "no such key: [tool] call names no {rpm}");
  }
  w.stop = s.blocks("stop", {});
  w.clockwise = word(s, "clockwise");
  w.counter_clockwise = word(s, "counter_clockwise");
}

void read_coolant(const Section& s, Dialect& d) {
  s.known({"flood", "mist", "off"});
  d.coolant.flood = s.blocks("flood", {});
  d.coolant.mist = s.blocks("mist", {});
  d.coolant.off = s.blocks("off", {});
}

void read_cycles(const Section& s, Dialect& d) {
  s.known({"native", "drill", "drill_dwell", "deep", "chip_break", "tap", "tap_left", "bore", "bore_dwell", "bore_drag",
           "dwell_in_ms", "first_peck_ijk", "cancel", "return_initial", "return_r", "tap_before"});
  if (!s.boolean("native")) return;
  CycleWords w;
  w.drill = s.text("drill"), w.drill_dwell = s.text("drill_dwell"), w.deep = s.text("deep");
  w.chip_break = s.text("chip_break"), w.tap = s.text("tap"), w.tap_left = s.text("tap_left");
  w.bore = s.text("bore"), w.bore_dwell = s.text("bore_dwell"), w.bore_drag = s.text("bore_drag");
  w.dwell_in_ms = s.boolean("dwell_in_ms");
  w.first_peck_ijk = s.boolean("first_peck_ijk");
  w.cancel = word(s, "cancel");
  w.return_initial = word(s, "return_initial");
  w.return_r = word(s, "return_r");
  if (s.has("tap_before")) w.tap_before = s.blocks("tap_before", {"{rpm}"});  // optional: none
  d.cycles = w;
}

void read_compensation(const Section& s, Dialect& d) {
  s.known({"native", "left", "right", "off", "register_letter"});
  if (!s.boolean("native")) return;
  CompWords w;
  w.left = s.text("left"), w.right = s.text("right"), w.off = s.text("off");
  w.register_letter = s.text("register_letter");
  d.compensation = w;
}

void read_comments(const Section& s, Dialect& d) {
  s.known({"style", "replaced", "replacements", "max_chars", "program_name_chars"});
  const std::string style = s.text("style");
  if (style == "parentheses")
    d.comments = Dialect::Comments::parentheses;
  else if (style == "semicolon")
    d.comments = Dialect::Comments::semicolon;
  else
    throw s.wrong(s.node("style"), "style", "\"parentheses\" or \"semicolon\", got \"" + style + "\"");
  CommentRules& r = d.comment_rules;
  r.replaced = s.text("replaced");
  r.replacements = s.text("replacements");
  if (r.replacements.size() != r.replaced.size())
    throw s.wrong(s.node("replacements"), "replacements", "one character for each of replaced's");
  for (const char c : r.replacements)
    if (r.replaced.find(c) != std::string::npos)
      throw s.wrong(s.node("replacements"), "replacements", fmt::format("no character of replaced (has '{}')", c));
  // what would end the comment or the tape must be replaced
  for (const char must : std::string(d.comments == Dialect::Comments::parentheses ? ")%" : "%"))
    if (r.replaced.find(must) == std::string::npos)
      throw s.wrong(s.node("replaced"), "replaced",
                    fmt::format("'{}' among the characters (it would end the comment "
                                "or the tape)",
                                must));
  r.max_chars = static_cast<std::size_t>(s.integer("max_chars", 5, 254));
  r.max_name_chars = static_cast<std::size_t>(s.integer("program_name_chars", 1, 64));
}

/// [tilted_plane] (optional: a file without it has no tilted planes; `post --tilted-plane` says so).
void read_tilted_plane(const Section& s, Dialect& d) {
  s.known({"native", "angles", "on", "off"});
  if (!s.boolean("native")) return;
  auto w = std::make_shared<TiltedPlaneWords>();
  const std::string angles = s.text("angles");
  if (angles == "euler_zxz")
    w->angles = TiltedPlaneWords::Angles::euler_zxz;
  else if (angles == "fixed_xyz")
    w->angles = TiltedPlaneWords::Angles::fixed_xyz;
  else
    throw s.wrong(s.node("angles"), "angles", "\"euler_zxz\" or \"fixed_xyz\", got \"" + angles + "\"");
  const std::set<std::string> placeholders{"{x}", "{y}", "{z}", "{a}", "{b}", "{c}", "{dir}", "{rotary}"};
  w->on = s.blocks("on", placeholders);
  w->off = s.blocks("off", {});
  std::string all;
  for (const auto& b : w->on) all += b;
  for (const char* p : {"{x}", "{y}", "{z}", "{a}", "{b}", "{c}"})
    if (all.find(p) == std::string::npos)
      throw s.wrong(s.node("on"), "on",
                    fmt::format("blocks that give the whole plane: {} is missing (origin {{x}} "
                                "{{y}} {{z}}, angles {{a}} {{b}} {{c}})",
                                p));
  d.tilted_plane = std::move(w);
}

/// The G codes a power-on state may name: motion (G0 G1), plane, units, distance, feed mode, work
/// offset, and the cancel words of compensation, length and cycles.
bool power_on_code(const std::string& word) {
  static const std::set<std::string> kCodes{"G0",  "G1",  "G17", "G18", "G19", "G20",   "G21",   "G90",
                                            "G91", "G93", "G94", "G95", "G54", "G55",   "G56",   "G57",
                                            "G58", "G59", "G40", "G49", "G80", "G59.1", "G59.2", "G59.3"};
  return kCodes.count(word) > 0;
}

/// [input] (optional): how a G-code program of this control reads where controls differ, and the
/// modal state the control starts a program in (LinuxCNC's RS274NGC_STARTUP_CODE).
/// [input] tool_offsets = { L10 = "length", ... }: what G10 L<n> sets (cl::ToolOffsetWrite).
void read_tool_offsets(const Section& s, Dialect& d) {
  static const std::map<std::string, cl::ToolOffsetWrite> kNames{
      {"length", cl::ToolOffsetWrite::length},         {"length_wear", cl::ToolOffsetWrite::length_wear},
      {"radius", cl::ToolOffsetWrite::radius},         {"radius_wear", cl::ToolOffsetWrite::radius_wear},
      {"diameter", cl::ToolOffsetWrite::diameter},     {"diameter_wear", cl::ToolOffsetWrite::diameter_wear},
      {"tool_table", cl::ToolOffsetWrite::tool_table}, {"length_reading", cl::ToolOffsetWrite::length_reading}};
  const toml::node& n = s.node("tool_offsets");
  const toml::table* t = n.as_table();
  if (!t) throw s.wrong(n, "tool_offsets", "a table of G10 L numbers, e.g. { L10 = \"length\" }");
  for (const auto& [key, value] : *t) {
    const std::string k(key.str());
    const auto v = value.value_exact<std::string>();
    const bool l_number = k.size() >= 2 && k.size() <= 3 && k[0] == 'L' &&
                          std::all_of(k.begin() + 1, k.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!l_number || !v || !kNames.count(*v))
      throw s.wrong(value, "tool_offsets",
                    "L<n> = one of \"length\", \"length_wear\", \"radius\", \"radius_wear\", \"diameter\", "
                    "\"diameter_wear\", \"tool_table\", \"length_reading\" (got " +
                        k + ")");
    d.input_tool_offsets[std::stoi(k.substr(1))] = kNames.at(*v);
  }
}

void read_input(const Section& s, Dialect& d) {
  s.known({"control", "power_on", "tool_offsets", "integer_words"});
  if (s.has("tool_offsets")) read_tool_offsets(s, d);
  if (s.has("integer_words")) {
    const std::string rule = s.text("integer_words");
    if (rule != "units" && rule != "increments")
      throw s.wrong(s.node("integer_words"), "integer_words", "\"units\" or \"increments\", got \"" + rule + "\"");
    d.input_integer_words = rule == "units" ? cl::IntegerWords::units : cl::IntegerWords::increments;
  }
  if (s.has("control")) {
    const std::string control = s.text("control");
    if (control == "fanuc")
      d.input_control = cl::ControlFamily::fanuc;
    else if (control == "linuxcnc")
      d.input_control = cl::ControlFamily::linuxcnc;
    else
      throw s.wrong(s.node("control"), "control", "\"fanuc\" (also Haas) or \"linuxcnc\", got \"" + control + "\"");
  }
  if (!s.has("power_on")) return;
  const std::string text = s.text("power_on");
  std::string word;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != ' ') {
      word += static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
      continue;
    }
    if (!word.empty() && !power_on_code(word))
      throw s.wrong(s.node("power_on"), "power_on",
                    "G codes of the modal state separated by blanks (G0 G1, G17-G19, G20 G21, G90 G91, G93-G95, "
                    "G54-G59.3, G40 G49 G80), got \"" +
                        word + "\"");
    word.clear();
  }
  d.input_power_on = text;
}

}  // namespace

/// A program stop's blocks (`stop`, `optional_stop` of [program]): optional, `blocks` keeps its
/// default when absent; an empty list is refused (the machine would not stop where the CAM says).
void read_stop(const Section& program, const char* key, std::vector<std::string>& blocks) {
  if (!program.has(key)) return;
  blocks = program.blocks(key, {});
  if (blocks.empty())
    throw program.wrong(program.node(key), key,
                        "at least one block (a program that stops nowhere is not the CAM's program)");
}

namespace {

/// The root holds only the dialect's sections.
void check_sections(const toml::table& root, const std::string& file) {
  const std::vector<std::string> sections{"dialect",  "program",      "blocks",       "motion",  "arcs",
                                          "comments", "tool",         "spindle",      "coolant", "cycles",
                                          "dwell",    "compensation", "tilted_plane", "input"};
  for (const auto& [key, node] : root)
    if (std::find(sections.begin(), sections.end(), std::string(key.str())) == sections.end()) {
      std::string list;
      for (const auto& k : sections) list += (list.empty() ? "" : ", ") + k;
      throw InputError(at(file, key.source()), fmt::format("unknown section [{}] (expected {})", key.str(), list));
    }
}

/// [program]: framing, start and end blocks, program stops.
void read_program(const Section& program, Dialect& d) {
  program.known({"percent_framing", "start", "end", "stop", "optional_stop"});
  d.percent_framing = program.boolean("percent_framing");
  d.program_start = program.blocks("start", {"{program}", "{comments}"});
  for (const auto& b : d.program_start)
    if (b != "{comments}" && b.find("{comments}") != std::string::npos)
      throw program.wrong(program.node("start"), "start", "\"{comments}\" as an entry of its own");
  d.program_end = program.blocks("end", {"{program}"});
  read_stop(program, "stop", d.program_stop);                    // optional: M0 when absent
  read_stop(program, "optional_stop", d.program_optional_stop);  // optional: M1 when absent
}

/// [tool]: the tool call (by number, and by name), length and RTCP words. Returns whether the
/// tool call writes the spindle speed ({rpm}).
bool read_tool(const Section& tool, Dialect& d) {
  tool.known({"call", "call_by_name", "length_on", "rtcp_on", "rtcp_off", "set_offset"});
  if (tool.has("set_offset"))  // optional: the blocks that write a tool offset the input set with G10
    d.tool_set_offset = tool.blocks("set_offset", {"{register}", "{length}", "{radius}", "{diameter}"});
  d.tool_call = tool.blocks("call", {"{tool}", "{rpm}"});
  tool.require("call", d.tool_call, "{tool}", "the tool number would not be written");
  if (tool.has("call_by_name")) {  // optional: controls that call tools by name
    d.tool_call_by_name = tool.blocks("call_by_name", {"{tool_name}", "{rpm}"});
    tool.require("call_by_name", d.tool_call_by_name, "{tool_name}", "the tool's name would not be written");
  }
  d.tool_length_on = tool.blocks("length_on", {"{tool}", "{length}"});
  d.rtcp_on = tool.blocks("rtcp_on", {"{tool}", "{length}"});
  d.rtcp_off = tool.blocks("rtcp_off", {"{tool}", "{length}"});
  auto takes_speed = [](const std::vector<std::string>& blocks) {
    return std::any_of(blocks.begin(), blocks.end(),
                       [](const std::string& b) { return b.find("{rpm}") != std::string::npos; });
  };
  const bool call_takes_speed = takes_speed(d.tool_call);
  if (!d.tool_call_by_name.empty() && takes_speed(d.tool_call_by_name) != call_takes_speed)
    throw tool.wrong(tool.node("call_by_name"), "call_by_name",
                     call_takes_speed ? "{rpm}, as call names it" : "no {rpm}, as call names none");
  return call_takes_speed;
}

}  // namespace

Dialect parse_dialect(const std::string& text, const std::string& file) {
  const toml::table root = toml_input::parse_toml(text, file);
  check_sections(root, file);
  Dialect d;
  d.file = file;
  const Section head(file, root, "dialect");
  head.known({"name"});
  d.name = head.text("name");
  if (d.name.empty()) throw head.wrong(head.node("name"), "name", "a name");

  read_program(Section(file, root, "program"), d);
  read_blocks(Section(file, root, "blocks"), d);
  read_motion(Section(file, root, "motion"), d);
  read_arcs(Section(file, root, "arcs"), d);
  read_comments(Section(file, root, "comments"), d);
  const bool call_takes_speed = read_tool(Section(file, root, "tool"), d);
  read_spindle(Section(file, root, "spindle"), d, call_takes_speed);
  read_coolant(Section(file, root, "coolant"), d);

  read_cycles(Section(file, root, "cycles"), d);
  const Section dwell(file, root, "dwell");
  dwell.known({"blocks"});
  d.dwell = dwell.blocks("blocks", {"{ms}", "{s}"});
  read_compensation(Section(file, root, "compensation"), d);
  if (root.contains("tilted_plane")) read_tilted_plane(Section(file, root, "tilted_plane"), d);
  if (root.contains("input")) read_input(Section(file, root, "input"), d);
  return d;
}

}  // namespace ncpost
