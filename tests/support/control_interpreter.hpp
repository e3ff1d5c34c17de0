// SPDX-License-Identifier: Apache-2.0
#pragma once
// An interpreter of INPUT programs for the tests, as their control runs them, independent of the
// product's reader (its own line reading, expressions, call stack and offsets). Small: only what
// the tests need.
//
// It gives the machine position (machine coordinates: the words plus the active work offset's
// value) at the end of every motion block executed, with the line of the block, in execution
// order (a subprogram called three times gives its ends three times).
//
// Words: G0 G1, G2 G3 (G17/G18/G19, I J K from the start or, under G90.1, absolute; R for the radius, negative
// beyond 180 degrees; a helix moves the third axis linearly; start = end in the plane: a full circle), G90 G91,
// G54-G59, G59.1-G59.3, G54.1 P<n>, G10 L2 P<n> (values), G10 L20 P<n> (Fanuc/Haas: G54.1 P<n>'s values; LinuxCNC: so
// that the current position reads the words), G10 L1/L10-L13 (tool offsets: no effect on the tip, which G43 puts at the
// words), G52 (a local shift: the words) and G92 (the local shift that makes the current position read the words), both
// added in every offset, G20 (X Y Z words in inches, of the motions only), M2 M30, N, F S T M3 M5 M6 H G17 G21 G40 G43
// G49 G80 G94 (no effect here), G4 (a dwell: its P or X is a time), G17 G18 G19, G28 G30 (the intermediate point, then
// the named axes to ControlSpec::reference / reference2) and G53 (machine coordinates counted from
// ControlSpec::reference; a linear axis without one is unknown until programmed again, a rotary axis takes the angle),
// canned cycles G73 G81-G89 with G98/G99 (as their straight moves: over the hole, R plane, bottom, back out), G40-G42
// G43.4 G61 G64 G234 G255 (no effect on the programmed tip), G69 (rotation off: G68 is not read, so none is on). Any
// other G code is an error: never a block skipped silently. Parameters: #1..#5399 numbered, `#<name>` named, `#n =
// expr` (several on a line), `X#1`, `X[expr]` with + - * / and EQ NE GT GE LT LE; LinuxCNC's #5420-#5425 (the current
// position in the program's units). Subprograms: Fanuc/Haas `M98 P<o> L<k>` to `O<o>` blocks (after M30 too), Haas `M97
// P<n> L<k>` to block N<n>, `M99` returns (`M99 P<n>`: to block N<n>), Haas G154 P<n> (G54.1 P<n>); a target the
// program lacks from ControlSpec::files. LinuxCNC o-words: sub/endsub/call (with [args] into #1..#30)/return,
// if/elseif/else/endif, while/endwhile, do/while, repeat/endrepeat, break, continue.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ncpost::test {

struct ControlSpec {
  bool linuxcnc = false;                                  ///< G10 L20's LinuxCNC meaning
  std::map<std::string, std::map<char, double>> offsets;  ///< "G54" -> X Y Z (mm) and rotary (deg)
  std::string axes = "XYZ";                               ///< the program's axis letters
  /// Files beside the program by name ("O1234.nc", "drill.ngc"): a subprogram the program lacks is
  /// taken from the one whose name before its '.' is O<n> or <n> (M98 P<n>) or <name>.ngc.
  std::map<std::string, std::string> files;
  /// G28's point (G53's zero) per axis in the interpreter's machine coordinates (mm, deg); an axis not given has
  /// none: after G28 or G53 it is unknown until programmed again.
  std::map<char, double> reference;
  std::map<char, double> reference2;  ///< G30's point; G30 on an axis without one is an error
  /// A tool-tip reading (X Y Z the tip, RTCP input): the machine's axes for the words and back, so that G28/G30/G53
  /// move machine axes (reference and reference2 then in machine coordinates). Unset: the words are the axes.
  std::function<std::map<char, double>(const std::map<char, double>&)> tip_to_machine, machine_to_tip;
};

struct ControlEnd {
  int line = 0;                    ///< 1-based line of the motion block
  std::map<char, double> machine;  ///< machine coordinates at its end (mm, deg)
  bool complete = true;            ///< every axis has been programmed (else where the machine stood before is in it)
  bool rapid = false;              ///< a G0 block: its path between the ends is the control's own
  int motion = 0;                  ///< 0 rapid, 1 straight feed, 2 clockwise arc, 3 counter-clockwise arc
  int plane = 17;                  ///< arcs: G17, G18 or G19
  std::map<char, double> centre;   ///< arcs: the centre, machine coordinates (X Y Z; the plane's normal: the start's)
  std::string unknown;             ///< the axes not programmed yet (complete: none)
};

