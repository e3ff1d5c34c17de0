// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/cl_input.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string_view>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/klartext/klartext_block.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"
#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"
#include "read/char_scan.hpp"

namespace ncpost {
namespace {

/// The first 4 KiB of `in`, the stream put back where it was.
std::string read_head(std::istream& in) {
  const std::istream::pos_type start = in.tellg();
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  in.clear();
  in.seekg(start);
  return head;
}

/// --input-kind machine|rtcp on a Klartext or Sinumerik program: refused, naming the language.
void refuse_other_language(std::istream& in, const std::string& name, InputKind kind) {
  const bool seekable = in.tellg() != std::istream::pos_type(-1);
  if ((kind != InputKind::machine && kind != InputKind::rtcp) || !seekable) return;
  const char* asked = kind == InputKind::machine ? "machine" : "rtcp";
  if (klartext::looks_like_klartext(read_head(in)))
    throw InputError({name, 1, 0}, fmt::format("a Heidenhain Klartext program (BEGIN PGM), read as G-code as "
                                               "--input-kind {} asks: use --input-kind klartext (or auto)",
                                               asked));
  if (sinumerik::looks_like_sinumerik(read_head(in)))
    throw InputError({name, 1, 0}, fmt::format("a Sinumerik program (DEF, CYCLE800, %_N_ ...), read as plain G-code as "
                                               "--input-kind {} asks: use --input-kind sinumerik (or auto)",
                                               asked));
}

/// Whether the file's name ends in ".ngc" (RS274NGC's, LinuxCNC's program extension), ".gcode" or
/// ".tap" (grbl's and Mach3's, as the hobby CAM posts name them), any case: controls that read a
/// coordinate without a decimal point in whole units.
bool has_units_extension(const std::string& name) {
  const std::string u = upper_of(name);
  return u.ends_with(".NGC") || u.ends_with(".GCODE") || u.ends_with(".TAP");
}

/// The G-code reader's options from the post's.
gcode::GcodeReaderOptions gcode_options(
    const cl::ReaderOptions& options, InputKind kind,
    const std::function<std::optional<ToolPoseT<double>>(const AxisPosition&, std::string*)>& word_forward) {
  gcode::GcodeReaderOptions go;
  go.default_inch = options.default_inch;
  go.units_given = options.units_given;
  go.integer_dwell = options.integer_dwell;
  go.arc_centre = options.arc_centre;
  go.tool_words = options.tool_words;
  go.integer_words = options.integer_words;
  go.work_offsets = options.work_offsets;
  go.control = options.control;
  go.tool_offset_writes = options.tool_offset_writes;
  go.subprogram_dir = options.subprogram_dir;
  go.power_on = options.power_on;
  go.power_on_source = options.power_on_source;
  go.circles = !word_forward;  // planar arcs reach the post (and preview) as CIRCLE records do from CL files
  go.word_forward = word_forward;
  go.kind = kind == InputKind::machine ? gcode::InputKind::machine
            : kind == InputKind::rtcp  ? gcode::InputKind::rtcp
                                       : gcode::InputKind::automatic;
  return go;
}

}  // namespace

InputKind input_kind_named(const std::string& name) {
  if (name == "auto") return InputKind::automatic;
  if (name == "cl") return InputKind::cl;
  if (name == "machine") return InputKind::machine;
  if (name == "rtcp") return InputKind::rtcp;
  if (name == "klartext") return InputKind::klartext;
  if (name == "sinumerik") return InputKind::sinumerik;
  throw std::invalid_argument("unknown input kind '" + name + "' (auto, cl, machine, rtcp, klartext, sinumerik)");
}

std::unique_ptr<cl::Reader> open_cl_reader(std::istream& in, const std::string& name, InputKind kind,
                                           const cl::ReaderOptions& options, const Machine& machine,
                                           const Setup& setup) {
  return open_cl_reader(in, name, kind, options, machine, setup, {});
}

std::unique_ptr<cl::Reader> open_cl_reader(
    std::istream& in, const std::string& name, InputKind kind, const cl::ReaderOptions& options, const Machine& machine,
    const Setup& setup,
    const std::function<std::optional<ToolPoseT<double>>(const AxisPosition&, std::string*)>& word_forward) {
  if (word_forward && kind == InputKind::rtcp)
    throw std::invalid_argument("open_cl_reader: a word machine reads no RTCP programs");
  bool apt = kind == InputKind::cl;
  bool klartext = kind == InputKind::klartext;
  bool sinumerik = kind == InputKind::sinumerik;
  refuse_other_language(in, name, kind);
  if (kind == InputKind::automatic) {
    const std::string head = read_head(in);
    std::string_view body(head);
    if (body.rfind("\xEF\xBB\xBF", 0) == 0) body.remove_prefix(3);
    if (body.find_first_not_of(" \t\r\n") == std::string_view::npos)
      throw InputError({name, 0, 0},
                       "the input is empty (no CL statements or G-code blocks); expected a CL file or a program");
    klartext = klartext::looks_like_klartext(body);
    apt = !klartext && cl::looks_like_apt(head);
    sinumerik = !klartext && !apt && sinumerik::looks_like_sinumerik(body);
  }
  if (apt) return std::make_unique<cl::AptReader>(in, name, options);
  if (klartext) {
    if (word_forward)
      throw InputError({name, 0, 0},
                       fmt::format("a Heidenhain Klartext program on the machine {}, whose words {} are no "
                                   "Cartesian frame: not supported (post the CL data)",
                                   machine.name, axis_letters(machine)));
    klartext::ReaderOptions ko;
    ko.allow_unterminated = options.allow_unterminated;
    ko.tool_table = options.tool_table;
    return std::make_unique<klartext::KlartextReader>(in, name, machine, setup, ko);
  }
  if (sinumerik && word_forward)
    throw InputError({name, 0, 0}, fmt::format("a Sinumerik program on the machine {}, whose words {} are no Cartesian "
                                               "frame: not supported (post the CL data)",
                                               machine.name, axis_letters(machine)));
  gcode::GcodeReaderOptions go = gcode_options(options, kind, word_forward);
  if (go.integer_words == cl::IntegerWords::automatic && has_units_extension(name))
    go.integer_words = cl::IntegerWords::units;  // .ngc (LinuxCNC), .gcode / .tap (grbl, Mach3): whole units
  if (sinumerik) {
    sinumerik::ReaderOptions so;
    so.gcode = go;
    so.gcode.kind = gcode::InputKind::automatic;       // the program's TRAORI/TRAFOOF and CYCLE800 say
    so.gcode.integer_words = cl::IntegerWords::units;  // Sinumerik reads whole units (its lines are translated)
    return std::make_unique<sinumerik::SinumerikReader>(in, name, machine, setup, so);
  }
  return std::make_unique<gcode::GcodeClReader>(in, name, machine, setup, go);
}

std::string axis_letters(const Machine& machine) {
  std::string s;
  for (const Axis& a : machine.axes) s += a.letter;
  return s;
}

}  // namespace ncpost
