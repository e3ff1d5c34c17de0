// The Spirit X3 grammar of one APT statement:
//   statement := major [ '/' arguments ]
//   arguments := argument % ','          (a trailing empty argument is dropped)
//   argument  := number | word           (number: the whole trimmed field is a real number)
#include <boost/spirit/home/x3.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "ncpost/postproc/apt_reader.hpp"

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

// Grammar pieces. A field is everything up to the next comma; it is a number when a real number
// followed only by blanks fills it.
const auto field = x3::rule<struct field_tag, std::string>{"field"} = x3::raw[*(x3::char_ - ',')];
const auto number_field = x3::rule<struct number_tag, double>{"number"} =
    x3::omit[*x3::blank] >> x3::double_ >> x3::omit[*x3::blank] >> x3::eoi;
const auto major_word = x3::rule<struct major_tag, std::string>{"major word"} = x3::raw[+(x3::char_ - '/')];

}  // namespace

AptStatement parse_apt_statement(const std::string& text, const std::string& file, Location where) {
  AptStatement st;
  st.where = where;
  auto first = text.begin();
  const auto last = text.end();
  std::string major;
  if (!x3::parse(first, last, major_word, major))
    throw InputError({file, where.line, where.column}, "expected a major word before '/'", text);
  st.major = upper(trim(major));
  // Fold runs of blanks inside the major word ("TOOL  PATH" -> "TOOL PATH").
  std::string folded;
  for (char c : st.major) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!folded.empty() && folded.back() != ' ') folded += ' ';
    } else {
      folded += c;
    }
  }
  st.major = folded;
  if (first == last) return st;
  st.has_slash = true;
  ++first;  // '/'
  st.raw_arguments = trim(std::string(first, last));
  if (st.raw_arguments.empty()) return st;  // "RAPID/"
  const int base_column = where.column + static_cast<int>(first - text.begin());
  std::vector<std::string> fields;
  auto it = first;
  if (!x3::parse(it, last, field % ',', fields) || it != last)
    throw InputError({file, where.line, base_column}, "malformed argument list", text);
  int offset = 0;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string& f = fields[i];
    AptStatement::Argument a;
    a.column = base_column + offset + static_cast<int>(f.find_first_not_of(" \t") == std::string::npos ? 0 : f.find_first_not_of(" \t"));
    offset += static_cast<int>(f.size()) + 1;
    const std::string t = trim(f);
    if (t.empty()) {
      if (i + 1 == fields.size() && i > 0) break;  // trailing comma
      throw InputError({file, where.line, a.column}, "empty argument (expected a number or a word)", text);
    }
    double value = 0.0;
    auto fb = f.begin();
    const bool starts_numeric = std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.' || t[0] == '-' || t[0] == '+';
    if (x3::parse(fb, f.end(), number_field, value)) {
      if (!std::isfinite(value))
        throw InputError({file, where.line, a.column}, fmt::format("'{}' is not a finite number", t), text);
      a.is_number = true;
      a.number = value;
    } else if (starts_numeric) {
      throw InputError({file, where.line, a.column}, fmt::format("malformed number '{}'", t), text);
    } else {
      a.word = upper(t);
      if (a.word == "NAN" || a.word == "INF" || a.word == "INFINITY" || a.word == "-NAN")
        throw InputError({file, where.line, a.column}, fmt::format("'{}' is not a finite number", t), text);
    }
    st.arguments.push_back(std::move(a));
  }
  return st;
}

}  // namespace ncpost::cl
