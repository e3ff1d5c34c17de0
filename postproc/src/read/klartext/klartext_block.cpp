// SPDX-License-Identifier: Apache-2.0
// The Klartext block tokenizer (klartext_block.hpp).
#include "ncpost/postproc/read/klartext/klartext_block.hpp"

#include <fmt/format.h>

#include <cctype>
#include <algorithm>
#include <charconv>

#include "read/klartext/klartext_q.hpp"
#include "read/char_scan.hpp"

namespace ncpost::klartext {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Statements of two words: the first word and the ones that may follow it.
struct TwoWord {
  std::string_view first;
  std::string_view seconds[4];
};
constexpr TwoWord kTwoWords[] = {
    {"BEGIN", {"PGM"}},
    {"END", {"PGM"}},
    {"BLK", {"FORM"}},
    {"TOOL", {"CALL", "DEF"}},
    {"CYCL", {"DEF", "CALL"}},
    {"CALL", {"LBL", "PGM"}},
    {"FUNCTION", {"TCPM", "RESET", "MODE", "PARAX"}},
    {"PLANE", {"SPATIAL", "PROJECTED", "EULER", "VECTOR"}},
    {"PLANE", {"POINTS", "RELATIV", "AXIAL", "RESET"}},
};

class Cursor {
 public:
  Cursor(std::string_view line, const std::string& file, int line_number)
      : line_(line), file_(&file), line_number_(line_number) {}

  bool done() const { return at_ >= line_.size(); }
  char peek(std::size_t ahead = 0) const { return at_ + ahead < line_.size() ? line_[at_ + ahead] : '\0'; }
  int column() const { return static_cast<int>(at_) + 1; }
  void skip_blanks() {
    while (!done() && is_blank(line_[at_])) ++at_;
  }
  std::string letters() {
    std::string s;
    while (!done() && is_alpha(line_[at_])) s += upper(line_[at_++]);
    return s;
  }
  /// The letters at the cursor, without moving.
  std::string peek_letters() const {
    std::string s;
    for (std::size_t i = at_; i < line_.size() && is_alpha(line_[i]); ++i) s += upper(line_[i]);
    return s;
  }
  void advance(std::size_t n) { at_ += n; }
  std::string_view rest() const { return line_.substr(std::min(at_, line_.size())); }

  /// digits [ ('.' | ',') digits ] | '.' digits, unsigned; nullopt (cursor unmoved) when none. A
  /// comma between digits is a decimal comma (X+50,022, as older TNCs and some CAM posts write it:
  /// a comma has no other meaning inside a number, and NC words have no thousands separators).
  std::optional<double> number() {
    const std::size_t start = at_;
    std::size_t p = at_;
    while (p < line_.size() && is_digit(line_[p])) ++p;
    bool digits = p > start;
    const bool decimal_comma = digits && p + 1 < line_.size() && line_[p] == ',' && is_digit(line_[p + 1]);
    if (p < line_.size() && (line_[p] == '.' || decimal_comma)) {
      ++p;
      const std::size_t frac = p;
      while (p < line_.size() && is_digit(line_[p])) ++p;
      digits = digits || p > frac;
    }
    if (!digits) return std::nullopt;
    double v = 0.0;
    std::string text(line_.substr(start, p - start));
    std::replace(text.begin(), text.end(), ',', '.');
    if (text.front() == '.') text.insert(text.begin(), '0');
    if (text.back() == '.') text.pop_back();
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{}) fail(column(), fmt::format("'{}' is not a number", text));
    at_ = p;
    return v;
  }

  [[noreturn]] void fail(int column, const std::string& what) const {
    throw InputError({*file_, line_number_, column}, what, std::string(line_));
  }

 private:
  std::string_view line_;
  const std::string* file_;
  int line_number_;
  std::size_t at_ = 0;
};

std::string trimmed_cr(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return std::string(s);
}

/// The statement at the cursor: one or two keywords, or "M" for a block that starts with M words.
void read_statement(Cursor& c, Block& b) {
  b.column = c.column();
  if (c.peek() == '*') {
    c.advance(1);
    b.statement = "*";
    b.comment_column = b.column;
    std::string text = trimmed_cr(c.rest());
    if (text.rfind("- ", 0) == 0 || text == "-") text = trimmed_cr(text.substr(1));
    b.comment = text;
    c.advance(c.rest().size());
    return;
  }
  const std::string first = c.peek_letters();
  // a block of M words only ("21 M30"), a Q parameter assignment ("Q1 = 5")
  if (first == "M" && is_digit(c.peek(1))) {
    b.statement = "M";
    return;
  }
  std::size_t q_length = 0;
  if (q_name_at(c.rest(), q_length)) {  // Q1 = ..., QL2 = ...: the text is the assignment
    b.statement = "Q";
    return;
  }
  if (first.empty()) return;  // the word loop reports what it finds
  c.letters();
  b.statement = first;
  for (const TwoWord& t : kTwoWords) {
    if (t.first != first) continue;
    Cursor probe = c;
    probe.skip_blanks();
    const std::string second = probe.peek_letters();
    for (std::string_view s : t.seconds)
      if (!s.empty() && s == second) {
        c = probe;
        c.letters();
        b.statement += " " + second;
        return;
      }
  }
}

