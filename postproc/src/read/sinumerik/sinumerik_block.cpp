// SPDX-License-Identifier: Apache-2.0
// One Sinumerik block: its items gathered (Words) and written as an ISO block
// (sinumerik_translator.hpp); frame statements.
#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/sinumerik/sinumerik_refusals.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"
#include "read/sinumerik/sinumerik_words.hpp"

namespace ncpost::sinumerik {
namespace {

int slot_of(const std::string& name, const char* letters) {
  if (name.size() != 1) return -1;
  const char* at = std::strchr(letters, name[0]);
  return at ? static_cast<int>(at - letters) : -1;
}

/// `IC(expr)` / `AC(expr)` around an axis value: the reference and the expression inside.
std::pair<Reference, std::string> referenced(const std::string& text) {
  const std::string u = upper(text.substr(0, 3));
  if ((u == "IC(" || u == "AC(") && text.back() == ')')
    return {u[0] == 'I' ? Reference::incremental : Reference::absolute, text.substr(3, text.size() - 4)};
  return {Reference::modal, text};
}

}  // namespace

void Translator::block(const ProgramLine& l) {
  Words w;
  w.column = l.block.items.front().column;
  for (const Item& item : l.block.items) collect(l, item, w);
  write_block(l, w);
}

void Translator::collect(const ProgramLine& l, const Item& item, Words& w) {
  switch (item.kind) {
    case Item::Kind::word: {
      if (item.name == "G") return g_word(l, item, w);
      const double v = *item.value;
      Item as_assign = item;
      as_assign.kind = Item::Kind::assign;
      if (item.name == "L" || item.name == "N") {
        if (item.name == "N") return;
        w.after.push_back(&item);
        return;
      }
      if (item.name == "M") {
        if (v == 2.0 || v == 30.0)
          w.program_end = true;
        else if (v == 17.0)
          w.unit_end = true;
        else if (auto why = refused_m(v))
          fail(l, item.column, *why);
        else
          w.iso.push_back("M" + item.text);
        if (v == 3.0 || v == 4.0 || v == 5.0) spindle_direction_ = static_cast<int>(v);
        if (v == 6.0) machine_mm_ = {};  // the tool change moves the axes where the machine's data has it
        return;
      }
      return assignment(l, as_assign, w);
    }
    case Item::Kind::assign:
      return assignment(l, item, w);
    case Item::Kind::call:
      return called(l, item, w);
    case Item::Kind::name:
      return named(l, item, w);
  }
}

/// An address with a value (X10, X=IC(5), F=R1, CR=5, A3=0.7) or a variable assignment.
void Translator::assignment(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& n = item.name;
  if (axis_address(l, item, w) || tool_name_address(l, item, w)) return;
  if (n == "A3" || n == "B3" || n == "C3") {
    w.orientation[static_cast<std::size_t>(n[0] - 'A')] = value(l, item.column, item.text);
    return;
  }
  if (n == "CR" || n == "F" || n == "S" || n == "T" || n == "D") return value_address(l, item, w);
  if (n == "FP") {
    w.fixed_point = item.value ? *item.value : value(l, item.column, item.text);
    w.fixed_point_column = item.column;
    return;
  }
  if (values_.known(n)) {
    try {
      if (values_.string_value(n))
        values_.assign_string(n, values_.evaluate_string(item.text));
      else
        values_.assign(n, values_.evaluate(item.text));
    } catch (const ValueError& e) {
      fail(l, item.column, e.what);
    }
    return;
  }
  fail(l, item.column, refused_address(n, item.value.has_value()));
}

/// X Y Z, A B C, I J K (a number, an expression, IC() / AC()): false for other names.
bool Translator::axis_address(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& n = item.name;
  const bool number = item.value.has_value();
  int s = slot_of(n, "XYZ");
  if (s < 0 && slot_of(n, "ABC") < 0 && slot_of(n, "IJK") < 0) return false;
  const auto [ref, expr] = number ? std::make_pair(Reference::modal, item.text) : referenced(item.text);
  const double v = number ? *item.value : value(l, item.column, expr);
  if (s >= 0) {
    w.xyz[static_cast<std::size_t>(s)] = v;
    w.xyz_ref[static_cast<std::size_t>(s)] = ref;
    if (!w.any_linear() || w.axis_column == 1) w.axis_column = item.column;
  } else if ((s = slot_of(n, "ABC")) >= 0) {
    w.abc[static_cast<std::size_t>(s)] = v;
    w.abc_ref[static_cast<std::size_t>(s)] = ref;
  } else {
    s = slot_of(n, "IJK");
    if (ref == Reference::incremental)
      fail(l, item.column, fmt::format("{}=IC(...): I J K are incremental already", n));
    w.ijk[static_cast<std::size_t>(s)] = v;
    w.ijk_absolute[static_cast<std::size_t>(s)] = ref == Reference::absolute;
  }
  return true;
}

/// T="12" (the tool number as a string) and T="name" (tool management): false for anything else.
bool Translator::tool_name_address(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& t = item.text;
  if (item.name != "T" || item.value || t.empty() || t.front() != '"') return false;
  if (t.size() > 2 && t.back() == '"' && t.find_first_not_of("0123456789", 1) == t.size() - 1) {
    w.iso.push_back("T" + t.substr(1, t.size() - 2));
    w.tool_name = "";
    return true;
  }
  if (t.size() < 3 || t.back() != '"' || t.find('"', 1) != t.size() - 1)
    fail(l, item.column, fmt::format("T={}: expected a tool name between quotes (T=\"NAME\")", t));
  w.iso.push_back("T0");
  w.tool_name = t.substr(1, t.size() - 2);
  return true;
}

/// CR, F (G4 F: the dwell), S, T, D (D0: no tool length, G49) with a number or an expression.
void Translator::value_address(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& n = item.name;
  const double v = item.value ? *item.value : value(l, item.column, item.text);
  if (n == "F" && w.dwell_s) {
    w.dwell_s = v;  // G4 F: the dwell in seconds
  } else if (n == "F") {
    feed_ = v, w.iso.push_back(n + gcode::word_number(v));
  } else if (n == "CR") {
    w.radius = v;
  } else if (n == "D") {
    if (v == 0.0)
      w.iso.push_back("G49"), length_off_ = true;
    else if (length_off_)
      w.iso.push_back("G43"), length_off_ = false;
  } else {
    if (v < 0 || v != std::floor(v)) fail(l, item.column, fmt::format("{}: expected a whole number >= 0", n));
    w.iso.push_back(n + gcode::word_number(v));
    if (n == "T") w.tool_name = "";
    if (n == "S") spindle_rpm_ = v;
  }
}

void Translator::g_word(const ProgramLine& l, const Item& item, Words& w) {
  const double v = *item.value;
  const int g = static_cast<int>(v);
  if (v != g) fail(l, item.column, fmt::format("G{} is not read", item.text));
  if (g >= 0 && g <= 3) {
    w.motion = g;
    return;
  }
  if (g == 90 || g == 91) {
    incremental_ = g == 91;
    return;
  }
  if (g == 53) {
    w.supa = true;
    w.g53_column = item.column;
    return;
  }
  if (g == 75) {
    w.g75_column = item.column;
    return;
  }
  if (g == 17 || g == 18 || g == 19) plane_ = g;
  if (g == 93 || g == 94 || g == 95) feed_mode_ = g;
  if (g == 70 || g == 700 || g == 71 || g == 710) inch_ = g == 70 || g == 700;
  if (g == 500) {
    notice_once(l, "G500",
                "G500 (no settable work offset): W is the job's workpiece frame as for G54 (--workpiece-origin)");
    return;
  }
  switch (kept_g(g)) {
    case GAction::pass:
      w.iso.push_back(fmt::format("G{}", g));
      return;
    case GAction::note:
      notice_once(l, fmt::format("G{}", g), fmt::format("G{} ({}) is noted, not posted", g, g_meaning(g)));
      return;
    case GAction::dwell:
      w.dwell_s = -1.0;
      return;
    case GAction::refuse:
      fail(l, item.column, refused_g(g));
  }
}

void Translator::named(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& n = item.name;
  if (n == "TRAORI" || n == "TRAFOOF") {
    if (n == "TRAORI" && swivel_tip_) fail(l, item.column, "TRAORI with a swivelled plane (CYCLE800) active: not read");
    traori_ = n == "TRAORI";
    w.iso.push_back(n);
    return;
  }
  if (n == "SUPA") {
    w.supa = true;
    return;
  }
  // a cycle called without a parameter list leaves every parameter out: CYCLE800 is CYCLE800(), the
  // reset (as NC-PB's programs and ShopMill write it before the first plane)
  if (program_.unit_named.count(n) || n == "CYCLE800") {
    w.after.push_back(&item);
    return;
  }
  if (const char* what = noted_name(n)) {
    notice_once(l, n, fmt::format("{} ({}) is noted, not posted", n, what));
    return;
  }
  fail(l, item.column, refused_name(n));
}

void Translator::called(const ProgramLine& l, const Item& item, Words& w) {
  const std::string& n = item.name;
  if (n == "MSG") {
    std::string text = item.text;
    try {
      text = values_.evaluate_string(item.text);
    } catch (const ValueError&) {
    }
    w.iso.push_back(";MSG " + text);
    return;
  }
  if (n == "TRAORI") {
    Item bare = item;
    bare.kind = Item::Kind::name;
    return named(l, bare, w);
  }
  if (n == "CYCLE800" || is_hole_cycle(n) || program_.unit_named.count(n)) {
    w.after.push_back(&item);
    return;
  }
  if (const char* what = noted_name(n)) {
    notice_once(l, n, fmt::format("{}({}) ({}) is noted, not posted", n, item.text, what));
    return;
  }
  fail(l, item.column, refused_name(n));
}

void Translator::write_block(const ProgramLine& l, Words& w) {
  std::string iso;
  for (const std::string& s : w.iso) {
    if (s.front() == ';') continue;
    iso += (iso.empty() ? "" : " ") + s;
  }
  if (w.dwell_s) {
    if (*w.dwell_s < 0.0) fail(l, w.column, "G4 without F (the dwell in seconds; G4 S in spindle turns is not read)");
    emit(l, fmt::format("G4 P{:.4f}", *w.dwell_s));
  }
  const bool moves = w.any_linear() || w.any_rotary() || w.any_orientation();
  if (w.fixed_point && !w.g75_column) fail(l, w.fixed_point_column, "FP= without G75 (the fixed point approach)");
  if (w.g75_column) {
    iso += (iso.empty() ? "" : " ") + fixed_point_words(l, w);
  } else if (w.supa) {
    frames_suppressed(l, w, moves);
    if (moves) iso += (iso.empty() ? "" : " ") + supa_words(l, w);
  } else if (moves) {
    motion(l, w, iso);
  } else if (w.motion) {
    motion_ = *w.motion;
  }
  for (const std::string& s : w.iso)
    if (s.front() == ';') emit(l, s);
  if (!l.block.comment.empty()) iso += (iso.empty() ? ";" : " ;") + l.block.comment;
  if (!iso.empty()) emit(l, iso);
  if (w.tool_name) out_.back().tool_name = w.tool_name;  // (T0 is in `iso`)
  if (mcall_ && w.any_linear() && !w.supa && !w.g75_column) drill(l, *mcall_);
  for (const Item* item : w.after) {
    if (item->name == "CYCLE800")
      cycle800(l, *item);
    else if (is_hole_cycle(item->name))
      drill(l, drilling(l, *item));
    else if (!call_if_subprogram(l, *item))
      fail(l, item->column, fmt::format("{}{} is not read", item->name, item->text));
  }
  if (w.program_end) {
    emit(l, "M30");
    end_program(l);
  } else if (w.unit_end) {
    if (calls_.empty()) {
      emit(l, "M30");
      end_program(l);
    } else {
      return_from_unit();
    }
  }
}

/// G53 (and SUPA) without axis words move nothing: the suppression holds for its own block only.
/// G53 is read as SUPA: both suppress the settable and the programmable frames (SINUMERIK 840D sl
/// Programming Manual Fundamentals, "Zero offset frame": G53 "non-modal deactivation of the current
/// settable and programmable zero offset", SUPA also the basic frame, DRF, external zero offset and
/// PRESET), which the machine's data holds, not the program: taken as zero, with a notice.
void Translator::frames_suppressed(const ProgramLine& l, const Words& w, bool moves) {
  const char* what = w.suppression();
  if (!moves) {
    notice_once(l, std::string(what) + " alone",
                fmt::format("{} without axis words moves nothing (it holds for its own block only)", what));
    if (w.motion) motion_ = *w.motion;
    return;
  }
  if (!w.g53_column) return;
  if (!swivel_.shift_only() || swivel_.offset != Eigen::Vector3d::Zero())
    fail(l, *w.g53_column,
         "G53 in a plane swivelled by CYCLE800: whether G53 suppresses the cycle's frame is the machine's "
         "setting; program SUPA (all frames suppressed) or CYCLE800() first");
  notice_once(l, "G53",
              "G53 (frames suppressed for the block) is read as SUPA, in machine coordinates (the machine file's "
              "reference data): the basic frame, DRF and external zero offset, which G53 keeps and SUPA suppresses, "
              "are taken as zero (their values are the machine's, not in the program)");
}

/// TRANS/ATRANS X Y Z, ROT/AROT X Y Z (RPL=: refused), SCALE/ASCALE with one factor for X Y Z.
void Translator::frame_statement(const ProgramLine& l) {
  const std::string& s = l.block.statement;
  Line words;
  try {
    words = lex_line(l.block.rest);
  } catch (const LexError& e) {
    fail(l, l.block.rest_column + static_cast<int>(e.offset), e.what);
  }
  std::array<std::optional<double>, 3> v;
  for (const Item& it : words.items) {
    const int slot = slot_of(it.name, "XYZ");
    if (slot < 0 || (it.kind != Item::Kind::word && it.kind != Item::Kind::assign))
      fail(l, l.block.rest_column + it.column - 1, fmt::format("{} {}: only X, Y and Z are read", s, it.name));
    v[static_cast<std::size_t>(slot)] = it.value ? *it.value : value(l, l.block.rest_column, it.text);
  }
  const bool additive = s[0] == 'A';
  const std::string kind = additive ? s.substr(1) : s;
  Frame f;
  if (kind == "TRANS") {
    f = shift(Eigen::Vector3d(v[0].value_or(0.0), v[1].value_or(0.0), v[2].value_or(0.0)));
  } else if (kind == "ROT") {
    f = rotation_rpy_deg(v[0].value_or(0.0), v[1].value_or(0.0), v[2].value_or(0.0));
  } else {
    const double k = v[0].value_or(v[1].value_or(v[2].value_or(1.0)));
    for (const auto& x : v)
      if (x && *x != k) fail(l, l.block.rest_column, fmt::format("{} with different factors per axis is not read", s));
    if (k <= 0.0) fail(l, l.block.rest_column, fmt::format("{}: a factor <= 0 (mirroring) is not read", s));
    f.scale = k;
  }
  programmable_ = additive ? programmable_.then(f) : f;
  if (!l.block.comment.empty()) emit(l, ";" + l.block.comment);
}

}  // namespace ncpost::sinumerik
