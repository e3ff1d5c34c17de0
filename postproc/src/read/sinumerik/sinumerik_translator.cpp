// SPDX-License-Identifier: Apache-2.0
// Program flow of the Sinumerik translator (sinumerik_translator.hpp): the program counter,
// DEF, jumps, loops and subprogram calls.
#include "read/sinumerik/sinumerik_translator.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/machines/input_error.hpp"
#include "read/sinumerik/sinumerik_refusals.hpp"
#include "read/sinumerik/sinumerik_words.hpp"

namespace ncpost::sinumerik {

Translator::Translator(Program program, const Machine& machine, const Setup& setup, TranslatorOptions options)
    : program_(std::move(program)), machine_(machine), setup_(setup), options_(options) {
  pc_ = program_.units[0].first;
}

bool Translator::next(IsoBlock& out) {
  while (out_.empty() && !ended_) ended_ = !step();
  if (out_.empty()) return false;
  out = std::move(out_.front());
  out_.pop_front();
  return true;
}

std::vector<std::string> Translator::take_notices() {
  std::vector<std::string> n;
  n.swap(notices_);
  return n;
}

void Translator::fail(const ProgramLine& l, int column, const std::string& what) const {
  std::string chain;
  for (auto it = calls_.rbegin(); it != calls_.rend(); ++it)
    chain += fmt::format("{}in {} called at line {}", chain.empty() ? " (" : ", ", it->name, it->line);
  if (!chain.empty()) chain += ")";
  throw InputError({program_.file, l.number, column}, what + chain, l.text);
}

void Translator::notice_once(const ProgramLine& l, const std::string& key, const std::string& what) {
  if (noticed_.insert(key).second) notices_.push_back(fmt::format("{}:{}: {}", program_.file, l.number, what));
}

void Translator::emit(const ProgramLine& l, std::string text) {
  if (!started_) {
    started_ = true;
    out_.push_back({"G90", l.number});
  }
  out_.push_back({std::move(text), l.number});
}

double Translator::value(const ProgramLine& l, int column, const std::string& expression) const {
  try {
    return values_.evaluate(expression);
  } catch (const ValueError& e) {
    fail(l, column, e.what);
  }
}

/// Runs the block at the program counter; false when the program has ended.
bool Translator::step() {
  const Unit& unit = program_.units[static_cast<std::size_t>(calls_.empty() ? 0 : calls_.back().unit)];
  if (pc_ >= unit.last) {
    if (calls_.empty()) return false;  // the end of the file without M30: the G-code reader judges it
    return_from_unit();
    return true;
  }
  const ProgramLine& l = program_.lines[pc_];
  if (++executed_ > options_.max_blocks)
    fail(l, 1,
         fmt::format("more than {} blocks executed: an endless loop? (the last at this line)", options_.max_blocks));
  ++pc_;
  if (l.block.skip && options_.block_skip) {
    notice_once(l, "/", "blocks that start with '/' (skip blocks) are left out, as with skip on");
    return true;
  }
  if (!l.block.header.empty()) return true;
  if (!l.block.statement.empty())
    statement(l);
  else if (!l.block.items.empty())
    block(l);
  else if (!l.block.comment.empty())
    emit(l, ";" + l.block.comment);
  return !ended_;
}

void Translator::statement(const ProgramLine& l) {
  const std::string& s = l.block.statement;
  const std::string& r = l.block.rest;
  if (!l.block.comment.empty()) emit(l, ";" + l.block.comment);
  if (s == "DEF") return define(l);
  if (flow_statement(l)) return;
  if (s == "RET") return return_from_unit();
  if (s == "TRANS" || s == "ATRANS" || s == "ROT" || s == "AROT" || s == "SCALE" || s == "ASCALE")
    return frame_statement(l);
  if (s == "CALL") {
    std::string name;
    try {
      name = values_.evaluate_string(r);
    } catch (const ValueError& e) {
      fail(l, l.block.rest_column, e.what);
    }
    return call(l, upper(name), {}, 1);
  }
  if (s == "STOPRE" || s == "SETMS") return notice_once(l, s, fmt::format("{} is noted (nothing to post)", s));
  if (s == "MCALL") return modal_call(l);
  if (s == "PROC")
    fail(l, l.block.statement_column, "PROC inside the main program: a subprogram starts a program unit");
  fail(l, l.block.statement_column, fmt::format("{} is not read", s));
}

/// GOTO*, IF, ELSE, WHILE, REPEAT/UNTIL, LOOP, FOR and their ends; false for other statements.
bool Translator::flow_statement(const ProgramLine& l) {
  const std::string& s = l.block.statement;
  const std::string& r = l.block.rest;
  if (s == "GOTOF" || s == "GOTOB" || s == "GOTO" || s == "GOTOC") {
    jump(l, s, upper(r));
  } else if (s == "IF") {
    if_statement(l);
  } else if (s == "ELSE") {
    pc_ = l.end + 1;
  } else if (s == "WHILE") {
    if (!condition(l, r)) pc_ = l.end + 1;
  } else if (s == "ENDWHILE" || s == "ENDLOOP") {
    pc_ = l.partner + (s == "ENDLOOP" ? 1 : 0);
  } else if (s == "UNTIL") {
    if (!condition(l, r)) pc_ = l.partner + 1;
  } else if (s == "FOR" || s == "ENDFOR") {
    for_loop(l);
  } else if (s == "REPEAT" && !l.block.rest.empty()) {
    fail(l, l.block.statement_column,
         fmt::format("REPEAT {} (repeating a section of the program) is not read", l.block.rest));
  } else if (s != "ENDIF" && s != "REPEAT" && s != "LOOP") {
    return false;
  }
  return true;
}

/// IF cond (a block up to ELSE/ENDIF) or IF cond GOTOF|GOTOB|GOTO label (a jump).
void Translator::if_statement(const ProgramLine& l) {
  const std::string& r = l.block.rest;
  const std::string R = upper(r);
  for (const std::string g : {" GOTOF ", " GOTOB ", " GOTOC ", " GOTO "}) {
    const std::size_t at = (R + " ").find(g);
    if (at == std::string::npos) continue;
    if (condition(l, r.substr(0, at))) {
      std::string label = R.substr(at + g.size());
      while (!label.empty() && label.back() == ' ') label.pop_back();
      jump(l, g.substr(1, g.size() - 2), label);
    }
    return;
  }
  if (!condition(l, r)) pc_ = (l.partner ? l.partner : l.end) + 1;
}

/// DEF REAL|INT|BOOL|STRING[n] name[=value], name ...
void Translator::define(const ProgramLine& l) {
  const std::string& r = l.block.rest;
  const std::size_t blank = r.find(' ');
  std::string type = upper(r.substr(0, blank));
  if (type.rfind("STRING", 0) == 0) type = "STRING";
  const VarType t = type == "REAL"     ? VarType::real
                    : type == "INT"    ? VarType::integer
                    : type == "BOOL"   ? VarType::boolean
                    : type == "STRING" ? VarType::string
                                       : VarType::real;
  if (type != "REAL" && type != "INT" && type != "BOOL" && type != "STRING")
    fail(l, l.block.rest_column, fmt::format("DEF {}: only REAL, INT, BOOL and STRING variables are read", type));
  if (blank == std::string::npos) fail(l, l.block.rest_column, "DEF without a name");
  for (const std::string& d : split_arguments(std::string_view(r).substr(blank + 1))) {
    const std::size_t eq = d.find('=');
    std::string name = upper(d.substr(0, eq));
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name.find('[') != std::string::npos)
      fail(l, l.block.rest_column, fmt::format("DEF {}: arrays are not read", name));
    try {
      values_.define(name, t);
      if (eq == std::string::npos) continue;
      if (t == VarType::string)
        values_.assign_string(name, values_.evaluate_string(d.substr(eq + 1)));
      else
        values_.assign(name, values_.evaluate(d.substr(eq + 1)));
    } catch (const ValueError& e) {
      fail(l, l.block.rest_column, e.what);
    }
  }
}