/// Statements whose words the tokenizer reads; the others keep their text for the message.
bool has_words(std::string_view statement) {
  for (std::string_view s : {"L",
                             "C",
                             "CC",
                             "CR",
                             "CT",
                             "CP",
                             "TOOL CALL",
                             "TOOL DEF",
                             "BLK FORM",
                             "M",
                             "STOP",
                             "FUNCTION TCPM",
                             "FUNCTION RESET",
                             "RND",
                             "CHF",
                             "LP",
                             "PLANE SPATIAL",
                             "PLANE PROJECTED",
                             "PLANE EULER",
                             "PLANE VECTOR",
                             "PLANE AXIAL",
                             "PLANE POINTS",
                             "PLANE RESET"})
    if (s == statement) return true;
  return false;
}

void read_word(Cursor& c, Block& b) {
  Word w;
  w.column = c.column();
  if (c.peek() == '"') {
    c.advance(1);
    const std::string_view rest = c.rest();
    const std::size_t close = rest.find('"');
    if (close == std::string_view::npos) c.fail(w.column, "a tool name without its closing '\"'");
    w.name = "\"";
    w.text = std::string(rest.substr(0, close));
    c.advance(close + 1);
    b.words.push_back(std::move(w));
    return;
  }
  w.name = c.letters();
  if (w.name == "P" && c.peek() >= '1' && c.peek() <= '3' &&
      (c.peek(1) == 'X' || c.peek(1) == 'Y' || c.peek(1) == 'Z')) {
    w.name += c.peek();  // P1X+0 (PLANE POINTS)
    c.advance(1);
    w.name += c.letters();
  }
  if (w.name == "DR" && c.peek() == '2' && (c.peek(1) == '+' || c.peek(1) == '-')) {  // DR2+0.1 (TOOL CALL)
    w.name = "DR2";
    c.advance(1);
  }
  // "F MAX" is FMAX, "MB MAX" keeps MAX as its value word
  if (w.name == "F" && c.peek() == ' ') {
    Cursor probe = c;
    probe.skip_blanks();
    if (probe.peek_letters() == "MAX" || probe.peek_letters() == "AUTO") {
      c = probe;
      w.name += c.letters();
      b.words.push_back(std::move(w));
      return;
    }
  }
  if (c.peek() == '+' || c.peek() == '-') {
    w.sign = c.peek();
    c.advance(1);
  }
  std::size_t q_length = 0;
  if (const auto q = q_name_at(c.rest(), q_length)) {
    c.advance(q_length);
    w.q_parameter = true;
    w.text = *q;
  } else if (auto v = c.number()) {
    w.value = w.sign == '-' ? -*v : *v;
  }
  if (w.name.empty() && !w.value && !w.q_parameter)
    c.fail(w.column, fmt::format("unexpected '{}' (expected a word such as X+10, R0, F500 or M3)", c.peek()));
  b.words.push_back(std::move(w));
}

}  // namespace

const Word* Block::find(std::string_view name) const {
  for (const Word& w : words)
    if (w.name == name) return &w;
  return nullptr;
}

Block parse_block(std::string_view line, const std::string& file, int line_number) {
  Block b;
  // a '~' at the end continues the block on the next line (also after a comment: Q200=2 ;TEXT ~)
  while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
  if (!line.empty() && line.back() == '~') {
    b.continued = true;
    line.remove_suffix(1);
  }
  // the comment: ';' outside a "..." string
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == ';' && !quoted) {
      b.comment_column = static_cast<int>(i) + 1;
      b.comment = trimmed_cr(line.substr(i + 1));
      line = line.substr(0, i);
      break;
    }
  }
  std::string_view body = line;
  while (!body.empty() && is_blank(body.back())) body.remove_suffix(1);
  Cursor c(body, file, line_number);
  c.skip_blanks();
  if (c.peek() == '/') {
    b.deleted = true;
    c.advance(1);
    c.skip_blanks();
  }
  if (is_digit(c.peek())) {
    const int at = c.column();
    const auto n = c.number();
    if (!n || *n != static_cast<double>(static_cast<long>(*n))) c.fail(at, "expected a block number (an integer)");
    b.number = static_cast<long>(*n);
    c.skip_blanks();
  }
  if (c.done()) return b;
  read_statement(c, b);
  if (b.statement == "*") return b;
  b.text = trimmed_cr(c.rest());
  if (!has_words(b.statement)) return b;  // refused by name by the reader; its words are not read
  for (c.skip_blanks(); !c.done(); c.skip_blanks()) read_word(c, b);
  return b;
}

bool looks_like_klartext(std::string_view head) {
  if (head.rfind("\xEF\xBB\xBF", 0) == 0) head.remove_prefix(3);
  std::size_t at = 0;
  while (at < head.size()) {
    std::size_t end = head.find('\n', at);
    const std::string_view line = head.substr(at, end == std::string_view::npos ? head.size() - at : end - at);
    std::size_t p = 0;
    while (p < line.size() && is_blank(line[p])) ++p;
    while (p < line.size() && is_digit(line[p])) ++p;
    while (p < line.size() && is_blank(line[p])) ++p;
    if (p < line.size() && line[p] != ';') {
      std::string words;
      for (std::size_t i = p; i < line.size() && words.size() < 24; ++i) words += upper(line[i]);
      if (words.rfind("BEGIN", 0) != 0) return false;
      std::size_t q = 5;
      if (q >= words.size() || !is_blank(words[q])) return false;
      while (q < words.size() && is_blank(words[q])) ++q;
      return words.compare(q, 3, "PGM") == 0;
    }
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return false;
}

}  // namespace ncpost::klartext
