// SPDX-License-Identifier: Apache-2.0
// Reading and structuring a Sinumerik file (sinumerik_program.hpp).
#include "read/sinumerik/sinumerik_program.hpp"

#include <fmt/format.h>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::sinumerik {
namespace {

/// `%_N_NAME_SPF` -> "NAME" (and whether it is a subprogram); nullopt for other '%' lines.
std::optional<std::pair<std::string, bool>> unit_header(const std::string& header) {
  if (header.rfind("%_N_", 0) != 0 || header.size() < 9) return std::nullopt;
  const std::string kind = header.substr(header.size() - 4);
  if (kind != "_MPF" && kind != "_SPF") return std::nullopt;
  return std::make_pair(header.substr(4, header.size() - 8), kind == "_SPF");
}

/// PROC NAME(REAL A, INT B) [SAVE ...]: the name and the parameters.
Unit proc_unit(const ProgramLine& l, const std::string& file) {
  Unit u;
  const std::string& r = l.block.rest;
  const std::size_t open = r.find('(');
  u.name = upper(r.substr(0, std::min(open, r.find(' '))));
  if (open == std::string::npos) return u;
  const std::size_t close = r.find(')', open);
  if (close == std::string::npos)
    throw InputError({file, l.number, l.block.rest_column}, "PROC: '(' without ')'", l.text);
  for (const std::string& p : split_arguments(std::string_view(r).substr(open + 1, close - open - 1))) {
    const std::string P = upper(p);
    const std::size_t blank = P.find(' ');
    const std::string type = P.substr(0, blank);
    if (blank == std::string::npos || (type != "REAL" && type != "INT" && type != "BOOL" && type != "STRING") ||
        P.find("VAR") != std::string::npos || P.find('[') != std::string::npos)
      throw InputError(
          {file, l.number, l.block.rest_column},
          fmt::format("PROC parameter '{}': expected REAL|INT|BOOL|STRING name (VAR and arrays are not read)", p),
          l.text);
    std::string name = P.substr(blank + 1);
    while (!name.empty() && name.front() == ' ') name.erase(0, 1);
    u.parameters.push_back(name);
    u.parameter_types.push_back(type[0] == 'R' ? 'R' : type[0] == 'I' ? 'I' : type[0] == 'B' ? 'B' : 'S');
  }
  return u;
}

void split_units(Program& p) {
  p.units.push_back(Unit{});
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    ProgramLine& l = p.lines[i];
    std::optional<Unit> starts;
    if (auto h = unit_header(l.block.header)) {
      if (!h->second && i == 0)
        p.units[0].name = h->first;
      else
        starts = Unit{h->first, i + 1, 0, {}, {}};
    } else if (l.block.statement == "PROC") {
      Unit u = proc_unit(l, p.file);
      const bool right_after_header = p.units.size() > 1 && p.units.back().first == i && p.units.back().name == u.name;
      if (right_after_header) {
        p.units.back().parameters = u.parameters;
        p.units.back().parameter_types = u.parameter_types;
        p.units.back().first = i + 1;
      } else if (i == 0 || (i == 1 && !p.lines[0].block.header.empty())) {
        throw InputError({p.file, l.number, l.block.statement_column},
                         "the file starts with PROC: a subprogram file is not a program to post (post the main "
                         "program that calls it, with the subprogram appended)",
                         l.text);
      } else {
        u.first = i + 1;
        starts = u;
      }
    }
    if (starts) {
      p.units.back().last = i;
      if (p.unit_named.count(starts->name))
        throw InputError({p.file, l.number, 1}, fmt::format("a second subprogram {}", starts->name), l.text);
      p.unit_named[starts->name] = p.units.size();
      p.units.push_back(*starts);
    }
    l.unit = static_cast<int>(p.units.size()) - 1;
  }
  p.units.back().last = p.lines.size();
}

bool opens(const std::string& s) { return s == "IF" || s == "WHILE" || s == "FOR" || s == "REPEAT" || s == "LOOP"; }
const char* closer_of(const std::string& s) {
  return s == "IF" ? "ENDIF" : s == "WHILE" ? "ENDWHILE" : s == "FOR" ? "ENDFOR" : s == "REPEAT" ? "UNTIL" : "ENDLOOP";
}

