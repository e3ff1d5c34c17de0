// SPDX-License-Identifier: Apache-2.0
// Reading a dialect file (TOML, postproc/dialects/*.toml): every key known, every value of the
// expected type and range, every placeholder known, or an InputError at file:line:column.
#include <fmt/format.h>
#include <toml++/toml.h>

#include <cctype>
#include <set>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/dialect.hpp"

namespace ncpost {
namespace {

SourcePosition at(const std::string& file, const toml::source_region& r) {
  return {file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

/// One [section] of the file: typed reads that name the key, its section and what was expected.
class Section {
 public:
  Section(const std::string& file, const toml::table& root, const std::string& name) : file_(file), name_(name) {
    const toml::node* n = root.get(name);
    if (!n) throw InputError({file, 1, 1}, fmt::format("missing section [{}]; expected every section of fanuc.toml", name));
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
      throw InputError(at(file_, n.source()), fmt::format("{} in [{}] is {}: expected {} to {}", key, name_, *v, lo, hi));
    return *v;
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
      for (std::size_t open = v->find('{'); open != std::string::npos; open = v->find('{', open + 1)) {
        const std::size_t close = v->find('}', open);
        const std::string p = close == std::string::npos ? v->substr(open) : v->substr(open, close - open + 1);
        if (!placeholders.count(p)) {
          std::string list;
          for (const auto& k : placeholders) list += (list.empty() ? "" : ", ") + k;
          throw InputError(at(file_, e.source()),
                           fmt::format("unknown placeholder '{}' in {} of [{}] (expected {})", p, key, name_,
                                       list.empty() ? "none" : list));
        }
      }
      out.push_back(*v);
    }
    return out;
  }

  InputError wrong(const toml::node& n, const char* key, const std::string& expected) const {
    return InputError(at(file_, n.source()), fmt::format("{} in [{}]: expected {}", key, name_, expected));
  }

 private:
  /// Text written into the program: printable ASCII, one line (a newline would be a block of its own).
  void check_printable(const toml::node& n, const char* key, const std::string& v) const {
    for (const char c : v)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
        throw InputError(at(file_, n.source()),
                         fmt::format("{} in [{}]: only printable ASCII on one line may be written into a program", key,
                                     name_));
  }

  const std::string& file_;
  std::string name_;
  const toml::table* t_ = nullptr;
};

void read_cycles(const Section& s, Dialect& d) {
  s.known({"native", "drill", "drill_dwell", "deep", "chip_break", "tap", "tap_left", "bore", "bore_dwell", "bore_drag",
           "dwell_in_ms", "first_peck_ijk"});
  if (!s.boolean("native")) return;
  CycleWords w;
  w.drill = s.text("drill"), w.drill_dwell = s.text("drill_dwell"), w.deep = s.text("deep");
  w.chip_break = s.text("chip_break"), w.tap = s.text("tap"), w.tap_left = s.text("tap_left");
  w.bore = s.text("bore"), w.bore_dwell = s.text("bore_dwell"), w.bore_drag = s.text("bore_drag");
  w.dwell_in_ms = s.boolean("dwell_in_ms");
  w.first_peck_ijk = s.boolean("first_peck_ijk");
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
  if (style == "parentheses") d.comments = Dialect::Comments::parentheses;
  else if (style == "semicolon") d.comments = Dialect::Comments::semicolon;
  else throw s.wrong(s.node("style"), "style", "\"parentheses\" or \"semicolon\", got \"" + style + "\"");
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
      throw s.wrong(s.node("replaced"), "replaced", fmt::format("'{}' among the characters (it would end the comment "
                                                                "or the tape)", must));
  r.max_chars = static_cast<std::size_t>(s.integer("max_chars", 5, 254));
  r.max_name_chars = static_cast<std::size_t>(s.integer("program_name_chars", 1, 64));
}

/// [tilted_plane] (optional: a file without it has no tilted planes; `post --tilted-plane` says so).
void read_tilted_plane(const Section& s, Dialect& d) {
  s.known({"native", "angles", "on", "off"});
  if (!s.boolean("native")) return;
  auto w = std::make_shared<TiltedPlaneWords>();
  const std::string angles = s.text("angles");
  if (angles == "euler_zxz") w->angles = TiltedPlaneWords::Angles::euler_zxz;
  else if (angles == "fixed_xyz") w->angles = TiltedPlaneWords::Angles::fixed_xyz;
  else throw s.wrong(s.node("angles"), "angles", "\"euler_zxz\" or \"fixed_xyz\", got \"" + angles + "\"");
  const std::set<std::string> placeholders{"{x}", "{y}", "{z}", "{a}", "{b}", "{c}", "{dir}", "{rotary}"};
  w->on = s.blocks("on", placeholders);
  w->off = s.blocks("off", {});
  std::string all;
  for (const auto& b : w->on) all += b;
  for (const char* p : {"{x}", "{y}", "{z}", "{a}", "{b}", "{c}"})
    if (all.find(p) == std::string::npos)
      throw s.wrong(s.node("on"), "on", fmt::format("blocks that give the whole plane: {} is missing (origin {{x}} "
                                                    "{{y}} {{z}}, angles {{a}} {{b}} {{c}})", p));
  d.tilted_plane = std::move(w);
}

}  // namespace

Dialect parse_dialect(const std::string& text, const std::string& file) {
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(at(file, e.source()), std::string(e.description()));
  }
  const std::set<std::string> sections{"dialect", "program", "blocks", "comments", "tool", "cycles", "dwell", "compensation",
                                       "tilted_plane"};
  for (const auto& [key, node] : root)
    if (!sections.count(std::string(key.str())))
      throw InputError(at(file, key.source()),
                       fmt::format("unknown section [{}] (expected dialect, program, blocks, comments, tool, cycles, "
                                   "dwell, compensation, tilted_plane)", key.str()));
  Dialect d;
  d.file = file;
  const Section head(file, root, "dialect");
  head.known({"name"});
  d.name = head.text("name");
  if (d.name.empty()) throw head.wrong(head.node("name"), "name", "a name");

