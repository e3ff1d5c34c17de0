// SPDX-License-Identifier: Apache-2.0
// The tables of the Sinumerik reader (sinumerik_refusals.hpp).
#include "read/sinumerik/sinumerik_refusals.hpp"

#include <fmt/format.h>

#include <string_view>

namespace ncpost::sinumerik {
namespace {

constexpr std::string_view kPostCl = "post the CL data";

struct GEntry {
  int g;
  GAction action;
  const char* what;
};

constexpr GEntry kG[] = {
    {4, GAction::dwell, "dwell"},
    {17, GAction::pass, ""},
    {18, GAction::pass, ""},
    {19, GAction::pass, ""},
    {40, GAction::pass, ""},
    {41, GAction::pass, ""},
    {42, GAction::pass, ""},
    {54, GAction::pass, ""},
    {55, GAction::pass, ""},
    {56, GAction::pass, ""},
    {57, GAction::pass, ""},
    {70, GAction::pass, ""},
    {71, GAction::pass, ""},
    {700, GAction::pass, ""},
    {710, GAction::pass, ""},
    {93, GAction::pass, ""},
    {94, GAction::pass, ""},
    {95, GAction::pass, ""},
    {9, GAction::note, "exact stop for the block"},
    {60, GAction::note, "exact stop"},
    {64, GAction::note, "continuous-path mode"},
    {641, GAction::note, "continuous-path mode with smoothing"},
    {642, GAction::note, "continuous-path mode with smoothing within tolerances"},
    {643, GAction::note, "continuous-path mode, block-internal smoothing"},
    {644, GAction::note, "continuous-path mode with maximum dynamics"},
    {645, GAction::note, "continuous-path smoothing"},
    {601, GAction::note, "exact stop fine"},
    {602, GAction::note, "exact stop coarse"},
    {603, GAction::note, "exact stop at interpolation end"},
    {97, GAction::note, "constant spindle speed (rpm)"},
    {62, GAction::note, "corner deceleration at inside corners with radius compensation: the feed only"},
    {621, GAction::note, "corner deceleration at all corners: the feed only"},
    {450, GAction::note, "transition circle at outer corners"},
    {451, GAction::note, "intersection at outer corners"},
};

struct NameEntry {
  std::string_view name;
  const char* what;
};

constexpr NameEntry kNoted[] = {
    {"SOFT", "jerk-limited acceleration"},
    {"BRISK", "step acceleration"},
    {"DRIVE", "acceleration mode"},
    {"FFWON", "feed forward control on"},
    {"FFWOF", "feed forward control off"},
    {"COMPOF", "compressor off"},
    {"COMPON", "compressor"},
    {"COMPCAD", "compressor for CAD surfaces"},
    {"COMPCURV", "compressor with constant curvature"},
    {"COMPSURF", "compressor for surfaces"},
    {"CYCLE832", "high-speed settings: a path tolerance of the control"},
    {"WORKPIECE", "the blank's shape for the control's simulation (ShopMill): no motion"},
    {"FNORM", "normal feed"},
    {"CFC", "constant feed at the contour"},
    {"CFTCP", "constant feed at the tool centre"},
    {"CFIN", "constant feed on inner arcs"},
    {"UPATH", "path parameter"},
    {"SPATH", "path parameter"},
    {"ORIWKS",
     "orientation interpolated in the workpiece frame: between the blocks the posted program "
     "interpolates the machine axes"},
    {"ORIMKS", "orientation interpolated in the machine frame"},
    {"ORIAXES", "orientation by axis interpolation"},
    {"ORIVECT", "orientation by vector interpolation"},
    {"CUT2D", "2-D radius compensation"},
    {"CUT2DF", "2-D radius compensation in the frame"},
    {"STOPRE", "preprocessing stop"},
    {"DIAMOF", "radius programming"},
    {"SETMS", "master spindle"},
    {"WAITMC", "wait for marker"},
    {"CTOL", "contour tolerance"},
    {"OTOL", "orientation tolerance"},
    {"TCOABS", "tool length from the tool data"},
    {"ORIPATH", "orientation relative to the path"},
};

constexpr NameEntry kRefused[] = {
    {"MIRROR", "frame mirroring"},
    {"AMIRROR", "frame mirroring"},
    {"RPL", "rotation in the plane"},
    {"TRANSMIT", "face-end transformation"},
    {"TRACYL", "cylinder surface transformation"},
    {"TRAANG", "inclined axis transformation"},
    {"TRACON", "chained transformations"},
    {"CIP", "a circle through an intermediate point"},
    {"CT", "a tangential circle"},
    {"POLY", "polynomial interpolation"},
    {"BSPLINE", "spline interpolation"},
    {"ASPLINE", "spline interpolation"},
    {"CSPLINE", "spline interpolation"},
    {"G153", "suppression of all frames blockwise"},
    {"DIAMON", "diameter programming (turning)"},
    {"TCARR", "a tool carrier selected by the program"},
    {"TOFRAME", "a frame along the tool"},
    {"PAROT", "a frame aligned with the workpiece"},
    {"SPOS", "spindle positioning"},
    {"OFFN", "contour offset"},
    {"CUT3DC", "3-D radius compensation"},
    {"CUT3DF", "3-D radius compensation"},
    {"CUT3DFF", "3-D radius compensation"},
    {"ORIC", "orientation change at corners"},
};

}  // namespace

bool is_hole_cycle(const std::string& name) {
  for (const char* n : {"CYCLE81", "CYCLE82", "CYCLE83", "CYCLE84", "CYCLE840", "CYCLE85", "CYCLE86"})
    if (name == n) return true;
  return false;
}

GAction kept_g(int g) {
  for (const GEntry& e : kG)
    if (e.g == g) return e.action;
  return GAction::refuse;
}

const char* g_meaning(int g) {
  for (const GEntry& e : kG)
    if (e.g == g) return e.what;
  return "";
}

std::string refused_g(int g) {
  if (g >= 505 && g <= 599)
    return fmt::format(
        "G{}: a settable work offset beyond G57 is not read (its values are the control's); use G54 "
        "and give the part's position with --workpiece-origin",
        g);
  if (g == 110 || g == 111 || g == 112) return fmt::format("G{}: polar coordinates are not read", g);
  if (g == 74)
    return "G74 (reference point approach) is not read: it homes the axes (the control's machine data); program "
           "the retract as SUPA/G53 with the machine position (e.g. G0 SUPA Z0 D0), or post the CL data";
  if (g == 331 || g == 332 || g == 33) return fmt::format("G{}: thread cutting and tapping are not read", g);
  if (g == 96) return "G96 (constant cutting speed) is not read: program the speed in rpm (G97)";
  if (g == 43 || g == 44)
    return fmt::format(
        "G{} (an ISO tool length offset with H: Sinumerik's ISO dialect mode) in a program read as Siemens "
        "language (it holds Siemens statements: DEF, MCALL, CYCLE..., ...): in Siemens language the tool's "
        "length comes with its D number (T1 D1); write D<n> for G{} ... H<n>, or post the CL data (a "
        "program of ISO words only is read as G-code)",
        g, g);
  return fmt::format("G{} is not read; {}", g, kPostCl);
}

std::optional<std::string> refused_m(double m) {
  if (m == 19.0) return std::string("M19 (spindle orientation) is not read");
  if (m != static_cast<int>(m)) return fmt::format("M{}: an extended M address is not read", m);
  return std::nullopt;
}

const char* noted_name(const std::string& name) {
  for (const NameEntry& e : kNoted)
    if (e.name == name) return e.what;
  return nullptr;
}

std::string refused_name(const std::string& name) {
  for (const NameEntry& e : kRefused)
    if (e.name == name) return fmt::format("{} ({}) is not read; {}", name, e.what, kPostCl);
  if (name.size() > 1 && name[0] == 'L' && name.find_first_not_of("0123456789", 1) == std::string::npos)
    return fmt::format(
        "{}: the subprogram {} is not in this file; append it as %_N_{}_SPF (its blocks) and post "
        "the file",
        name, name, name);
  if (name.size() > 1 && name[0] == 'M' && name.find_first_not_of("0123456789", 1) == std::string::npos)
    return fmt::format(
        "{}(...): an M function with a value is the machine builder's own, not a Siemens function (NX's post "
        "for the Cincinnati FTV5 writes M200 / M202(tolerance) / M204 as that machine's spline mode on / off): "
        "what it does is not in the program; where it only smooths the path within a tolerance, delete the "
        "block and post again, or post the CL data",
        name);
  if (name.rfind("CYCLE", 0) == 0) return fmt::format("{} (a Sinumerik cycle) is not read; {}", name, kPostCl);
  if (!name.empty() && name[0] == '$') return fmt::format("{} (a system variable) is not read", name);
  return fmt::format("{} is not read (not a statement, address or subprogram of this file ncpost knows); {}", name,
                     kPostCl);
}

std::string refused_address(const std::string& name, bool number) {
  if (name == "H") return "H (an auxiliary function of the machine builder) is not read";
  if (name == "P") return "P (repetitions of a subprogram call L... P) is not read";
  if (name == "AR" || name == "AP" || name == "RP")
    return fmt::format("{}= (arcs by opening angle or polar coordinates) are not read; program I J K or CR", name);
  if (name == "TURN") return "TURN= (helix turns) is not read";
  if (!number) return fmt::format("{} is not a defined variable or an address ncpost reads (DEF it first?)", name);
  return fmt::format("the address {} is not read", name);
}

}  // namespace ncpost::sinumerik
