// SPDX-License-Identifier: Apache-2.0
// The Spirit X3 grammar of one RS274 block (see gcode_block.hpp for the rules it implements).
// Semantic actions append straight into the caller's Block (no attribute containers), so a line
// costs no allocation once the Block's vectors have grown.
// <cfloat> first: X3's table of powers of ten for double is only compiled in when DBL_MAX_10_EXP
// is defined (otherwise every fractional number costs a call to std::pow).
#include <cfloat>
#include <boost/spirit/home/x3.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "read/char_scan.hpp"

namespace ncpost::gcode {
namespace {

namespace x3 = boost::spirit::x3;
using Iterator = const char*;

/// Real numbers as RS274 writes them: optional sign, `5`, `5.`, `.5`; no exponent (E is a word
/// letter), no NaN or Inf.
template <class T>
struct GcodeRealPolicies : x3::real_policies<T> {
  template <class It>
  static bool parse_exp(It&, const It&) {
    return false;
  }
  template <class It, class A>
  static bool parse_nan(It&, const It&, A&) {
    return false;
  }
  template <class It, class A>
  static bool parse_inf(It&, const It&, A&) {
    return false;
  }
};

/// What the actions need: the block being filled and where the line starts (for columns).
struct ParseState {
  Block& block;
  Iterator line_begin;
  std::string_view line;
  const std::string& file;
  int line_number;
  Iterator letter_end = nullptr;  ///< just after the letter of the word being parsed