bool Translator::condition(const ProgramLine& l, const std::string& text) {
  return value(l, l.block.rest_column, text) != 0.0;
}

void Translator::jump(const ProgramLine& l, const std::string& how, const std::string& label) {
  if (label.empty()) fail(l, l.block.statement_column, fmt::format("{} without a label", how));
  if (how == "GOTOC")
    fail(l, l.block.statement_column, "GOTOC (a jump that goes on when the label is missing) is not read");
  const int unit = l.unit;
  std::optional<std::size_t> to;
  const std::size_t here = pc_ - 1;
  if (how == "GOTOF" || how == "GOTO") to = program_.find_label(unit, label, here + 1, true);
  if (!to && (how == "GOTOB" || how == "GOTO")) to = program_.find_label(unit, label, here, false);
  if (!to)
    fail(l, l.block.rest_column,
         fmt::format("{} {}: no label {} {} in this program unit", how, label, label,
                     how == "GOTOF"   ? "after this block"
                     : how == "GOTOB" ? "before this block"
                                      : ""));
  pc_ = *to;
}

/// FOR var = start TO end ... ENDFOR: the variable counts up by 1 (the control's only step).
void Translator::for_loop(const ProgramLine& l) {
  if (l.block.statement == "ENDFOR") {
    const ProgramLine& head = program_.lines[l.partner];
    const std::string var = upper(head.block.rest.substr(0, head.block.rest.find('=')));
    std::string name = var;
    while (!name.empty() && name.back() == ' ') name.pop_back();
    const double next = value(l, 1, name) + 1.0;
    if (next <= for_end_[l.partner]) {
      assign_or_fail(l, name, next);
      pc_ = l.partner + 1;
    }
    return;
  }
  const std::string R = upper(l.block.rest);
  const std::size_t eq = R.find('=');
  const std::size_t to = R.find(" TO ");
  if (eq == std::string::npos || to == std::string::npos || to < eq)
    fail(l, l.block.rest_column, "expected FOR variable = start TO end");
  std::string name = R.substr(0, eq);
  while (!name.empty() && name.back() == ' ') name.pop_back();
  if (!values_.known(name)) fail(l, l.block.rest_column, fmt::format("FOR {}: not a defined variable", name));
  const double start = value(l, l.block.rest_column, l.block.rest.substr(eq + 1, to - eq - 1));
  for_end_[pc_ - 1] = value(l, l.block.rest_column, l.block.rest.substr(to + 4));
  assign_or_fail(l, name, start);
  if (start > for_end_[pc_ - 1]) pc_ = l.end + 1;
}