class ControlInterpreter {
 public:
  ControlInterpreter(const std::string& text, ControlSpec spec) : spec_(std::move(spec)) {
    std::istringstream in(text);
    for (std::string raw; std::getline(in, raw);) lines_.push_back(clean(raw));
    for (char a : spec_.axes) pos_[a] = 0.0;
    // a leader: what comes before the first '%' of a program framed by two is not read (ISO tape format)
    std::vector<std::size_t> percent;
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (!lines_[i].empty() && lines_[i][0] == '%') percent.push_back(i);
    if (percent.size() >= 2)
      for (std::size_t i = 0; i < percent.front(); ++i) lines_[i].clear();
  }

  /// A line as the interpreter reads it: comments out, blanks out, upper case.
  static std::string clean(const std::string& raw) {
    std::string s;
    int depth = 0;
    for (char c : raw) {
      if (c == ';' && depth == 0) break;
      if (c == '(')
        ++depth;
      else if (c == ')')
        --depth;
      else if (depth == 0 && c != ' ' && c != '\t' && c != '\r')
        s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return s;
  }

  /// The axes the program never programmed (after run()).
  std::string never_programmed() const {
    std::string out;
    for (char a : spec_.axes)
      if (!ever_programmed_.count(a)) out += a;
    return out;
  }

  std::vector<ControlEnd> run() {
    std::size_t pc = 0;
    long steps = 0;
    while (pc < lines_.size() && !ended_) {
      if (++steps > 1'000'000) throw std::runtime_error("test interpreter: endless program");
      pc = step(pc);
    }
    return ends_;
  }

  /// The offset in force at the first motion (the posted frame's).
  const std::string& offset_at_first_motion() const { return first_offset_; }

  /// The value of offset `name` when the first motion was executed (the posted frame's zero).
  std::map<char, double> value_at_first_motion(const std::string& name) const {
    const auto it = first_values_.find(name);
    if (it == first_values_.end())
      throw std::runtime_error("test interpreter: " + name + " had no value at the first motion");
    return it->second;
  }

 private:
  struct Frame {
    std::size_t return_pc;
    std::size_t start_pc;
    int repeats_left;
    std::map<int, double> saved;  ///< #1..#30 of the caller (o-word calls)
  };

  [[noreturn]] void fail(std::size_t pc, const std::string& what) const {
    throw std::runtime_error("test interpreter line " + std::to_string(pc + 1) + ": " + what);
  }

  // ---- expressions: [a op b ...] with precedence * / over + - over comparisons
  double number(const std::string& s, std::size_t& k, std::size_t pc) {
    if (k < s.size() && s[k] == '[') {
      ++k;
      const double v = comparison(s, k, pc);
      if (k >= s.size() || s[k] != ']') fail(pc, "expected ]");
      ++k;
      return v;
    }
    if (k < s.size() && s[k] == '#') {
      ++k;
      if (k < s.size() && s[k] == '<') {
        const std::string name = named(s, k, pc);
        if (!named_.count(name)) fail(pc, "named parameter " + name + " not set");
        return named_.at(name);
      }
      const int n = static_cast<int>(number(s, k, pc));
      if (spec_.linuxcnc && n >= 5420 && n <= 5425) return current_position(pc, "XYZABC"[n - 5420]);
      return params_[n];
    }
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) {
      const bool minus = s[k++] == '-';
      const double v = number(s, k, pc);
      return minus ? -v : v;
    }
    const std::size_t start = k;
    while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.')) ++k;
    if (k == start) fail(pc, "expected a number in '" + s + "'");
    return std::stod(s.substr(start, k - start));
  }
  /// `<name>` at k (the '<'), k past the '>'.
  std::string named(const std::string& s, std::size_t& k, std::size_t pc) const {
    const std::size_t close = s.find('>', k);
    if (close == std::string::npos) fail(pc, "expected > in '" + s + "'");
    const std::string name = s.substr(k + 1, close - k - 1);
    k = close + 1;
    return name;
  }
  /// LinuxCNC's #5420..#5425: where the tool is in the active system (G92 included), program units.
  double current_position(std::size_t pc, char axis) const {
    if (!programmed_.count(axis) || !programmed_.at(axis))
      fail(pc, std::string("the position of ") + axis + " read before it is known");
    const bool linear = axis == 'X' || axis == 'Y' || axis == 'Z';
    return pos_.at(axis) / (inch_ && linear ? 25.4 : 1.0);
  }
  double product(const std::string& s, std::size_t& k, std::size_t pc) {
    double v = number(s, k, pc);
    while (k < s.size() && (s[k] == '*' || s[k] == '/')) {
      const char op = s[k++];
      const double r = number(s, k, pc);
      v = op == '*' ? v * r : v / r;
    }
    return v;
  }
  double sum(const std::string& s, std::size_t& k, std::size_t pc) {
    double v = product(s, k, pc);
    while (k < s.size() && (s[k] == '+' || s[k] == '-')) {
      const char op = s[k++];
      const double r = product(s, k, pc);
      v = op == '+' ? v + r : v - r;
    }
    return v;
  }
  double comparison(const std::string& s, std::size_t& k, std::size_t pc) {
    const double a = sum(s, k, pc);
    for (const char* op : {"EQ", "NE", "GT", "GE", "LT", "LE"}) {
      if (s.compare(k, 2, op) != 0) continue;
      k += 2;
      const double b = sum(s, k, pc);
      const std::string o(op);
      return (o == "EQ"   ? a == b
              : o == "NE" ? a != b
              : o == "GT" ? a > b
              : o == "GE" ? a >= b
              : o == "LT" ? a < b
                          : a <= b)
                 ? 1.0
                 : 0.0;
    }
    return a;
  }