  int column_of(Iterator it) const { return static_cast<int>(it - line_begin) + 1; }
  [[noreturn]] void fail(Iterator at, const std::string& what) const {
    throw InputError({file, line_number, column_of(at)}, what, std::string(line));
  }
};
struct state_tag;

template <class Ctx>
ParseState& state(const Ctx& ctx) {
  return x3::get<state_tag>(ctx).get();
}

const auto on_delete = [](auto& ctx) { state(ctx).block.deleted = true; };

// Note: in X3 actions `_where(ctx)` is the input *after* the match; a one-character letter
// therefore starts one before it.
const auto on_letter = [](auto& ctx) {
  ParseState& s = state(ctx);
  s.letter_end = x3::_where(ctx).begin();
  s.block.words.push_back(Word{upper(x3::_attr(ctx)), 0.0, s.column_of(s.letter_end) - 1, false});
};

const auto on_value = [](auto& ctx) {
  const double v = x3::_attr(ctx);
  if (!std::isfinite(v)) {
    const ParseState& s = state(ctx);
    Iterator number_begin = s.letter_end;
    while (*number_begin == ' ' || *number_begin == '\t') ++number_begin;
    s.fail(number_begin, "number out of range (expected a finite number)");
  }
  ParseState& s = state(ctx);
  s.block.words.back().value = v;
  for (Iterator it = s.letter_end; it != x3::_where(ctx).begin(); ++it)
    if (*it == '.') s.block.words.back().has_point = true;
};

/// The attribute is the comment with its delimiter ('(' or ';'), without the closing ')'.
const auto on_comment = [](auto& ctx) {
  ParseState& s = state(ctx);
  const auto range = x3::_attr(ctx);
  const Iterator b = range.begin();
  s.block.comments.push_back(
      BlockComment{std::string_view(b + 1, static_cast<std::size_t>(range.end() - b - 1)), s.column_of(b)});
};

/// Sinumerik MSG("text"): a message for the operator, kept as a comment of its text (MSG() clears
/// the message: nothing to keep).
const auto on_message = [](auto& ctx) {
  ParseState& s = state(ctx);
  const auto range = x3::_attr(ctx);
  const std::string_view all(range.begin(), static_cast<std::size_t>(range.end() - range.begin()));
  const std::size_t open = all.find('"');
  const std::size_t close = all.rfind('"');
  if (open == std::string_view::npos || close <= open + 1) return;
  s.block.comments.push_back(BlockComment{all.substr(open + 1, close - open - 1), s.column_of(range.begin())});
};

/// ':' is the ISO program number address, written for O (Fanuc: `:1234` is `O1234`; NX's Fadal
/// and Mori Seiki posts): a word O.
const auto on_colon = [](auto& ctx) {
  ParseState& s = state(ctx);
  s.letter_end = x3::_where(ctx).begin();
  s.block.words.push_back(Word{'O', 0.0, s.column_of(s.letter_end) - 1, false});
};

const auto on_program_name = [](auto& ctx) {
  const auto range = x3::_attr(ctx);
  state(ctx).block.program_name =
      std::string_view(range.begin() + 1, static_cast<std::size_t>(range.end() - range.begin() - 1));
};

template <Keyword K, int Length>
const auto on_keyword = [](auto& ctx) {
  ParseState& s = state(ctx);
  s.block.keywords.push_back(BlockKeyword{K, s.column_of(x3::_where(ctx).begin()) - Length});
};

const x3::real_parser<double, GcodeRealPolicies<double>> real_number{};
const auto letter_char = x3::char_("a-zA-Z");
const auto blank = x3::char_(" \t");

const auto number = x3::rule<struct number_tag>{"number"} = real_number[on_value];
const auto word = x3::rule<struct word_tag>{"word"} = letter_char[on_letter] > number;
const auto close_paren = x3::rule<struct close_tag>{"')' closing the comment"} = x3::lit(')');
/// '(' and the comment's text up to its closing ')' (not consumed: `close_paren` expects it),
/// parentheses inside it balanced: `(TEST (NESTED) COMMENT)` is one comment, as NX and Mastercam
/// headers write them.
struct OpenComment : x3::parser<OpenComment> {
  using attribute_type = x3::unused_type;
  static bool const has_attribute = false;
  template <class It, class Ctx, class RCtx, class Attr>
  bool parse(It& first, const It& last, const Ctx&, RCtx&, Attr&) const {
    if (first == last || *first != '(') return false;
    int depth = 0;
    It p = first;
    for (; p != last; ++p) {
      if (*p == '(') ++depth;
      if (*p == ')' && --depth == 0) break;
    }
    first = p;  // at the closing ')', or at the end of the line (then close_paren reports it)
    return true;
  }
};
const auto paren_comment = x3::rule<struct paren_tag>{"comment"} = x3::raw[OpenComment{}][on_comment] > close_paren;
const auto semicolon_comment = x3::rule<struct semi_tag>{"comment"} =
    x3::raw[x3::lit(';') >> x3::lexeme[*x3::char_]][on_comment];
const auto keyword = x3::rule<struct keyword_tag>{"keyword"} =
    &x3::char_("tT") >> (x3::lexeme[x3::no_case[x3::lit("traori")]][on_keyword<Keyword::traori, 6>] >>
                             -(x3::lit('(') >> x3::uint_ >> x3::lit(')')) |
                         x3::lexeme[x3::no_case[x3::lit("trafoof")]][on_keyword<Keyword::trafoof, 7>]);
const auto message = x3::rule<struct message_tag>{"message"} =
    x3::raw[x3::lexeme[x3::no_case[x3::lit("msg")] >> *blank >> x3::lit('(') >> *blank >>
                       -(x3::lit('"') >> *(x3::char_ - '"') >> x3::lit('"')) >> *blank >> x3::lit(')')]][on_message];
const auto program_name = x3::rule<struct name_tag>{"program name"} =
    x3::raw[x3::lexeme[x3::char_("oO") >> &(*x3::char_("0-9") >> x3::char_("a-zA-Z_-")) >>
                       +(x3::char_ - x3::char_(" \t(;"))]][on_program_name];
const auto colon_number = x3::rule<struct colon_tag>{"colon program number"} = x3::lit(':')[on_colon] > number;
const auto block_grammar = -x3::lit('/')[on_delete] >> -(program_name | colon_number) >>
                           *(paren_comment | keyword | message | word) >> -semicolon_comment;

/// Words that follow the block number of a Heidenhain conversational (plain-language) block.
constexpr std::string_view kHeidenhainWords[] = {
    "BEGIN PGM", "END PGM", "BLK FORM", "TOOL CALL", "TOOL DEF", "CYCL DEF", "CYCL CALL", "LBL ", "CALL LBL", "FN ",
    "PLANE ",    "L ",      "CC ",      "C ",        "CR ",      "CT ",      "RND ",      "CHF ", "STOP"};

/// A line that starts with a number: a Heidenhain conversational block (`0010 BEGIN PGM 100 MM`)
/// or a block number without its N.
std::string leading_number_message(const ParseState& s, Iterator at, Iterator end) {
  const Iterator binary = std::find_if(at, end, [](char b) {
    const auto byte = static_cast<unsigned char>(b);
    return (byte < 0x20 && b != '\t') || byte >= 0x7f;
  });
  if (binary != end)
    return fmt::format("unexpected byte 0x{:02X} at column {} (binary data?); expected G-code text",
                       static_cast<unsigned char>(*binary), s.column_of(binary));
  Iterator p = at;
  while (p != end && is_digit(*p)) ++p;
  const std::string number(at, p);
  while (p != end && (*p == ' ' || *p == '\t')) ++p;
  const std::string_view rest(p, static_cast<std::size_t>(end - p));
  for (const std::string_view w : kHeidenhainWords)
    if (rest.substr(0, w.size()) == w || (rest == w.substr(0, w.size() - 1) && w.back() == ' '))
      return fmt::format(
          "'{} {}...' is a Heidenhain conversational (plain-language) block, not G-code: ncpost reads "
          "ISO G-code (RS274, Fanuc, Haas, Sinumerik, LinuxCNC); post the CL data, or have the CAM "
          "post the part for an ISO control",
          number, w.back() == ' ' ? w.substr(0, w.size() - 1) : w);
  return fmt::format(
      "a block that starts with the number '{}' (expected a word: a letter and its number, such as "
      "N{} for a block number)",
      number, number);
}

/// Explains why the grammar stopped at `at` (shared by expectation failures and leftovers).
std::string explain(const ParseState& s, Iterator at, Iterator end, const char* expected) {
  if (at == end) return fmt::format("expected {}, found the end of the line", expected);
  const char c = *at;
  if (is_digit(c) && std::all_of(s.line_begin, at, [](char b) { return b == ' ' || b == '\t'; }))
    return leading_number_message(s, at, end);
  const auto byte = static_cast<unsigned char>(c);
  if (c == '#') return "parameters (#...) are not supported";
  if (c == '[') return "expressions ([...]) are not supported";
  if (c == '=') return "assignments (=) are not supported";
  if (c == '<') return "named O-words and subroutines (o<...>) are not supported";
  if (c == '\r') return "unexpected carriage return inside a line (CR-only line endings are not supported)";
  if (byte < 0x20 || byte >= 0x7f)
    return fmt::format("unexpected byte 0x{:02X} (binary data?); expected {}", byte, expected);
  if (c == ')') return "')' without an opening '('";
  if ((is_digit(c) || c == '.' || c == '-' || c == '+') && at != s.line_begin) {
    Iterator before = at;
    while (before != s.line_begin && (before[-1] == ' ' || before[-1] == '\t')) --before;
    if (before != at && before != s.line_begin && (is_digit(before[-1]) || before[-1] == '.'))
      return "blanks inside a number are not supported (expected a word letter after the number)";
    if (before != s.line_begin && (is_digit(before[-1]) || before[-1] == '.'))
      return fmt::format("malformed number: unexpected '{}'", c);
  }
  return fmt::format("expected {}, found '{}'", expected, c);
}

/// A name where a word was expected (`MCALL`, `CYCLE81(...)`, `TRANS`): what it is, when known
/// (empty otherwise).
std::string keyword_message(Iterator at, Iterator end) {
  Iterator p = at;
  std::string name;
  while (p != end && (is_alpha(*p) || is_digit(*p) || *p == '_') && name.size() < 32) name += upper(*p++);
  struct Known {
    const char* name;
    const char* what;
  };
  static constexpr Known kKnown[] = {
      {"MCALL", "a Sinumerik modal subprogram call, repeated at every following position"},
      {"CALL", "a Sinumerik subprogram call"},
      {"TRANS", "a Sinumerik programmable work offset"},
      {"ATRANS", "a Sinumerik additive work offset"},
      {"ROT", "a Sinumerik frame rotation"},
      {"AROT", "a Sinumerik additive frame rotation"},
      {"SCALE", "a Sinumerik frame scaling"},
      {"MIRROR", "a Sinumerik frame mirroring"},
      {"SUPA", "a Sinumerik suppression of all frames"},
      {"CYCLE800", "a Sinumerik swivel (tilted plane) cycle"},
      {"DIAMON", "Sinumerik lathe diameter programming"},
      {"GOTOF", "Sinumerik program flow"},
      {"GOTOB", "Sinumerik program flow"},
      {"REPEAT", "Sinumerik program flow"},
  };
  for (const Known& k : kKnown)
    if (name == k.name)
      return fmt::format("{} ({}) is not supported: post the CL data, or expand it into G-code blocks", name, k.what);
  if (name.rfind("CYCLE", 0) == 0 && name.size() > 5)
    return fmt::format(
        "{} (a Sinumerik cycle call) is not supported: post the CL data, or expand it into G-code "
        "blocks",
        name);
  return {};
}

constexpr const char* kOWordFlow =
    "O-word subroutines and control flow (sub, call, if, while, ...) are not supported; "
    "expected a program number";

bool starts_with_o_word(const Block& b) { return !b.words.empty() && b.words.front().letter == 'O'; }

/// `% 123 G71` (also `N9999 %123 G71 *` at the end) opens a Heidenhain ISO program: a program
/// name and the units after the '%' (a Sinumerik `%_N_NAME_MPF` has no units word).
bool heidenhain_iso_header(std::string_view rest) {
  const auto skip_blanks = [&] {
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  };
  skip_blanks();
  const std::size_t name = rest.find_first_of(" \t");
  if (name == 0 || name == std::string_view::npos) return false;
  rest.remove_prefix(name);
  skip_blanks();
  if (rest.size() < 3 || upper(rest[0]) != 'G' || rest[1] != '7' || (rest[2] != '0' && rest[2] != '1')) return false;
  rest.remove_prefix(3);
  skip_blanks();
  return rest.empty() || rest.front() == '*';
}

constexpr const char* kHeidenhainIso =
    "a Heidenhain ISO program ('%' with its name and G70/G71): its T calls the tool without M6, I J K are absolute "
    "centres and M91/M92 move in machine coordinates, so ncpost does not read it as RS274 G-code; post the CL data";

}  // namespace

void parse_block(std::string_view line, Block& block, const std::string& file, int line_number) {
  block.clear();
  const Iterator begin = line.data();
  const Iterator end = begin + line.size();
  Iterator first = begin;
  while (first != end && (*first == ' ' || *first == '\t')) ++first;
  if (first == end) return;
  block.column = static_cast<int>(first - begin) + 1;
  if (*first == '%') {
    if (heidenhain_iso_header(std::string_view(first + 1, static_cast<std::size_t>(end - first - 1))))
      throw InputError({file, line_number, block.column}, kHeidenhainIso, std::string(line));
    block.percent = true;
    return;
  }
  ParseState s{block, begin, line, file, line_number};
  try {
    x3::phrase_parse(first, end, x3::with<state_tag>(std::ref(s))[block_grammar], blank);
  } catch (const x3::expectation_failure<Iterator>& e) {
    const Iterator at = e.where();
    if (e.which() == "number") {
      const char letter = block.words.back().letter;
      const Iterator letter_at = s.line_begin + block.words.back().column - 1;
      if (letter != 'O' && at == letter_at + 1 && at != end && is_alpha(*at))
        if (const std::string known = keyword_message(letter_at, end); !known.empty()) s.fail(letter_at, known);
      if (at != end && (*at == '#' || *at == '[' || *at == '=' || *at == '<'))
        s.fail(at, explain(s, at, end, "a number"));
      if (starts_with_o_word(block) || letter == 'O') s.fail(s.line_begin + block.words.back().column - 1, kOWordFlow);
      if (at != end && (is_digit(*at) || *at == '.' || *at == '+' || *at == '-')) {
        // X3 gives up on a well-formed number only when it overflows
        Iterator p = at;
        if (*p == '+' || *p == '-') ++p;
        int digits = 0;
        while (p != end && is_digit(*p)) ++p, ++digits;
        if (p != end && *p == '.') ++p;
        while (p != end && is_digit(*p)) ++p, ++digits;
        s.fail(at, digits > 0 ? fmt::format("number out of range after '{}' (expected a finite number)", letter)
                              : fmt::format("malformed number after '{}'", letter));
      }
      s.fail(at, explain(s, at, end, fmt::format("a number after '{}'", letter).c_str()));
    }
    s.fail(at, explain(s, at, end, e.which().c_str()));
  }
  if (first != end) {
    if (starts_with_o_word(block)) s.fail(first, kOWordFlow);
    s.fail(first, explain(s, first, end, "a word (letter and number), a comment or the end of the line"));
  }
}

}  // namespace ncpost::gcode
