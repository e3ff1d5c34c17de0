// SPDX-License-Identifier: Apache-2.0
// The Spirit X3 grammar of one APT statement:
//   statement := major [ '/' arguments ]
//   arguments := argument % ','          (a trailing empty argument is dropped)
//   argument  := number | word           (number: the whole trimmed field is a real number;
//                                          word: a name, which may start with a digit: 1STPECK)
// The statements that carry free text (PPRINT, INSERT, PARTNO, TPRINT, OPERATION NAME, TOOL PATH)
// keep their text whole: it is never read as numbers.
// <cfloat> first: X3's table of powers of ten for double is only compiled in when DBL_MAX_10_EXP
// is defined (otherwise every fractional number costs a call to std::pow).
#include <cfloat>
// clang-format off
#include <boost/spirit/home/x3.hpp>
// clang-format on
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "ncpost/postproc/read/line_source.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"

namespace ncpost::cl {
namespace {

namespace x3 = boost::spirit::x3;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Grammar pieces: the major word (up to '/'); fields are split at commas and read by x3::double_.
const auto major_word = x3::rule<struct major_tag, std::string>{"major word"} = x3::raw[+(x3::char_ - '/')];

/// A field that starts with a digit but is not a number: a name (1STPECK, 10_SVERL_63_N2) when it
/// has a character no number has; otherwise a malformed number (2.5.3, 1.5E).
bool is_digit_first_word(std::string_view t) {
  if (t.empty() || !std::isdigit(static_cast<unsigned char>(t[0]))) return false;
  for (char c : t)
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != 'e' && c != 'E' && c != '+' && c != '-')
      return true;
  return false;
}

bool carries_free_text(const std::string& major) {
  return major == "PPRINT" || major == "INSERT" || major == "TPRINT" || major == "OPERATION NAME" ||
         major == "TOOL PATH" || major.rfind("PARTNO", 0) == 0;
}

/// The major word in upper case, runs of blanks inside folded ("TOOL  PATH" -> "TOOL PATH").
std::string folded_major(const std::string& major) {
  std::string folded;
  for (char c : upper(trim(major))) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!folded.empty() && folded.back() != ' ') folded += ' ';
    } else {
      folded += c;
    }
  }
  return folded;
}

/// One trimmed field `t` (not empty) as a number or a word; InputError at `a.column` otherwise.
void read_field(std::string_view t, const std::string& text, const std::string& file, int line,
                AptStatement::Argument& a) {
  double value = 0.0;
  const char* nb = t.data();
  const char* ne = t.data() + t.size();
  const bool starts_numeric =
      std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.' || t[0] == '-' || t[0] == '+';
  if (starts_numeric && x3::parse(nb, ne, x3::double_, value) && nb == ne) {
    if (!std::isfinite(value))
      throw InputError({file, line, a.column}, fmt::format("'{}' is not a finite number", echo_of(t, 40)),
                       echo_for(text, a.column));
    a.is_number = true;
    a.number = value;
  } else if (is_digit_first_word(t)) {
    a.word = upper(std::string(t));
  } else if (starts_numeric) {
    throw InputError({file, line, a.column}, fmt::format("malformed number '{}'", echo_of(t, 40)),
                     echo_for(text, a.column));
  } else {
    a.word = upper(std::string(t));
    if (a.word == "NAN" || a.word == "INF" || a.word == "INFINITY" || a.word == "-NAN")
      throw InputError({file, line, a.column}, fmt::format("'{}' is not a finite number", echo_of(t, 40)),
                       echo_for(text, a.column));
  }
}

}  // namespace

AptStatement parse_apt_statement(const std::string& text, const std::string& file, Location where) {
  AptStatement st;
  st.where = where;
  auto first = text.begin();
  const auto last = text.end();
  std::string major;
  if (!x3::parse(first, last, major_word, major))
    throw InputError({file, where.line, where.column}, "expected a major word before '/'",
                     echo_for(text, where.column));
  st.major = folded_major(major);
  if (first == last) return st;
  st.has_slash = true;
  ++first;  // '/'
  {
    const std::string_view rest(text.data() + (first - text.begin()), static_cast<std::size_t>(last - first));
    const auto b = rest.find_first_not_of(" \t\r\n");
    if (b != std::string_view::npos) st.raw_arguments.assign(rest.substr(b, rest.find_last_not_of(" \t\r\n") - b + 1));
  }
  if (st.raw_arguments.empty() || carries_free_text(st.major)) return st;  // "RAPID/", or text
  const int base_column = where.column + static_cast<int>(first - text.begin());
  // Fields are split at commas and read in place (string views: no copies on the hot path of
  // GOTO records); a field is a number when x3::double_ fills it up to trailing blanks.
  const std::string_view args(&*first, static_cast<std::size_t>(last - first));
  st.arguments.reserve(8);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = args.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? args.size() : comma;
    const std::string_view f = args.substr(start, end - start);
    const bool last_field = comma == std::string_view::npos;
    AptStatement::Argument a;
    const std::size_t lead = f.find_first_not_of(" \t\r\n");
    a.column = base_column + static_cast<int>(start) + static_cast<int>(lead == std::string_view::npos ? 0 : lead);
    if (lead == std::string_view::npos) {
      if (last_field && !st.arguments.empty()) break;  // trailing comma
      throw InputError({file, where.line, a.column}, "empty argument (expected a number or a word)",
                       echo_for(text, a.column));
    }
    read_field(f.substr(lead, f.find_last_not_of(" \t\r\n") - lead + 1), text, file, where.line, a);
    st.arguments.push_back(std::move(a));
    if (last_field) break;
    start = comma + 1;
  }
  return st;
}

}  // namespace ncpost::cl