/// An IF whose line holds its jump (`IF R1>0 GOTOF END`) opens no block.
bool one_line_if(const Line& b) {
  const std::string r = upper(b.rest);
  for (const char* g : {" GOTOF ", " GOTOB ", " GOTO ", " GOTOC "})
    if ((r + " ").find(g) != std::string::npos) return true;
  return false;
}

void match_blocks(Program& p) {
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    ProgramLine& l = p.lines[i];
    const std::string& s = l.block.statement;
    if (!open.empty() && p.lines[open.back()].unit != l.unit) {
      const ProgramLine& o = p.lines[open.back()];
      throw InputError(
          {p.file, o.number, o.block.statement_column},
          fmt::format("{} without its {} in its program unit", o.block.statement, closer_of(o.block.statement)),
          o.text);
    }
    if (opens(s) && !(s == "IF" && one_line_if(l.block)) && !(s == "REPEAT" && !l.block.rest.empty())) {
      open.push_back(i);
      continue;
    }
    const bool else_ = s == "ELSE";
    const bool closes = s == "ENDIF" || s == "ENDWHILE" || s == "ENDFOR" || s == "UNTIL" || s == "ENDLOOP";
    if (!else_ && !closes) continue;
    const std::string expected_opener = s == "ENDIF" || else_ ? "IF"
                                        : s == "ENDWHILE"     ? "WHILE"
                                        : s == "ENDFOR"       ? "FOR"
                                        : s == "UNTIL"        ? "REPEAT"
                                                              : "LOOP";
    if (open.empty() || p.lines[open.back()].block.statement != expected_opener)
      throw InputError(
          {p.file, l.number, l.block.statement_column},
          fmt::format("{} without its {}{}", s, expected_opener,
                      open.empty() ? ""
                                   : fmt::format(" (the open {} at line {} closes first)",
                                                 p.lines[open.back()].block.statement, p.lines[open.back()].number)),
          l.text);
    ProgramLine& o = p.lines[open.back()];
    if (else_) {
      if (o.partner) throw InputError({p.file, l.number, l.block.statement_column}, "a second ELSE", l.text);
      o.partner = i;
      continue;
    }
    if (o.partner) p.lines[o.partner].end = i;
    o.end = i;
    l.partner = open.back();
    open.pop_back();
  }
  if (!open.empty()) {
    const ProgramLine& o = p.lines[open.back()];
    throw InputError({p.file, o.number, o.block.statement_column},
                     fmt::format("{} without its {}", o.block.statement, closer_of(o.block.statement)), o.text);
  }
}

}  // namespace

std::optional<std::size_t> Program::find_label(int unit, const std::string& label, std::size_t from,
                                               bool forward) const {
  const Unit& u = units[static_cast<std::size_t>(unit)];
  const auto matches = [&](const ProgramLine& l) {
    if (l.block.label == label) return true;
    return label.size() > 1 && label[0] == 'N' && l.block.block_number &&
           fmt::format("N{}", *l.block.block_number) == label;
  };
  if (forward) {
    for (std::size_t i = from; i < u.last; ++i)
      if (matches(lines[i])) return i;
  } else {
    for (std::size_t i = from + 1; i-- > u.first;)
      if (matches(lines[i])) return i;
  }
  return std::nullopt;
}

Program load_program(std::istream& in, const std::string& file) {
  Program p;
  p.file = file;
  LineSource source(in, file, "Sinumerik blocks, one per line");
  std::string_view text;
  while (source.next(text)) {
    ProgramLine l;
    l.number = source.line_number();
    l.text = echo_of(text);
    try {
      l.block = lex_line(text);
    } catch (const LexError& e) {
      throw InputError({file, l.number, static_cast<int>(e.offset) + 1}, e.what,
                       echo_for(text, static_cast<int>(e.offset) + 1));
    }
    p.lines.push_back(std::move(l));
  }
  split_units(p);
  match_blocks(p);
  return p;
}

}  // namespace ncpost::sinumerik