  const Section program(file, root, "program");
  program.known({"percent_framing", "start", "end"});
  d.percent_framing = program.boolean("percent_framing");
  d.program_start = program.blocks("start", {"{program}", "{comments}"});
  for (const auto& b : d.program_start)
    if (b != "{comments}" && b.find("{comments}") != std::string::npos)
      throw program.wrong(program.node("start"), "start", "\"{comments}\" as an entry of its own");
  d.program_end = program.blocks("end", {"{program}"});

  const Section blocks(file, root, "blocks");
  blocks.known({"line_numbers", "klartext", "linear_decimals", "angle_decimals"});
  d.line_numbers = blocks.boolean("line_numbers");
  d.klartext = blocks.boolean("klartext");
  d.linear_decimals = static_cast<int>(blocks.integer("linear_decimals", 0, 6));
  d.angle_decimals = static_cast<int>(blocks.integer("angle_decimals", 0, 6));

  read_comments(Section(file, root, "comments"), d);

  const Section tool(file, root, "tool");
  tool.known({"call", "length_on", "rtcp_on", "rtcp_off"});
  d.tool_call = tool.blocks("call", {"{tool}"});
  d.tool_length_on = tool.blocks("length_on", {"{tool}"});
  d.rtcp_on = tool.blocks("rtcp_on", {"{tool}"});
  d.rtcp_off = tool.blocks("rtcp_off", {"{tool}"});

  read_cycles(Section(file, root, "cycles"), d);
  const Section dwell(file, root, "dwell");
  dwell.known({"blocks"});
  d.dwell = dwell.blocks("blocks", {"{ms}", "{s}"});
  read_compensation(Section(file, root, "compensation"), d);
  if (root.contains("tilted_plane")) read_tilted_plane(Section(file, root, "tilted_plane"), d);
  return d;
}

}  // namespace ncpost
