#include "input_options.hpp"

#include <sstream>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/apt_reader.hpp"
#include "ncpost/postproc/gcode_cl_reader.hpp"

namespace ncpost::cli {

void add_job_options(CLI::App& sub, JobOptions& o) {
  sub.add_option("--machine", o.machine, "Machine definition (TOML)")->required()->check(CLI::ExistingFile);
  sub.add_option("--workpiece-origin", o.workpiece_origin, "Origin of the workpiece frame W in M at home: X,Y,Z (mm)");
  sub.add_option("--tool-length", o.tool_length_mm, "Tool length (mm): places head pivots");
  sub.add_option("--units", o.units, "Units of a CL file that does not say (mm or inch)")->check(CLI::IsMember({"mm", "inch"}));
  sub.add_option("--input-kind", o.input_kind, "cl, machine (machine-axis G-code), rtcp (tool-tip G-code), auto")
      ->check(CLI::IsMember({"auto", "cl", "machine", "rtcp"}));
}

Vec3d workpiece_origin_mm(const JobOptions& o) {
  if (o.workpiece_origin.empty()) return Vec3d::Zero();
  std::string s = o.workpiece_origin;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  Vec3d v;
  if (!(in >> v.x() >> v.y() >> v.z()) || !(in >> std::ws).eof() || !v.allFinite())
    throw UsageError("--workpiece-origin: expected X,Y,Z in mm, got '" + o.workpiece_origin + "'");
  return v;
}

LoadedJob load_job(const JobOptions& o) {
  LoadedJob job;
  job.machine = load_machine(o.machine);
  job.setup.tool_length_mm = o.tool_length_mm;
  job.setup.workpiece_origin_mm = workpiece_origin_mm(o);
  return job;
}

std::unique_ptr<cl::Reader> open_cl_reader(std::istream& in, const std::string& name, const JobOptions& o,
                                           const LoadedJob& job) {
  cl::ReaderOptions ro;
  ro.default_inch = o.units == "inch";
  std::string kind = o.input_kind;
  if (kind == "auto") {
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    in.clear();
    in.seekg(0);
    kind = cl::looks_like_apt(head) ? "cl" : "gcode";
  }
  if (kind == "cl") return std::make_unique<cl::AptReader>(in, name, ro);
  gcode::GcodeReaderOptions go;
  go.default_inch = ro.default_inch;
  go.circles = true;  // planar arcs reach the post (and preview) as CIRCLE records do from CL files
  go.kind = o.input_kind == "machine" ? gcode::InputKind::machine
          : o.input_kind == "rtcp"    ? gcode::InputKind::rtcp
                                      : gcode::InputKind::automatic;
  return std::make_unique<gcode::GcodeClReader>(in, name, job.machine, job.setup, go);
}

std::string axis_letters(const Machine& m) {
  std::string s;
  for (const Axis& a : m.axes) s += a.letter;
  return s;
}

}  // namespace ncpost::cli