  // ---- o-words (LinuxCNC)
  /// "O<NAME>" or "O100" and the keyword after it, or nullopt.
  static std::optional<std::pair<std::string, std::string>> o_word(const std::string& s) {
    if (s.size() < 2 || s[0] != 'O') return std::nullopt;
    std::size_t k = 1;
    if (s[1] == '<')
      k = s.find('>') + 1;
    else
      while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
    if (k <= 1 || k >= s.size() || !std::isalpha(static_cast<unsigned char>(s[k]))) return std::nullopt;
    std::size_t e = k;
    while (e < s.size() && std::isalpha(static_cast<unsigned char>(s[e]))) ++e;
    return std::make_pair(s.substr(0, k), s.substr(k, e - k));
  }
  /// The next line after `from` whose o-word is `label` with one of `keywords`.
  std::size_t find_o(std::size_t from, const std::string& label, std::vector<std::string> keywords) const {
    for (std::size_t i = from + 1; i < lines_.size(); ++i) {
      const auto o = o_word(lines_[i]);
      if (o && o->first == label)
        for (const auto& k : keywords)
          if (o->second == k) return i;
    }
    fail(from, "no " + keywords.front() + " for " + label);
  }
  std::size_t find_o_back(std::size_t from, const std::string& label, const std::string& keyword) const {
    for (std::size_t i = from; i-- > 0;) {
      const auto o = o_word(lines_[i]);
      if (o && o->first == label && o->second == keyword) return i;
    }
    fail(from, "no " + keyword + " before for " + label);
  }
  bool has_do(const std::string& label) const {
    for (const auto& l : lines_) {
      const auto o = o_word(l);
      if (o && o->first == label && o->second == "DO") return true;
    }
    return false;
  }
  double condition(std::size_t pc, const std::string& s, std::size_t after) {
    std::size_t k = after;
    return number(s, k, pc);
  }

