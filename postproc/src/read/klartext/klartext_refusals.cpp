// SPDX-License-Identifier: Apache-2.0
// The refusals of the Klartext reader (klartext_refusals.hpp): one table, one sentence each.
#include "read/klartext/klartext_refusals.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace ncpost::klartext {
namespace {

constexpr std::string_view kPostCl = "post the CL data, or have the CAM system write the motions as L and C blocks";

/// The hole cycles read (klartext_drilling.hpp, klartext_hole_path.hpp).
constexpr std::array<int, 9> kHoleCycles = {200, 201, 203, 206, 207, 208, 209, 240, 241};

struct Refusal {
  std::string_view statement;  ///< the statement, or its first word followed by a blank
  std::string_view what;
  std::string_view instead;
};

constexpr Refusal kStatements[] = {
    {"CYCL DEF",
     "this cycle (tilted plane, pocket, other drilling cycles ...) is not read (CYCL DEF 7 datum "
     "shift, 9 dwell, 32 tolerance, 247 preset and the hole cycles {} are)",
     kPostCl},
    {"CYCL CALL", "a cycle call is not read", kPostCl},
    {"APPR", "an approach contour is not read", kPostCl},
    {"DEP", "a departure contour is not read", kPostCl},
    {"LN", "a line with a surface normal (3-D tool compensation) is not read", kPostCl},
    {"CALL ", "a program call is not read (CALL LBL is)",
     "post each program on its own, or copy the called program in as a subprogram (LBL)"},
    {"FUNCTION ", "this function is not read", kPostCl},
    {"SEL", "a program or table selection is not read", "post each program on its own"},
    {"SPL", "a spline is not read", kPostCl},
    {"TCH", "a touch-probe cycle is not read", "probe on the machine; post the machining program"},
};

struct MRefusal {
  int code;
  std::string_view what;
};

constexpr MRefusal kMFunctions[] = {
    {94, "reduces the rotary axis display below 360 deg, changing what later rotary words mean: not read"},
    {97, "a small contour step (radius compensation) is not read"},
    {98, "open contour corners (radius compensation, M98) change the compensated path: not read"},
    {101, "automatic tool change with a replacement tool is not read"},
    {103,
     "M103 F (the plunge feed reduced to a percentage of the programmed feed) is not read: its F is a percentage, "
     "not a feed; write the plunging feeds in the program"},
    {104, "M104 reactivates a datum the control set before (not in the program): not read"},
    {112, "rounding arcs inserted at the contour's corners (M112) change the path: not read"},
    {114,
     "the automatic tool-length compensation of tilted axes (M114) gives X Y Z another meaning: not read; "
     "use M128 or FUNCTION TCPM"},
    {116, "a feed in mm/min on rotary axes (M116) gives F another meaning: not read"},
    {118, "a handwheel superimposition is not read"},
    {120, "M120 LA (radius compensation calculated ahead) changes the compensated path: not read"},
    {124, "M124 (contour points closer than a tolerance left out) changes the path: not read"},
    {130, "a motion in the untilted system inside a tilted plane is not read"},
    {136,
     "a feed in mm per spindle revolution (M136) gives F another meaning (mm/rev, not mm/min): not read; program "
     "the feed in mm/min"},
    {138, "a selection of the rotary axes for M128 is not read"},
    {144, "M144 (kinematics in the actual/nominal positions) gives X Y Z another meaning: not read"},
    {145, "M145 is not read"},
    {150, "M150 (no error at the limit switches) is not read"},
};

}  // namespace

bool is_hole_cycle(int number) {
  return std::find(kHoleCycles.begin(), kHoleCycles.end(), number) != kHoleCycles.end();
}

std::string hole_cycles_listed(const char* last_word) {
  std::string s;
  for (std::size_t i = 0; i < kHoleCycles.size(); ++i)
    s += fmt::format("{}{}",
                     i == 0                        ? ""
                     : i + 1 == kHoleCycles.size() ? fmt::format(" {} ", last_word)
                                                   : ", ",
                     kHoleCycles[i]);
  return s;
}

std::string refused_statement(const Block& b) {
  std::string shown = b.statement;
  if (!b.text.empty()) shown += " " + b.text.substr(0, std::min<std::size_t>(b.text.size(), 40));
  for (const Refusal& r : kStatements) {
    const bool prefix = r.statement.back() == ' ';
    const std::string_view key = prefix ? r.statement.substr(0, r.statement.size() - 1) : r.statement;
    if (prefix ? b.statement.rfind(key, 0) == 0 : b.statement == key)
      return fmt::format("'{}': {}; {}", shown, fmt::format(fmt::runtime(r.what), hole_cycles_listed("and")),
                         r.instead);
  }
  return fmt::format(
      "'{}' is not a Klartext statement ncpost reads (L, LP, C, CC, CR, CT, CP, RND, CHF, TOOL CALL, M functions, "
      "FUNCTION TCPM, PLANE, Q parameters, FN, LBL, CALL LBL); {}",
      shown, kPostCl);
}

std::optional<std::string> refused_m(int code) {
  for (const MRefusal& m : kMFunctions)
    if (m.code == code) return fmt::format("M{}: {}", code, m.what);
  return std::nullopt;
}

}  // namespace ncpost::klartext
