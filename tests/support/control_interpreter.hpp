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
// Words: G0 G1 (straight moves only), G90 G91, G54-G59, G59.1-G59.3, G54.1 P<n>, G10 L2 P<n>
// (values), G10 L20 P<n> (Fanuc/Haas: G54.1 P<n>'s values; LinuxCNC: so that the current position
// reads the words), G10 L1/L10-L13 (tool offsets: no effect on the tip, which G43 puts at the words), G52 (a local
// shift: the words) and G92 (the local shift that makes the current position read the words), both added in every
// offset, G20 (X Y Z words in inches, of the motions only), M2 M30, N, F S T M3 M5 M6 H G17 G21 G40 G43 G49 G80 G94 (no
// effect here). Parameters: #1..#5399 numbered, `#n = expr`, `X#1`, `X[expr]` with + - * / and EQ NE GT GE LT LE.
// Subprograms: Fanuc/Haas `M98 P<o> L<k>` to `O<o>` blocks (after M30 too), Haas `M97 P<n> L<k>` to block N<n>, `M99`
// returns (`M99 P<n>`: to block N<n>), Haas G154 P<n> (G54.1 P<n>); a target the program lacks from ControlSpec::files.
// LinuxCNC o-words: sub/endsub/call (with [args] into #1..#30)/return, if/elseif/else/endif, while/endwhile, do/while,
// repeat/endrepeat, break, continue.
#include <cctype>
#include <cmath>
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
};

struct ControlEnd {
  int line = 0;                    ///< 1-based line of the motion block
  std::map<char, double> machine;  ///< machine coordinates at its end (mm, deg)
  bool complete = true;            ///< every axis has been programmed (else where the machine stood before is in it)
  bool rapid = false;              ///< a G0 block: its path between the ends is the control's own
};

class ControlInterpreter {
 public:
  ControlInterpreter(const std::string& text, ControlSpec spec) : spec_(std::move(spec)) {
    std::istringstream in(text);
    for (std::string raw; std::getline(in, raw);) lines_.push_back(clean(raw));
    for (char a : spec_.axes) pos_[a] = 0.0;
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
      const int n = static_cast<int>(number(s, k, pc));
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
    if (s[0] == '#') {
      std::size_t k = 1;
      const int n = static_cast<int>(number(s, k, pc));
      if (k >= s.size() || s[k] != '=') fail(pc, "expected =");
      ++k;
      params_[n] = comparison(s, k, pc);
      return pc + 1;
    }
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
        spec_.offsets[name][a] = w.at(a);
      else
        spec_.offsets[name][a] = machine - w.at(a);
      if (active) pos_[a] = machine - spec_.offsets[name][a];  // the machine stays where it is
    }
  }

  std::size_t block(std::size_t pc, const std::map<char, double>& w, const std::vector<int>& g,
                    const std::vector<int>& m) {
    bool is_g10 = false;
    for (int c : g)
      if (c == 520 || c == 920) {
        for (char a : spec_.axes) {
          if (!w.count(a)) continue;
          const double before = local_[a];
          local_[a] = c == 520 ? w.at(a) : pos_[a] + local_[a] - w.at(a);
          pos_[a] -= local_[a] - before;  // the machine stays where it is
        }
        return pc + 1;
      }
    for (int c : g) {
      if (c == 0 || c == 10)
        motion_ = c;
      else if (c == 200 || c == 210)
        inch_ = c == 200;
      else if (c == 900)
        absolute_ = true;
      else if (c == 910)
        absolute_ = false;
      else if (c == 100)
        is_g10 = true;
      else if (const std::string n = offset_name(c, w); !n.empty()) {
        if (!ends_.empty())  // the machine stays; before any motion there is no position to carry
          for (char a : spec_.axes) pos_[a] += offset(active_, a) - offset(n, a);
        active_ = n;
      }
    }
    if (is_g10) {
      g10(w);
      return pc + 1;
    }
    bool moves = false;
    for (char a : spec_.axes)
      if (w.count(a)) {
        const double v = w.at(a) * (inch_ && (a == 'X' || a == 'Y' || a == 'Z') ? 25.4 : 1.0);
        pos_[a] = absolute_ ? v : pos_[a] + v;
        moves = true;
      }
    if (moves) {
      if (ends_.empty()) first_values_ = spec_.offsets;
      ControlEnd e{static_cast<int>(pc + 1), {}, true, motion_ == 0};
      for (char a : spec_.axes) programmed_[a] = programmed_[a] || w.count(a) > 0;
      for (char a : spec_.axes) e.complete = e.complete && programmed_[a];
      for (char a : spec_.axes) e.machine[a] = pos_[a] + offset(active_, a) + local_[a];
      ends_.push_back(e);
    }
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
  int motion_ = 0;
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