  std::size_t o_step(std::size_t pc, const std::string& label, const std::string& kw) {
    const std::string& s = lines_[pc];
    const std::size_t after = s.find(kw, label.size()) + kw.size();
    if (kw == "SUB") return find_o(pc, label, {"ENDSUB"}) + 1;  // a definition: skipped
    if (kw == "CALL") {
      std::size_t sub = std::string::npos;
      for (std::size_t i = 0; i < lines_.size(); ++i) {
        const auto o = o_word(lines_[i]);
        if (o && o->first == label && o->second == "SUB") sub = i;
      }
      if (sub == std::string::npos && label.size() > 2 && label[1] == '<' &&
          append_file(label.substr(2, label.size() - 3) + ".NGC"))
        return o_step(pc, label, kw);
      if (sub == std::string::npos) fail(pc, "no sub " + label);
      Frame f{pc + 1, sub + 1, 0, {}};
      for (int n = 1; n <= 30; ++n) f.saved[n] = params_[n];
      std::vector<double> args;
      for (std::size_t k = after; k < s.size();) args.push_back(number(s, k, pc));
      for (int n = 1; n <= 30; ++n)
        params_[n] = n <= static_cast<int>(args.size()) ? args[static_cast<std::size_t>(n - 1)] : 0.0;
      frames_.push_back(f);
      return sub + 1;
    }
    if (kw == "ENDSUB" || kw == "RETURN") {
      if (frames_.empty()) fail(pc, "return without a call");
      const Frame f = frames_.back();
      frames_.pop_back();
      for (const auto& [n, v] : f.saved) params_[n] = v;
      return f.return_pc;
    }
    if (kw == "IF" || kw == "ELSEIF") {
      if (kw == "ELSEIF") return find_o(pc, label, {"ENDIF"}) + 1;  // reached after a branch taken
      std::size_t at = pc;
      while (true) {
        const auto o = o_word(lines_[at]);
        const std::size_t cond_at = lines_[at].find(o->second, label.size()) + o->second.size();
        if (o->second == "ELSE" || condition(at, lines_[at], cond_at) != 0.0) return at + 1;
        at = find_o(at, label, {"ELSEIF", "ELSE", "ENDIF"});
        if (o_word(lines_[at])->second == "ENDIF") return at + 1;
      }
    }
    if (kw == "ELSE") return find_o(pc, label, {"ENDIF"}) + 1;
    if (kw == "ENDIF" || kw == "DO") return pc + 1;
    if (kw == "WHILE" && has_do(label)) {  // the end of a do-while
      return condition(pc, s, after) != 0.0 ? find_o_back(pc, label, "DO") + 1 : pc + 1;
    }
    if (kw == "WHILE") return condition(pc, s, after) != 0.0 ? pc + 1 : find_o(pc, label, {"ENDWHILE"}) + 1;
    if (kw == "ENDWHILE") return find_o_back(pc, label, "WHILE");
    if (kw == "REPEAT") {
      if (!repeat_left_.count(label)) repeat_left_[label] = static_cast<int>(condition(pc, s, after));
      if (repeat_left_[label]-- > 0) return pc + 1;
      repeat_left_.erase(label);
      return find_o(pc, label, {"ENDREPEAT"}) + 1;
    }
    if (kw == "ENDREPEAT") return find_o_back(pc, label, "REPEAT");
    if (kw == "BREAK") {
      repeat_left_.erase(label);
      return find_o(pc, label, {"ENDWHILE", "ENDREPEAT", "WHILE"}) + 1;
    }
    if (kw == "CONTINUE") {
      const std::size_t end = find_o(pc, label, {"ENDWHILE", "ENDREPEAT", "WHILE"});
      return o_word(lines_[end])->second == "WHILE" ? end : end;  // the end re-evaluates the loop
    }
    fail(pc, "o-word " + kw);
  }