void Translator::assign_or_fail(const ProgramLine& l, const std::string& name, double v) {
  try {
    values_.assign(name, v);
  } catch (const ValueError& e) {
    fail(l, l.block.rest_column, e.what);
  }
}

/// An item that names a subprogram of the file (NAME, NAME(args), L<n>) is called; false otherwise.
bool Translator::call_if_subprogram(const ProgramLine& l, const Item& item) {
  std::string name = item.name;
  if (item.kind == Item::Kind::word && item.name == "L") name = "L" + item.text;
  if (!program_.unit_named.count(name)) return false;
  if (item.kind == Item::Kind::assign) return false;
  call(l, name, item.kind == Item::Kind::call ? split_arguments(item.text) : std::vector<std::string>{}, 1);
  return true;
}

void Translator::call(const ProgramLine& l, const std::string& unit_name, const std::vector<std::string>& args,
                      long repeats) {
  const auto it = program_.unit_named.find(unit_name);
  if (it == program_.unit_named.end())
    fail(l, 1,
         fmt::format("{}: no subprogram {} in this file (post a file with the subprogram appended as %_N_{}_SPF)",
                     unit_name, unit_name, unit_name));
  if (static_cast<int>(calls_.size()) + 1 >= options_.max_call_depth)
    fail(l, 1, fmt::format("{}: more than {} subprogram levels", unit_name, options_.max_call_depth));
  const Unit& u = program_.units[it->second];
  if (args.size() > u.parameters.size())
    fail(l, 1, fmt::format("{}: {} arguments for {} parameters", unit_name, args.size(), u.parameters.size()));
  std::vector<std::pair<double, std::string>> given;
  for (const std::string& a : args) given.emplace_back(a.empty() ? 0.0 : (a.front() == '"' ? 0.0 : value(l, 1, a)), a);
  calls_.push_back(Call{pc_, static_cast<int>(it->second), l.number, unit_name, values_.save(), repeats - 1});
  try {
    for (std::size_t i = 0; i < u.parameters.size(); ++i) {
      const char t = u.parameter_types[i];
      values_.define(u.parameters[i], t == 'R'   ? VarType::real
                                      : t == 'I' ? VarType::integer
                                      : t == 'B' ? VarType::boolean
                                                 : VarType::string);
      if (i < given.size() && !given[i].second.empty()) {
        if (t == 'S')
          values_.assign_string(u.parameters[i], values_.evaluate_string(given[i].second));
        else
          values_.assign(u.parameters[i], given[i].first);
      }
    }
  } catch (const ValueError& e) {
    fail(l, 1, fmt::format("{}: {}", unit_name, e.what));
  }
  pc_ = u.first;
}

void Translator::return_from_unit() {
  if (calls_.empty()) {
    ended_ = true;
    return;
  }
  Call& c = calls_.back();
  if (c.repeats_left > 0) {
    --c.repeats_left;
    pc_ = program_.units[static_cast<std::size_t>(c.unit)].first;
    return;
  }
  pc_ = c.return_to;
  values_.restore_scope(std::move(c.saved));  // R parameters keep what the subprogram set
  calls_.pop_back();
}

/// MCALL CYCLE81(...) ... CYCLE86(...) (also CYCLE84/840): the hole after every following motion; MCALL alone ends it.
void Translator::modal_call(const ProgramLine& l) {
  if (l.block.rest.empty()) {
    mcall_.reset();
    return;
  }
  Line called;
  try {
    called = lex_line(l.block.rest);
  } catch (const LexError& e) {
    fail(l, l.block.rest_column + static_cast<int>(e.offset), e.what);
  }
  if (called.items.size() != 1 || called.items[0].kind != Item::Kind::call || !is_hole_cycle(called.items[0].name))
    fail(l, l.block.rest_column,
         "MCALL of a subprogram or of a cycle other than CYCLE81, 82, 83, 84, 840, 85 or 86 is not read");
  Item item = called.items[0];
  item.column += l.block.rest_column - 1;
  mcall_ = drilling(l, item);
}

void Translator::end_program(const ProgramLine& l) {
  if (!calls_.empty()) notice_once(l, "end-in-sub", "M2/M30 in a subprogram ends the program");
  ended_ = true;
}

}  // namespace ncpost::sinumerik
