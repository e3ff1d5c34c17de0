// SPDX-License-Identifier: Apache-2.0
#include "input_options.hpp"

#include <fmt/format.h>

#include <sstream>
#include <string>
#include <vector>

#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/read/gcode/work_offsets.hpp"
#include "number_checks.hpp"
#include "terminal_text.hpp"

namespace ncpost::cli {

// Plausible set-up values (README "Command line"): beyond them a typing slip, not a machine.
constexpr double kMaxToolLengthMm = 2000.0;
constexpr double kMaxWorkpieceOriginMm = 100000.0;

namespace {

/// An option whose value is one of `choices`.
void add_choice(CLI::App& sub, const std::string& name, std::string& value, const std::string& help,
                std::vector<std::string> choices) {
  sub.add_option(name, value, help)->check(CLI::IsMember(std::move(choices)));
}

}  // namespace

void add_job_options(CLI::App& sub, JobOptions& o) {
  sub.add_option("--machine", o.machine, "Machine definition (TOML)")->required()->check(CLI::ExistingFile);
  sub.add_option("--workpiece-origin", o.workpiece_origin, "Origin of the workpiece frame W in M at home: X,Y,Z (mm)");
  sub.add_option("--tool-length", o.tool_length_mm, "Tool length (mm): places head pivots")
      ->check(finite_in(0.0, kMaxToolLengthMm, "mm"));
  sub.add_option(
         "--units", o.units,
         "Units of a CL file or G-code program that does not say (mm or inch); a G-code program without G20/G21 that "
         "speaks inches, or an APT file without UNITS with FEDRAT/IPM (NX inch parts), is refused until this says")
      ->check(CLI::IsMember({"mm", "inch"}));
  sub.add_option("--input-kind", o.input_kind,
                 "cl, machine (machine-axis G-code), rtcp (tool-tip G-code), klartext (Heidenhain conversational), "
                 "sinumerik (Siemens 840D sl: DEF, R parameters, program flow, frames, CYCLE800, TRAORI), "
                 "auto (a file whose first block is BEGIN PGM is Klartext; DEF, CYCLE800, %_N_ ... mark Sinumerik)")
      ->check(CLI::IsMember({"auto", "cl", "machine", "rtcp", "klartext", "sinumerik"}));
  sub.add_flag("--allow-unterminated", o.allow_unterminated,
               "Post a CL file that ends without FINI/END/END-OF-PATH (refused otherwise: a cut copy)");
  sub.add_option("--msys", o.msys,
                 "NX MSYS: ignore = GOTOs as written, in the MCS, as NX's posts do (default); apply = map them "
                 "through MSYS into the absolute frame (docs/choices.md)")
      ->check(CLI::IsMember({"ignore", "apply"}));
  sub.add_option("--dwell-p", o.dwell_p,
                 "G-code input: a dwell time without a decimal point (G4 P, G82/G89 P) is ms (Fanuc, Haas) or s "
                 "(LinuxCNC); auto reads 100 and more as ms and refuses 1 to 99 (docs/choices.md)")
      ->check(CLI::IsMember({"auto", "ms", "s"}));
  sub.add_option("--arc-centre", o.arc_centre,
                 "G-code input: what I J K of G2/G3 give: incremental = the vector from the start to the centre "
                 "(RS274, Fanuc, Haas; default), centre-to-start = the vector from the centre to the start (some NX "
                 "posts), absolute = the centre's coordinates (as G90.1); an arc that does not fit is refused, "
                 "naming the readings it fits")
      ->check(CLI::IsMember({"incremental", "centre-to-start", "absolute"}));
  add_choice(sub, "--tool-words", o.tool_words,
             "G-code input, T01 T02 M06: one = refused (default); load-next = T01 loaded, T02 pre-selected (Mazak)",
             {"one", "load-next"});
  add_choice(sub, "--integer-words", o.integer_words,
             "G-code input, X20: units; increments = 0.001 mm, 0.0001 in (Fanuc DPI=0); auto (default) = units, "
             "refused beside whole numbers with a point (X20.): docs/choices.md",
             {"auto", "units", "increments"});
  sub.add_option("--work-offsets", o.work_offsets,
                 "G-code input: the values of the work offsets G54 .. G59.3, G54.1 P1 .. P300 (TOML, or a LinuxCNC "
                 "var file: 5221 .. 5389; docs/choices.md, G-code input): a program that moves in several is "
                 "posted in the frame of its first, the others shifted by their values; without it a second offset "
                 "is refused")
      ->check(CLI::ExistingFile);
  sub.add_option("--subprogram-dir", o.subprogram_dir,
                 "G-code input: the directory where M98 P<n> (O<n>.nc, <n>.nc, ...) and o<name> call (name.ngc) find "
                 "a subprogram the program's file does not hold, before the program's own directory; a "
                 "subprogram found nowhere is refused")
      ->check(CLI::ExistingDirectory);
}

Vec3d workpiece_origin_mm(const JobOptions& o) {
  if (o.workpiece_origin.empty()) return Vec3d::Zero();
  std::string s = o.workpiece_origin;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  Vec3d v;
  if (!(in >> v.x() >> v.y() >> v.z()) || !(in >> std::ws).eof() || !v.allFinite() ||
      v.cwiseAbs().maxCoeff() > kMaxWorkpieceOriginMm)
    throw UsageError(fmt::format("--workpiece-origin: expected X,Y,Z in mm, each finite and within +-{:g} mm, got '{}'",
                                 kMaxWorkpieceOriginMm, terminal_text(o.workpiece_origin)));
  return v;
}

LoadedJob load_job(const JobOptions& o) {
  LoadedJob job;
  job.machine = machines::load_as<Machine>(o.machine);
  job.setup.tool_length_mm = o.tool_length_mm;
  job.setup.workpiece_origin_mm = workpiece_origin_mm(o);
  return job;
}

cl::ReaderOptions reader_options(const JobOptions& o) {
  cl::ReaderOptions ro;
  ro.default_inch = o.units == "inch";
  ro.units_given = !o.units.empty();
  ro.allow_unterminated = o.allow_unterminated;
  ro.msys = o.msys == "apply" ? cl::ReaderOptions::Msys::apply : cl::ReaderOptions::Msys::ignore;
  ro.integer_dwell = o.dwell_p == "ms"  ? cl::IntegerDwell::milliseconds
                     : o.dwell_p == "s" ? cl::IntegerDwell::seconds
                                        : cl::IntegerDwell::automatic;
  ro.arc_centre = o.arc_centre == "centre-to-start" ? cl::ArcCentre::centre_to_start
                  : o.arc_centre == "absolute"      ? cl::ArcCentre::absolute
                                                    : cl::ArcCentre::incremental;
  ro.tool_words = o.tool_words == "load-next" ? cl::ToolWords::load_next : cl::ToolWords::one;
  ro.integer_words = o.integer_words == "units"        ? cl::IntegerWords::units
                     : o.integer_words == "increments" ? cl::IntegerWords::increments
                                                       : cl::IntegerWords::automatic;
  if (!o.work_offsets.empty())
    ro.work_offsets = std::make_shared<const gcode::WorkOffsetTable>(gcode::load_work_offsets(o.work_offsets));
  ro.subprogram_dir = o.subprogram_dir;
  return ro;
}

std::unique_ptr<cl::Reader> open_cl_reader(std::istream& in, const std::string& name, const JobOptions& o,
                                           const LoadedJob& job) {
  return ncpost::open_cl_reader(in, name, input_kind_named(o.input_kind), reader_options(o), job.machine, job.setup);
}

}  // namespace ncpost::cli
