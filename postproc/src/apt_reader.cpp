// Meaning of APT statements: units, motions, feeds, tool, spindle, coolant, circles, cycles,
// comments. Unknown statements become Unsupported records with a notice; they never abort.
#include <fmt/format.h>

#include <cmath>
#include <deque>

#include "ncpost/postproc/apt_reader.hpp"
#include "ncpost/postproc/apt_cycle.hpp"

#include <cctype>

namespace ncpost::cl {
namespace {

constexpr double kMmPerInch = 25.4;

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

bool is_binary_junk(const std::string& line) {
  int bad = 0;
  for (unsigned char c : line)
    if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n') || c == 0x7f) ++bad;
  return bad > 0;
}

}  // namespace

struct AptReader::State {
  std::istream& in;
  std::string file;
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

  State(std::istream& i, std::string f, ReaderOptions o) : in(i), file(std::move(f)) {
    if (o.default_inch) scale = kMmPerInch;
  }

  [[noreturn]] void fail(Location w, const std::string& what, const std::string& text) const {
    throw InputError({file, w.line, w.column}, what, text);
  }

  /// Next logical statement: continuation lines joined, CR stripped. False at end of file.
  std::string line;       ///< read buffers, kept between statements (no allocation per line)
  std::string text;
  std::string statement;

  bool read_logical(std::string& out, Location& where) {
    out.clear();
    bool continued = false;
    while (std::getline(in, line)) {
      ++line_number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (is_binary_junk(line)) fail({line_number, 1}, "binary or control characters (expected APT CL text)", "");
      if (!continued) {
        const auto b = line.find_first_not_of(" \t");
        if (b == std::string::npos) continue;  // blank line
        where = {line_number, static_cast<int>(b) + 1};
        line.erase(0, b);
      }
      const auto comment = line.find("$$");
      const std::size_t last_dollar = line.find_last_of('$');
      const bool continues = !line.empty() && line.back() == '$' &&
                             (comment == std::string::npos || last_dollar > comment + 1);
      if (continues) {
        out.append(line, 0, line.size() - 1);
        continued = true;
        continue;
      }
      out += line;
      return true;
    }
    if (continued) return true;  // a file ending in '$': take what we have
    if (in.bad()) fail({line_number, 0}, "read error", "");
    return false;
  }

  std::vector<double> numbers;  ///< the numbers of the current motion statement

  Motion motion(const AptStatement& st, bool relative) {
    const std::vector<double>& v = numbers_into(st, numbers);
    if (v.size() != st.arguments.size())
      fail(st.where, fmt::format("{} expects numbers only", st.major), st.major + "/" + st.raw_arguments);
    Motion m;
    m.where = st.where;
    if (relative) {
      if (v.size() == 3) position += scale * Vec3d(v[0], v[1], v[2]);
      else if (v.size() == 1) position += scale * v[0] * axis;
      else fail(st.where, fmt::format("GODLTA expects 1 or 3 numbers, got {}", v.size()), "GODLTA/" + st.raw_arguments);
    } else {
      if (v.size() != 3 && v.size() != 6)
        fail(st.where, fmt::format("{} expects 3 or 6 numbers (x,y,z[,i,j,k]), got {}", st.major, v.size()),
             st.major + "/" + st.raw_arguments);
      position = scale * Vec3d(v[0], v[1], v[2]);
      if (v.size() == 6) {
        const Vec3d a(v[3], v[4], v[5]);
        if (a.norm() < 1e-9)
          fail(st.where, "tool axis (i, j, k) is zero (expected a unit vector)", st.major + "/" + st.raw_arguments);
        if (std::abs(a.norm() - 1.0) > 1e-3)
          notices.push_back(fmt::format("{}:{}: tool axis of length {:.6f} normalised", file, st.where.line, a.norm()));
        axis = a.normalized();
        m.axis_given = true;
      }
    }
    m.point.tip_mm = position;
    m.point.axis = axis;
    m.rapid = rapid_pending;
    rapid_pending = false;
    return m;
  }