  // ---- Fanuc/Haas subprograms
  std::optional<std::size_t> program_line(int number) const {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      const std::string& l = lines_[i];
      if (l.size() > 1 && l[0] == 'O' && std::isdigit(static_cast<unsigned char>(l[1])) &&
          std::stoi(l.substr(1)) == number)
        return i + 1;
    }
    return std::nullopt;
  }
  /// O<number>'s first line and the repeats: Fanuc's P<kkkk><oooo> where only O<oooo> exists.
  std::pair<std::size_t, int> find_program(std::size_t pc, int number) {
    if (const auto at = program_line(number)) return {*at, 1};
    if (number > 9999)
      if (const auto at = program_line(number % 10000)) return {*at, number / 10000};
    for (const auto& [name, text] : spec_.files) {
      std::string stem = name.substr(0, name.find('.'));
      if (!stem.empty() && (stem[0] == 'O' || stem[0] == 'o')) stem.erase(0, 1);
      if (!stem.empty() && stem.find_first_not_of("0123456789") == std::string::npos && std::stoi(stem) == number &&
          append_file(name))
        return find_program(pc, number);
    }
    fail(pc, "no O" + std::to_string(number));
  }
  /// Appends the lines of the file `name` (upper case compared) once; false when none or appended.
  bool append_file(const std::string& name) {
    for (const auto& [n, text] : spec_.files) {
      std::string upper = n;
      for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (upper != name && n != name) continue;
      if (appended_.count(n)) return false;
      appended_.insert(n);
      std::istringstream in(text);
      for (std::string raw; std::getline(in, raw);) lines_.push_back(clean(raw));
      return true;
    }
    return false;
  }
  std::size_t find_block(std::size_t pc, int number) const {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      const std::string& l = lines_[i];
      if (l.size() > 1 && l[0] == 'N' && std::stoi(l.substr(1)) == number) return i;
    }
    fail(pc, "no N" + std::to_string(number));
  }

  // ---- one block
  std::size_t step(std::size_t pc) {
    const std::string& s = lines_[pc];
    if (s.empty() || s[0] == '%') return pc + 1;
    if (const auto o = o_word(s)) return o_step(pc, o->first, o->second);
    if (s[0] == 'O') return pc + 1;  // a program number (its start)
    if (s[0] == '#') {               // assignments, applied after the line is read
      std::map<int, double> numbered;
      std::map<std::string, double> names;
      for (std::size_t k = 0; k < s.size();) {
        if (s[k] != '#') fail(pc, "a block that mixes assignments and words");
        ++k;
        std::string name;
        int n = 0;
        if (k < s.size() && s[k] == '<')
          name = named(s, k, pc);
        else
          n = static_cast<int>(number(s, k, pc));
        if (k >= s.size() || s[k] != '=') fail(pc, "expected =");
        ++k;
        (name.empty() ? numbered[n] : names[name]) = comparison(s, k, pc);
      }
      for (const auto& [n, v] : numbered) params_[n] = v;
      for (const auto& [n, v] : names) named_[n] = v;
      return pc + 1;
    }
    if (s[0] == '/') fail(pc, "block skip (/): the test interpreter does not choose the switch");
    std::map<char, double> w;
    std::vector<int> g, m;
    for (std::size_t k = 0; k < s.size();) {
      const char letter = s[k++];
      const double v = number(s, k, pc);
      if (letter == 'G')
        g.push_back(static_cast<int>(std::lround(v * 10)));
      else if (letter == 'M')
        m.push_back(static_cast<int>(std::lround(v)));
      else
        w[letter] = v;
    }
    return block(pc, w, g, m);
  }

  std::string offset_name(int g10, const std::map<char, double>& w) const {
    switch (g10) {
      case 540:
        return "G54";
      case 550:
        return "G55";
      case 560:
        return "G56";
      case 570:
        return "G57";
      case 580:
        return "G58";
      case 590:
        return "G59";
      case 591:
        return "G59.1";
      case 592:
        return "G59.2";
      case 593:
        return "G59.3";
      case 541:
      case 1540:
        return "G54.1 P" + std::to_string(static_cast<int>(w.at('P')));
      default:
        return "";
    }
  }
  double offset(const std::string& name, char axis) {
    auto it = spec_.offsets[name].find(axis);
    if (it == spec_.offsets[name].end()) throw std::runtime_error("test interpreter: " + name + " has no " + axis);
    return it->second;
  }

  void g10(const std::map<char, double>& w) {
    const int l = static_cast<int>(w.at('L')), p = static_cast<int>(w.at('P'));
    if (l != 2 && l != 20) return;  // a tool offset (L1, L10 ..): the tip is where the words say
    static const char* names[] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};
    const bool fanuc_l20 = l == 20 && !spec_.linuxcnc;
    const std::string name = fanuc_l20 ? "G54.1 P" + std::to_string(p) : p == 0 ? active_ : names[p - 1];
    for (char a : spec_.axes) {
      if (!w.count(a)) continue;
      const bool active = name == active_ && !ends_.empty();  // a position to keep where the machine is
      const double machine = active || !(l == 2 || fanuc_l20) ? pos_[a] + offset(active_, a) : 0.0;
      if (l == 2 || fanuc_l20)
        spec_.offsets[name][a] = w.at(a) * unit(a);
      else
        spec_.offsets[name][a] = machine - w.at(a) * unit(a);
      if (active) pos_[a] = machine - spec_.offsets[name][a];  // the machine stays where it is
    }
  }

  /// A modal G code of no motion (true when `c`, G times 10, is one).
  bool modal(int c) {
    if (c == 0 || c == 10 || c == 20 || c == 30)
      motion_ = c / 10, cycle_ = 0;
    else if (c == 730 || (c >= 810 && c <= 890)) {
      if (cycle_ == 0) initial_z_ = pos_['Z'], motion_before_cycle_ = motion_;
      cycle_ = c, motion_ = -1;
    } else if (c == 800) {  // Fanuc keeps G0/G1 apart from the cycles; LinuxCNC needs a motion word after G80
      if (cycle_ != 0) motion_ = motion_before_cycle_;
      cycle_ = 0;
    } else if (c == 170 || c == 180 || c == 190)
      plane_ = c / 10;
    else if (c == 200 || c == 210)
      inch_ = c == 200;
    else if (c == 900 || c == 910)
      absolute_ = c == 900;
    else if (c == 901 || c == 911)
      arc_absolute_ = c == 901;
    else if (c == 980 || c == 990)
      return_r_ = c == 990;
    else  // and G50: scaling off, the state a mill starts in (with axis words it is a lathe's, which ncpost refuses)
      return c == 170 || c == 400 || c == 410 || c == 420 || c == 430 || c == 434 || c == 490 || c == 500 || c == 610 ||
             c == 640 || c == 690 || c == 930 || c == 940 || c == 2340 || c == 2550;
    return true;
  }

  double unit(char letter) const {
    return inch_ && std::string("XYZIJKR").find(letter) != std::string::npos ? 25.4 : 1.0;
  }

  /// The block's end: the machine coordinates of pos_ (and of an arc's centre, in the active system).
  void push_end(std::size_t pc, int motion, const std::map<char, double>& centre = {}) {
    if (ends_.empty()) first_values_ = spec_.offsets, first_offset_ = active_;
    ControlEnd e{static_cast<int>(pc + 1), {}, true, motion == 0};
    e.motion = motion;
    e.plane = plane_;
    for (char a : spec_.axes) {
      e.complete = e.complete && programmed_[a];
      if (!programmed_[a]) e.unknown += a;
      if (programmed_[a]) ever_programmed_.insert(a);
    }
    for (char a : spec_.axes) e.machine[a] = pos_[a] + offset(active_, a) + local_[a];
    for (const auto& [a, v] : centre) e.centre[a] = v + offset(active_, a) + local_[a];
    ends_.push_back(e);
  }

  /// The words of a motion block: a straight move, an arc or a canned cycle's hole.
  void motion(std::size_t pc, const std::map<char, double>& w) {
    bool moves = false;
    for (char a : spec_.axes) moves = moves || w.count(a);
    if (cycle_ != 0) {
      if (moves) cycle_hole(pc, w);
      return;
    }
    const bool centre_words = w.count('I') || w.count('J') || w.count('K');
    if (!moves && motion_ >= 2 && centre_words) {  // no end point: the end is the start, a full circle
      push_end(pc, motion_, arc_centre(pc, w, pos_));
      return;
    }
    if (!moves) return;
    if (motion_ < 0) fail(pc, "axis words with no motion mode");
    const std::map<char, double> start = pos_;
    for (char a : spec_.axes)
      if (w.count(a)) {
        const double v = w.at(a) * unit(a);
        pos_[a] = absolute_ ? v : pos_[a] + v;
        programmed_[a] = true;
      }
    if (motion_ <= 1) return push_end(pc, motion_);
    push_end(pc, motion_, arc_centre(pc, w, start));
  }

  /// The indices (into "XYZ") of the plane's first and second axis and of its normal.
  std::array<int, 3> plane_axes() const {
    return plane_ == 17   ? std::array<int, 3>{0, 1, 2}
           : plane_ == 18 ? std::array<int, 3>{2, 0, 1}
                          : std::array<int, 3>{1, 2, 0};
  }

  /// The centre of the arc from `start` to pos_ (program coordinates, X Y Z).
  std::map<char, double> arc_centre(std::size_t pc, const std::map<char, double>& w,
                                    const std::map<char, double>& start) {
    static const char* xyz = "XYZ";
    static const char* ijk = "IJK";
    if (w.count('P')) fail(pc, "an arc of several turns (P) is not read by the test interpreter");
    const std::array<int, 3> ax = plane_axes();
    const char u = xyz[ax[0]], v = xyz[ax[1]], n = xyz[ax[2]];
    std::map<char, double> c{{n, start.at(n)}};
    if (w.count('R')) {
      const double su = start.at(u), sv = start.at(v), du = pos_[u] - su, dv = pos_[v] - sv;
      const double chord = std::hypot(du, dv), r = w.at('R') * unit('R');
      const double h2 = r * r - chord * chord / 4.0;
      if (chord < 1e-9 || h2 < -1e-6 * std::abs(r)) fail(pc, "an R arc whose ends are not 2R apart or closer");
      const double h = std::sqrt(std::max(0.0, h2)) * (r < 0 ? -1.0 : 1.0) * (motion_ == 3 ? 1.0 : -1.0);
      c[u] = su + du / 2 - h * dv / chord;
      c[v] = sv + dv / 2 + h * du / chord;
      return c;
    }
    const char iu = ijk[ax[0]], iv = ijk[ax[1]];
    const double ou = w.count(iu) ? w.at(iu) * unit(iu) : 0.0, ov = w.count(iv) ? w.at(iv) * unit(iv) : 0.0;
    c[u] = arc_absolute_ ? ou : start.at(u) + ou;
    c[v] = arc_absolute_ ? ov : start.at(v) + ov;
    return c;
  }

  /// A canned cycle's hole: over it (rapid), to the R plane (rapid), to the bottom (feed), out to the R plane
  /// (feed, for the cycles that feed out) and back to the initial level (G98) or the R plane (G99), rapid.
  void cycle_hole(std::size_t pc, const std::map<char, double>& w) {
    if (!absolute_) fail(pc, "a canned cycle under G91 is not read by the test interpreter");
    if (w.count('R')) cycle_r_ = w.at('R') * unit('R');
    if (w.count('Z')) cycle_z_ = w.at('Z') * unit('Z');
    if (!cycle_r_ || !cycle_z_) fail(pc, "a canned cycle without its R plane or its depth");
    if (pos_['Z'] < *cycle_r_ - 1e-9) fail(pc, "a hole started below its R plane");
    const double clear = return_r_ ? *cycle_r_ : initial_z_;
    for (char a : spec_.axes)
      if (a != 'Z' && w.count(a)) pos_[a] = w.at(a) * unit(a), programmed_[a] = true;
    push_end(pc, 0);
    pos_['Z'] = *cycle_r_, programmed_['Z'] = true;
    push_end(pc, 0);
    pos_['Z'] = *cycle_z_;
    push_end(pc, 1);
    if (cycle_ == 840 || cycle_ == 740 || cycle_ == 850 || cycle_ == 890) {
      pos_['Z'] = *cycle_r_;
      push_end(pc, 1);
    }
    pos_['Z'] = clear;
    push_end(pc, 0);
  }

  /// The words of the current position (machine coordinates of the interpreter: words + offsets).
  std::map<char, double> current_words() {
    std::map<char, double> out;
    for (char a : spec_.axes) out[a] = pos_[a] + offset(active_, a) + local_[a];
    return out;
  }

  /// G28/G30 (the intermediate point, then to the reference point) and G53 (machine coordinates): they move
  /// the machine's axes (through ControlSpec::tip_to_machine where the words are the tool tip). An axis left
  /// unknown (no reference) makes every axis unknown while a rotary axis is turned (the tip then depends on it).
  void machine_motion(std::size_t pc, int code, const std::map<char, double>& w) {
    std::map<char, double> given;
    for (char a : spec_.axes)
      if (w.count(a)) given[a] = w.at(a) * unit(a);
    if (given.empty()) fail(pc, "G28/G30/G53 without axis words");
    if (code != 530) {
      for (const auto& [a, v] : given) pos_[a] = absolute_ ? v : pos_[a] + v;
      push_end(pc, 0);
    }
    const std::map<char, double>& refs = code == 300 ? spec_.reference2 : spec_.reference;
    std::map<char, double> axes = spec_.tip_to_machine ? spec_.tip_to_machine(current_words()) : current_words();
    bool unknown = false, turned = false;
    for (const auto& [a, v] : axes) turned = turned || (std::string("XYZ").find(a) == std::string::npos && v != 0.0);
    for (const auto& [a, v] : given) {
      const bool rotary = std::string("XYZ").find(a) == std::string::npos;
      if (refs.count(a))
        axes[a] = refs.at(a) + (code == 530 ? v : 0.0);
      else if (code == 530 && rotary)
        axes[a] = v;
      else if (code == 300)
        fail(pc, std::string("G30 on ") + a + " without a second reference point");
      else
        unknown = true, programmed_[a] = false;
    }
    const std::map<char, double> words = spec_.machine_to_tip ? spec_.machine_to_tip(axes) : axes;
    for (char a : spec_.axes) pos_[a] = words.at(a) - offset(active_, a) - local_[a];
    if (unknown && turned)
      for (char a : spec_.axes) programmed_[a] = false;
    push_end(pc, code == 530 ? std::max(motion_, 0) : 0);
  }

  std::size_t block(std::size_t pc, const std::map<char, double>& w, const std::vector<int>& g,
                    const std::vector<int>& m) {
    bool is_g10 = false;
    for (int c : g)
      if (c == 520 || c == 920) {
        for (char a : spec_.axes) {
          if (!w.count(a)) continue;
          const double before = local_[a];
          local_[a] = c == 520 ? w.at(a) * unit(a) : pos_[a] + local_[a] - w.at(a) * unit(a);
          pos_[a] -= local_[a] - before;  // the machine stays where it is
        }
        return pc + 1;
      }
    int machine_move = 0;  // 280, 300 or 530
    bool dwell = false;
    for (int c : g) {
      if (modal(c)) continue;
      if (c == 100)
        is_g10 = true;
      else if (c == 40)
        dwell = true;
      else if (c == 280 || c == 300 || c == 530)
        machine_move = c;
      else if (const std::string n = offset_name(c, w); !n.empty()) {
        if (!ends_.empty())  // the machine stays; before any motion there is no position to carry
          for (char a : spec_.axes) pos_[a] += offset(active_, a) - offset(n, a);
        active_ = n;
      } else {
        fail(pc, "G" + std::to_string(c / 10) + (c % 10 ? "." + std::to_string(c % 10) : "") +
                     " is not read by the test interpreter");
      }
    }
    if (is_g10) {
      g10(w);
      return pc + 1;
    }
    if (machine_move)
      machine_motion(pc, machine_move, w);
    else if (!dwell)
      motion(pc, w);
    for (int c : m) {
      if (c == 2 || c == 30) ended_ = true;
      if (c == 98 || c == 97) {
        const int target = static_cast<int>(w.at('P'));
        int times = w.count('L') ? static_cast<int>(w.at('L')) : 1;
        std::size_t start = 0;
        if (c == 98) {
          const auto [at, repeats] = find_program(pc, target);
          start = at;
          times *= repeats;
        } else {
          start = find_block(pc, target);
        }
        frames_.push_back(Frame{pc + 1, start, times - 1, {}});
        return start;
      }
      if (c == 99) {
        if (frames_.empty()) fail(pc, "M99 without a call");
        Frame& f = frames_.back();
        if (f.repeats_left-- > 0) return f.start_pc;
        const std::size_t back = f.return_pc;
        frames_.pop_back();
        return w.count('P') ? find_block(pc, static_cast<int>(w.at('P'))) : back;
      }
    }
    return pc + 1;
  }

  ControlSpec spec_;
  std::vector<std::string> lines_;
  std::map<int, double> params_;
  std::map<char, double> pos_;       ///< program coordinates in the active offset
  std::map<char, double> local_;     ///< the G52 / G92 shift
  std::map<char, bool> programmed_;  ///< the axis has had a word
  std::string active_ = "G54";
  int motion_ = 0;  ///< 0 1 2 3; -1 none (after G80)
  int plane_ = 17;
  int cycle_ = 0;  ///< a canned cycle's G code times 10, 0 none
  std::optional<double> cycle_r_, cycle_z_;
  double initial_z_ = 0.0;  ///< the Z where the cycles began (G98's return level)
  bool return_r_ = false;   ///< G99
  int motion_before_cycle_ = 0;
  bool arc_absolute_ = false;
  std::map<std::string, double> named_;
  std::string first_offset_ = "G54";
  std::set<char> ever_programmed_;
  bool absolute_ = true;
  bool inch_ = false;  ///< G20: X Y Z words in inches (converted to mm)
  bool ended_ = false;
  std::vector<Frame> frames_;
  std::map<std::string, int> repeat_left_;
  std::vector<ControlEnd> ends_;
  std::map<std::string, std::map<char, double>> first_values_;
  std::set<std::string> appended_;  ///< files of ControlSpec::files read in
};

}  // namespace ncpost::test
