// SPDX-License-Identifier: Apache-2.0
// ncpost export: the model as compensation data for the control (issue 17; docs/cli.md "export"):
// LinuxCNC's COMP_FILE, a SINUMERIK LEC table, an ISG-kernel / Beckhoff TwinCAT CNC leadscrew error
// compensation list, the machine file with the location errors of the rotary axes applied (ncpost's own
// kinematics calibration), or those errors as a control's kinematics: LinuxCNC's trt kinematics parameters,
// a SINUMERIK CYCLE800 swivel data record (issue 25 item 2). What a format cannot hold is listed on stderr
// and in the file.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "commands.hpp"
#include "file_checks.hpp"
#include "machine_kind.hpp"
#include "model_input.hpp"
#include "ncpost/compensation/export_cycle800.hpp"
#include "ncpost/compensation/export_heidenhain.hpp"
#include "ncpost/compensation/export_isg.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/export_linuxcnc_trt.hpp"
#include "ncpost/compensation/export_machine.hpp"
#include "ncpost/compensation/export_siemens.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/version.hpp"

namespace ncpost::cli {

namespace {

/// The formats --format takes: name, what it writes (the option's help), whether it needs --machine,
/// whether it is a one-axis table (takes --axis).
struct ExportFormat {
  const char* name;
  const char* help;
  bool needs_machine;
  bool one_axis;
};
constexpr ExportFormat kFormats[] = {
    {"linuxcnc", "LinuxCNC COMP_FILE (type 1) of one axis", false, true},
    {"siemens", "SINUMERIK LEC table ($AA_ENC_COMP) of one axis", false, true},
    {"isg", "ISG-kernel / Beckhoff TwinCAT CNC leadscrew error compensation list (kw.ssfk, bilateral) of one axis",
     false, true},
    {"machine",
     "the machine file with the rotary axes' location errors applied (TRR-XY: the model's 30 parameters "
     "as the machine's calibration)",
     true, false},
    {"linuxcnc-trt",
     "the rotary axes' line offsets as LinuxCNC xyzac-trt / xyzbc-trt kinematics parameters (HAL "
     "setp lines; tilts listed as left out with their effect in um)",
     true, false},
    {"siemens-cycle800",
     "the rotary axes' lines (offsets and tilts) as a SINUMERIK CYCLE800 swivel data record, "
     "kinematic type P ($TC_CARR)",
     true, false},
    {"heidenhain",
     "the rotary axes' positions and orientations as the Heidenhain kinematics entries KinematicsOpt "
     "adjusts (a table to enter)",
     true, false},
};

const ExportFormat* find_format(const std::string& name) {
  for (const ExportFormat& f : kFormats)
    if (name == f.name) return &f;
  return nullptr;
}

std::string format_names() {
  std::vector<std::string> names;
  for (const ExportFormat& f : kFormats) names.push_back(f.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

std::string format_help() {
  std::vector<std::string> lines;
  for (const ExportFormat& f : kFormats) lines.push_back(fmt::format("{}: {}", f.name, f.help));
  return fmt::format("{}", fmt::join(lines, "; "));
}

/// A three-axis machine X Y Z for a model given without --machine (its axes say XYZ).
Machine three_axis_machine(const std::string& name) {
  Machine m;
  m.name = name;
  m.chain = "w b X Y Z t";
  for (char c : {'X', 'Y', 'Z'}) {
    Axis a;
    a.letter = c;
    a.direction = Vec3d::Unit(c - 'X');
    m.axes.push_back(a);
  }
  m.tool_side = {0, 1, 2};
  return m;
}

/// The letter of `--axis`, or the one axis the model has a table for.
char chosen_axis(const ExportArgs& args, const comp::MachineModel& model) {
  if (!args.axis.empty()) {
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(args.axis[0])));
    if (args.axis.size() != 1 || std::string("XYZABC").find(letter) == std::string::npos)
      throw UsageError(fmt::format("--axis: expected an axis letter X, Y, Z, A, B or C, got '{}'", args.axis));
    return letter;  // an axis the model's machine lacks: refused naming the model (describe_axis_export)
  }
  std::string candidates;
  for (const Axis& a : model.machine().axes) {
    try {
      (void)comp::describe_axis_export(model, a.letter);
      candidates += a.letter;
    } catch (const comp::ExportRefusal&) {
    }
  }
  if (candidates.size() == 1) return candidates[0];
  if (candidates.empty())
    throw InputError({args.model, 0, 0},
                     "the model has no positioning error and no reversal of any axis: there is "
                     "nothing for a one-axis table to hold (--format machine writes location errors)");
  throw UsageError(
      fmt::format("--axis is needed: the model has tables for the axes {} (one file per axis)", candidates));
}

void print_left_out(const std::vector<std::string>& left_out, const std::string& what) {
  if (left_out.empty()) return;
  fmt::print(stderr,
             "ncpost: warning: {} cannot hold {} term(s) of the model; they are NOT compensated by it "
             "(also listed in the file):\n",
             what, left_out.size());
  for (const std::string& s : left_out) fmt::print(stderr, "  {}\n", s);
}

/// The terms a kinematics record leaves out, with their effect on the workpiece (kinematics_left_out.hpp).
void print_left_out_effects(const comp::LeftOut& left, const std::string& what) {
  if (left.terms.empty()) return;
  fmt::print(stderr,
             "ncpost: warning: {} cannot hold {} term(s) of the model; they are NOT compensated by it "
             "(also listed in the file, with the poses):\n",
             what, left.terms.size());
  for (const comp::LeftOutTerm& t : left.terms)
    fmt::print(stderr, "  {:<10} up to {:.3f} um at the workpiece  ({})\n", t.term, t.effect_um, t.why);
  fmt::print(stderr, "  all together: up to {:.3f} um at {} poses of the travel\n", left.together_um, left.poses);
}

/// Where the travel reaches beyond a table's nodes (end values held): never silent (issue 25 item 4).
void print_held_beyond(const comp::AxisExport& axis) {
  for (const std::string& s : axis.held_beyond)
    fmt::print(stderr, "ncpost: note: beyond the measured travel: {} (also in the file)\n", s);
}

/// The file's own round trip (landing_check.hpp), in µm or µrad.
void print_landing(const comp::AxisExport& axis, const comp::LandingCheck& check) {
  const double to_micro = axis.rotary ? 1e6 : 1e3;
  fmt::print(
      "round trip: the axis lands within {:.4f} {} of the commanded position at {} positions (model alone: {:.3f})\n",
      check.with_file * to_micro, axis.rotary ? "µrad" : "µm", check.positions, check.model_only * to_micro);
}

/// The format of --format, checked against --axis.
const ExportFormat& checked_format(const ExportArgs& args) {
  const ExportFormat* format = find_format(args.format);
  if (format == nullptr)
    throw UsageError(fmt::format("--format: expected one of {}, got '{}'", format_names(), args.format));
  if (!format->one_axis && !args.axis.empty())
    throw UsageError(fmt::format("--axis {}: --format {} writes every rotary axis of the machine, not one axis's table",
                                 args.axis, args.format));
  return *format;
}

/// The machine of --machine, or without it the three-axis machine of the model's axes; `file` gets
/// the model read against it.
Machine export_machine(const ExportArgs& args, const ExportFormat& format, comp::ModelFile& file) {
  if (!args.machine.empty()) {
    Machine machine = machines::load_as<Machine>(args.machine);
    file = read_model_for(args.model, machine, args.force);
    return machine;
  }
  file = comp::read_model_json(args.model, nullptr);
  if (format.needs_machine)
    throw UsageError(
        fmt::format("--format {} needs --machine M.toml: the machine whose rotary axes the model "
                    "locates",
                    args.format));
  if (!file.axes.empty() && file.axes != "XYZ")
    throw UsageError(
        fmt::format("--machine M.toml is needed: the model's machine has the axes {} (rotary axes "
                    "need their directions)",
                    file.axes));
  Machine machine = three_axis_machine(file.machine.empty() ? "three-axis" : file.machine);
  file = read_model_for(args.model, machine, args.force);  // every name checked against X Y Z
  return machine;
}

/// --format machine: the machine file with the location errors applied.
int export_machine_file(const ExportArgs& args, const comp::MachineModel& model, const comp::ExportSource& source) {
  const Machine& machine = model.machine();
  const comp::MachineExport out = comp::corrected_machine(model);
  std::vector<std::string> notes{
      fmt::format("ncpost {} export --format machine: '{}' with the location errors of model '{}' applied",
                  source.version, machine.name, args.model),
      fmt::format("(from '{}'), as a control's kinematics calibration: read it NOMINALLY (post without --model);",
                  args.machine),
      "the name differs from the original's so that this model is not applied a second time.",
      fmt::format("Applied: {}", fmt::join(out.applied, ", "))};
  if (out.left_out.empty()) {
    notes.push_back("Left out: nothing");
  } else {
    notes.push_back(fmt::format("Left out (NOT in this machine file, {} term(s)):", out.left_out.size()));
    for (const std::string& s : out.left_out) notes.push_back("  " + s);
  }
  write_file_atomically(args.output, comp::format_machine_toml(out.corrected, notes));
  print_left_out(out.left_out, "a machine file");
  fmt::print("exported {} location error(s) of '{}' into the machine file '{}' ({})\n", out.applied.size(),
             machine.name, args.output, out.corrected.name);
  return 0;
}

/// The rotary axes' errors as a control's kinematics: linuxcnc-trt, siemens-cycle800, heidenhain.
int export_kinematics(const ExportArgs& args, const comp::MachineModel& model, const comp::ExportSource& source) {
  const Machine& machine = model.machine();
  if (args.format == "linuxcnc-trt") {
    const comp::TrtKinematics k = comp::linuxcnc_trt_kinematics(model);
    write_file_atomically(args.output, comp::format_linuxcnc_trt(k, model, source));
    print_left_out_effects(k.left_out, fmt::format("LinuxCNC's {}", k.module));
    fmt::print("exported {} line offset(s) of '{}' as {} parameters -> {}\n", k.held.size(), machine.name, k.module,
               args.output);
    return 0;
  }
  if (args.format == "siemens-cycle800") {
    const comp::Cycle800Record r = comp::cycle800_record(model);
    write_file_atomically(args.output, comp::format_cycle800(r, model, source));
    print_left_out_effects(r.left_out, "a CYCLE800 swivel data record");
    fmt::print("exported {} location error(s) of '{}' as the CYCLE800 record (type P, axes {} {}) -> {}\n",
               r.held.size(), machine.name, r.axis1, r.axis2, args.output);
    return 0;
  }
  const comp::HeidenhainKinematics k = comp::heidenhain_kinematics(model);
  write_file_atomically(args.output, comp::format_heidenhain(k, model, source));
  print_left_out_effects(k.left_out, "a Heidenhain kinematics description");
  fmt::print("exported {} location error(s) of '{}' as {} Heidenhain kinematics entries (axes {} {}) -> {}\n",
             k.held.size(), machine.name, k.entries.size(), k.axis1, k.axis2, args.output);
  return 0;
}

/// One axis's table: linuxcnc, isg, siemens.
int export_axis_table(const ExportArgs& args, const comp::MachineModel& model, const comp::ExportSource& source) {
  const char letter = chosen_axis(args, model);
  if (args.format == "linuxcnc") {
    const comp::LinuxcncCompTable table = comp::linuxcnc_comp_table(model, letter);
    write_file_atomically(args.output, comp::format_linuxcnc_comp(table, model, source));
    print_left_out(table.axis.left_out, fmt::format("a LinuxCNC compensation file of {}", letter));
    print_held_beyond(table.axis);
    fmt::print("exported {} rows for axis {} (COMP_FILE_TYPE = 1) -> {}\n", table.rows.size(), letter, args.output);
    print_landing(table.axis, table.landing);
    return 0;
  }
  if (args.format == "isg") {
    const comp::IsgLsecTable table = comp::isg_lsec_table(model, letter);
    write_file_atomically(args.output, comp::format_isg_lsec(table, model, source));
    print_left_out(table.axis.left_out, fmt::format("an ISG leadscrew error compensation list of {}", letter));
    print_held_beyond(table.axis);
    fmt::print("exported {} points for axis {} (kw.ssfk, bilateral, 0.1 µm) -> {}\n", table.setpoints.size(), letter,
               args.output);
    print_landing(table.axis, table.landing);
    return 0;
  }
  const comp::SiemensLecTable table = comp::siemens_lec_table(model, letter);
  write_file_atomically(args.output, comp::format_siemens_lec(table, model, source));
  print_left_out(table.axis.left_out, fmt::format("a SINUMERIK LEC table of {}", letter));
  print_held_beyond(table.axis);
  fmt::print("exported {} points for axis {} ($AA_ENC_COMP, step {:.6g}) -> {}\n", table.values.size(), letter,
             table.step, args.output);
  print_landing(table.axis, table.landing);
  return 0;
}

}  // namespace

int export_serial(const ExportArgs& args) {
  std::vector<NamedPath> inputs{{"MODEL", args.model}};
  if (!args.machine.empty()) inputs.push_back({"--machine", args.machine});
  check_files({{"-o", args.output}}, inputs);
  const ExportFormat& format = checked_format(args);
  comp::ModelFile file;
  const Machine machine = export_machine(args, format, file);
  const comp::MachineModel model(machine, file.parameters);
  const comp::ExportSource source{args.model, args.machine, ncpost::version()};
  try {
    if (args.format == "machine") return export_machine_file(args, model, source);
    if (!format.one_axis) return export_kinematics(args, model, source);
    return export_axis_table(args, model, source);
  } catch (const comp::ExportRefusal& e) {
    const bool machine_at_fault = e.source == comp::ExportRefusal::Source::machine && !args.machine.empty();
    throw InputError({machine_at_fault ? args.machine : args.model, 0, 0}, e.what());
  }
}

namespace {

int run_export(const ExportArgs& args) { return export_kind(args).export_model(args); }

}  // namespace

void add_export(CLI::App& app, Action& action) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* sub = app.add_subcommand("export", "Export a model as compensation data for the control");
  sub->add_option("--format", args->format, format_help())->required();
  sub->add_option("--axis", args->axis,
                  "the axis of a one-axis table (linuxcnc, siemens, isg); needed when the model has "
                  "tables for more than one");
  sub->add_option("--machine", args->machine,
                  "machine definition (TOML); needed for rotary axes and --format machine, linuxcnc-trt, "
                  "siemens-cycle800, heidenhain");
  add_model_force_option(*sub, args->force);
  sub->add_option("-o,--output", args->output, "the file to write")->required();
  sub->add_option("model", args->model, "error model JSON (written by identify)")->required();
  sub->footer(
      "Every term of the model acting on the axis that the format cannot hold is listed on stderr and in the file.\n"
      "Example: ncpost export --format linuxcnc --axis X --machine machines/vmcl600.toml -o x.comp model.json");
  sub->callback([&action, args] { action = [args] { return run_export(*args); }; });
}

}  // namespace ncpost::cli