  Feed feed(const AptStatement& st) {
    Feed f;
    f.where = st.where;
    const auto v = numbers_of(st);
    if (v.empty()) fail(st.where, "FEDRAT expects a feed value", "FEDRAT/" + st.raw_arguments);
    f.value = v[0];
    double unit = scale;
    if (has_word(st, "IPM")) unit = kMmPerInch;
    if (has_word(st, "MMPM")) unit = 1.0;
    if (has_word(st, "IPR")) { unit = kMmPerInch; f.per_rev = true; }
    if (has_word(st, "MMPR")) { unit = 1.0; f.per_rev = true; }
    f.value *= unit;
    if (!(f.value > 0.0)) fail(st.where, "FEDRAT: the feed must be positive", "FEDRAT/" + st.raw_arguments);
    return f;
  }

  /// Applies a statement: queues the records it produces (none for modal settings).
  void apply(const AptStatement& st, const std::string& text) {
    const std::string& w = st.major;
    const Location at = st.where;
    auto comment = [&](std::string t) { pending.push_back(Comment{at, std::move(t)}); };
    if (w == "GOTO" || w == "FROM") {
      Motion m = motion(st, false);
      m.from = (w == "FROM");
      pending.push_back(m);
    } else if (w == "GODLTA") {
      pending.push_back(motion(st, true));
    } else if (w == "RAPID") {
      rapid_pending = true;
    } else if (w == "FEDRAT") {
      pending.push_back(feed(st));
    } else if (w == "UNITS" || w == "UNIT") {
      if (has_word(st, "MM")) scale = 1.0;
      else if (has_word(st, "INCHES") || has_word(st, "INCH") || has_word(st, "IN")) scale = kMmPerInch;
      else fail(at, "UNITS expects MM or INCHES", text);
    } else if (w == "MULTAX") {
      multax = !has_word(st, "OFF");
    } else if (w == "TLAXIS") {
      const auto v = numbers_of(st);
      if (v.size() >= 3 && Vec3d(v[0], v[1], v[2]).norm() > 1e-9) axis = Vec3d(v[0], v[1], v[2]).normalized();
      else fail(at, "TLAXIS expects i, j, k of a non-zero vector", text);
    } else if (w == "SPINDL") {
      Spindle s;
      s.where = at;
      if (has_word(st, "OFF")) s.direction = Spindle::Direction::off;
      else if (has_word(st, "CCLW")) s.direction = Spindle::Direction::ccw;
      const auto v = numbers_of(st);
      if (!v.empty()) s.rpm = v[0];
      pending.push_back(s);
    } else if (w == "COOLNT") {
      Coolant c;
      c.where = at;
      c.on = !has_word(st, "OFF");
      c.mode = st.arguments.empty() || st.arguments[0].is_number ? "ON" : st.arguments[0].word;
      pending.push_back(c);
    } else if (w == "LOADTL" || (w == "LOAD" && has_word(st, "TOOL"))) {
      ToolChange t;
      t.where = at;
      const auto v = numbers_of(st);
      if (v.empty()) fail(at, "LOADTL expects a tool number", text);
      if (!(v[0] >= 0.0 && v[0] <= 1e6)) fail(at, "LOADTL: tool number out of range (expected 0 to 1000000)", text);
      t.number = static_cast<int>(v[0]);
      if (auto l = number_after(st, "LENGTH")) t.length_mm = *l * scale;
      pending.push_back(t);
    } else if (w == "CIRCLE") {
      const auto v = numbers_of(st);
      if (v.size() < 7) fail(at, fmt::format("CIRCLE expects at least 7 numbers (xc,yc,zc,i,j,k,r), got {}", v.size()), text);
      Circle c;
      c.where = at;
      c.center_mm = scale * Vec3d(v[0], v[1], v[2]);
      const Vec3d a(v[3], v[4], v[5]);
      if (a.norm() < 1e-9) fail(at, "CIRCLE axis is zero", text);
      c.axis = nx_circle_axis ? Vec3d(-a.normalized()) : Vec3d(a.normalized());
      c.radius_mm = scale * v[6];
      pending.push_back(c);
    } else if (w == "CUTCOM") {
      CutterComp c;
      c.where = at;
      c.text = st.raw_arguments;
      if (has_word(st, "LEFT")) c.side = CutterComp::Side::left;
      else if (has_word(st, "RIGHT")) c.side = CutterComp::Side::right;
      else if (!has_word(st, "OFF")) fail(at, "CUTCOM expects LEFT, RIGHT or OFF", text);
      const auto v = numbers_of(st);
      if (!v.empty() && v[0] >= 0.0 && v[0] <= 1e6) c.offset_register = static_cast<int>(v[0]);
      pending.push_back(c);
    } else if (w == "CYCLE") {
      if (auto c = read_apt_cycle(st, {file, scale, nx_circle_axis})) pending.push_back(std::move(*c));
    } else if (w == "PPRINT" || w == "INSERT" || w == "TPRINT" || w == "TOOL PATH" || w == "OPERATION NAME") {
      if (w == "TOOL PATH") nx_circle_axis = true;
      comment(st.raw_arguments.empty() ? w : (w == "PPRINT" || w == "INSERT" ? st.raw_arguments : w + ": " + st.raw_arguments));
    } else if (w.rfind("PARTNO", 0) == 0) {
      comment("PARTNO " + (st.has_slash ? st.raw_arguments : text.substr(std::min(text.size(), std::size_t(6)))));
    } else if (w == "END-OF-PATH" || w == "END" || w == "FINI") {
      pending.push_back(End{at, w == "FINI"});
    } else if (w == "MSYS" || w == "CSYS" || w == "TLDATA" || w == "CUTTER" || w == "TOOLNO" || w == "PAINT" ||
               w == "MACHIN" || w == "CLRSRF" || w == "SELCTL") {
      // Information for the post that does not change the motion: kept as a comment.
      if (w != "PAINT") comment(w + (st.has_slash ? "/" + st.raw_arguments : ""));
    } else {
      notices.push_back(fmt::format("{}:{}:{}: '{}' is not acted on; passed through as a comment", file, at.line,
                                    at.column, w));
      pending.push_back(Unsupported{at, text});
    }
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
    if (!s.read_logical(text, where)) return std::nullopt;
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
    s.apply(parse_apt_statement(statement, s.file, where), statement);
  }
  Record r = std::move(s.pending.front());
  s.pending.pop_front();
  return r;
}

std::vector<std::string> AptReader::take_notices() {
  std::vector<std::string> out;
  out.swap(state_->notices);
  return out;
}

bool looks_like_apt(const std::string& head) {
  // An APT statement starts a line with its major word (then '/', or alone as RAPID / MULTAX);
  // the words may also appear inside G-code comments, e.g. "(ncpost 0.1.0 from part.cls)".
  static const char* const kMajor[] = {"GOTO", "FROM", "TOOL PATH", "PARTNO", "MULTAX", "LOADTL", "$$",
                                       "FEDRAT", "UNITS", "UNIT", "CIRCLE", "SPINDL", "COOLNT", "RAPID",
                                       "TLAXIS", "CUTTER", "MSYS", "PPRINT"};
  std::size_t start = 0;
  while (start < head.size()) {
    std::size_t end = head.find('\n', start);
    if (end == std::string::npos) end = head.size();
    std::size_t b = head.find_first_not_of(" \t\r", start);
    if (b < end) {
      std::string line;
      for (std::size_t i = b; i < end; ++i) line += static_cast<char>(std::toupper(static_cast<unsigned char>(head[i])));
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
