// SPDX-License-Identifier: Apache-2.0
// Acceptance against a real peer: LinuxCNC's xyzac-trt kinematics.
//
// `linuxcnc_impeller-7bl-xyzac.ngc` is CAM output for LinuxCNC with TCP on (M428): X Y Z are the
// tool tip in the table frame, A and C the rotary commands. For every motion, the joint X Y Z
// that LinuxCNC's published inverse kinematics computes from the programmed world position must
// equal what ncpost computes from its CL (our reader + kinematics::linear_for with the programmed
// angles, and kinematics::solve from the CL point alone), for both of LinuxCNC's rotary direction
// conventions (HAL pin `conventional-directions` 0 and 1).
//
// Oracle: LinuxCNC src/emc/kinematics/trtfuncs.c (xyzacKinematicsInverse) and trtfuncs_math.h
// (the `con` sign), restated here in our own form. Parameters (also in
// machines/linuxcnc-xyzac-trt.toml): x/y/z-rot-point = 10, 20, 30; y-offset = 5; z-offset = 15;
// tool-offset = 0. With s = +1 for conventional-directions = 1 and s = -1 otherwise (the
// default), p = world - rot_point:
//   Jx = cos C·px + s·sin C·py + xr
//   Jy = cos A·(−s·sin C·px + cos C·py − dy) + s·sin A·(pz − dz) + dy + yr
//   Jz = sin A·(sin C·px − s·cos C·py + s·dy) + cos A·(pz − dz) + dz + zr
// and the tool axis in world coordinates (the Z joint column of the forward map):
//   u = (sin C·sin A, −s·cos C·sin A, cos A)
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;

namespace {

struct TrtParams {
  double x_rot = 10, y_rot = 20, z_rot = 30;
  double y_offset = 5, z_offset = 15;
  bool conventional = false;
};

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Vec3d linuxcnc_xyzac_joints(const TrtParams& k, const Vec3d& world, double a_deg, double c_deg) {
  const double s = k.conventional ? 1.0 : -1.0;
  const double sa = std::sin(a_deg * kDeg), ca = std::cos(a_deg * kDeg);
  const double sc = std::sin(c_deg * kDeg), cc = std::cos(c_deg * kDeg);
  const double px = world.x() - k.x_rot, py = world.y() - k.y_rot, pz = world.z() - k.z_rot;
  const double dy = k.y_offset, dz = k.z_offset;
  return {cc * px + s * sc * py + k.x_rot, ca * (-s * sc * px + cc * py - dy) + s * sa * (pz - dz) + dy + k.y_rot,
          sa * (sc * px - s * cc * py + s * dy) + ca * (pz - dz) + dz + k.z_rot};
}

Vec3d linuxcnc_xyzac_tool_axis(const TrtParams& k, double a_deg, double c_deg) {
  const double s = k.conventional ? 1.0 : -1.0;
  const double sa = std::sin(a_deg * kDeg), ca = std::cos(a_deg * kDeg);
  const double sc = std::sin(c_deg * kDeg), cc = std::cos(c_deg * kDeg);
  return {sc * sa, -s * cc * sa, ca};
}

/// The programmed motions of the file, read independently of ncpost's parser: every line that
/// starts with G0/G1 carries X Y Z A C words (or keeps the previous values).
struct ProgrammedMotion {
  Vec3d world = Vec3d::Zero();
  double a_deg = 0, c_deg = 0;
  int line = 0;
};

std::vector<ProgrammedMotion> read_motions_independently(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::vector<ProgrammedMotion> out;
  ProgrammedMotion current;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("G0", 0) != 0 && line.rfind("G1", 0) != 0) continue;
    for (std::size_t i = 2; i < line.size(); ++i) {
      const char c = line[i];
      if (c == ' ') continue;
      char* end = nullptr;
      const double v = std::strtod(line.c_str() + i + 1, &end);
      switch (c) {
        case 'X':
          current.world.x() = v;
          break;
        case 'Y':
          current.world.y() = v;
          break;
        case 'Z':
          current.world.z() = v;
          break;
        case 'A':
          current.a_deg = v;
          break;
        case 'C':
          current.c_deg = v;
          break;
        default:
          break;  // F
      }
      i = static_cast<std::size_t>(end - line.c_str()) - 1;
    }
    current.line = number;
    out.push_back(current);
  }
  return out;
}

Machine machine_variant(bool conventional) {
  const std::string path = NCPOST_SOURCE_DIR "/machines/linuxcnc-xyzac-trt.toml";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  if (conventional) {
    // the ISO sense: both table directions negated
    for (auto [from, to] : {std::pair<std::string, std::string>{"direction = [1, 0, 0]", "direction = [-1, 0, 0]"},
                            {"direction = [0, 0, 1]", "direction = [0, 0, -1]"}}) {
      const auto at = s.find(from);
      REQUIRE(at != std::string::npos);
      s.replace(at, from.size(), to);
    }
  }
  return parse_machine(s, path);
}

double wrap(double a) { return std::remainder(a, 2.0 * kPi); }

}  // namespace

TEST_CASE("LinuxCNC peer: impeller (TCP on) gives LinuxCNC's xyzac-trt joints, both conventions") {
  const std::string file = NCPOST_SOURCE_DIR "/tests/data/real/linuxcnc_impeller-7bl-xyzac.ngc";
  const auto programmed = read_motions_independently(file);
  REQUIRE(programmed.size() > 4000);
  for (const bool conventional : {false, true}) {
    INFO("conventional-directions = " << conventional);
    TrtParams k;
    k.conventional = conventional;
    const Machine m = machine_variant(conventional);
    REQUIRE(m.rotary(0).letter == 'A');
    REQUIRE(m.rotary(1).letter == 'C');
    const Setup setup;  // W = the table frame with its origin at the origin of M (G54 = 0)
    auto reader = gcode::open_gcode(file, m, setup);  // auto: M428 switches RTCP on
    std::size_t n = 0;
    double max_joint_dev = 0, max_axis_dev = 0, max_ik_dev = 0, max_angle_dev = 0;
    int inverse_time = 0;
    AxisPosition previous = home_of(m);
    while (auto record = reader->next()) {
      const auto* motion = std::get_if<cl::Motion>(&*record);
      if (!motion) continue;
      REQUIRE(n < programmed.size());
      const ProgrammedMotion& p = programmed[n++];
      REQUIRE(motion->where.line == p.line);
      REQUIRE(motion->rotary_rad);
      // the CL tip is the programmed world position (RTCP)
      REQUIRE((motion->point.tip_mm - p.world).norm() < 1e-12);
      // joints: ncpost's inverse kinematics with the programmed angles vs LinuxCNC's
      const Vec3d ours = linear_for(m, *motion->rotary_rad, motion->point.tip_mm, setup);
      const Vec3d peer = linuxcnc_xyzac_joints(k, p.world, p.a_deg, p.c_deg);
      max_joint_dev = std::max(max_joint_dev, (ours - peer).cwiseAbs().maxCoeff());
      // tool axis of the CL point vs LinuxCNC's forward map
      max_axis_dev =
          std::max(max_axis_dev, (motion->point.axis - linuxcnc_xyzac_tool_axis(k, p.a_deg, p.c_deg)).norm());
      // closed-form IK from the CL point alone (nearest the programmed angles, as a post would
      // keep continuity) reaches the same joints
      AxisPosition near = home_of(m);
      near.rotary_rad = *motion->rotary_rad;
      const IkOutcome ik = solve(m, motion->point, setup, near);
      REQUIRE(ik.ok());
      max_ik_dev = std::max(max_ik_dev, (ik.position->linear_mm - peer).cwiseAbs().maxCoeff());
      for (int j = 0; j < 2; ++j)
        max_angle_dev = std::max(max_angle_dev, std::abs(wrap(ik.position->rotary_rad[j] - (*motion->rotary_rad)[j])));
      if (motion->inverse_time) {
        ++inverse_time;
        REQUIRE(motion->feed);
        CHECK(*motion->feed > 0);
      }
      previous = *ik.position;
    }
    CHECK(n == programmed.size());
    CHECK(inverse_time > 4000);
    std::cout << "LinuxCNC xyzac-trt peer (conventional-directions=" << conventional << "): " << n
              << " motions, max joint deviation " << max_joint_dev << " mm (programmed angles), " << max_ik_dev
              << " mm (IK from CL), max tool-axis deviation " << max_axis_dev << ", max angle deviation "
              << max_angle_dev << " rad\n";
    CHECK(max_joint_dev < 1e-6);
    CHECK(max_axis_dev < 1e-12);
    CHECK(max_ik_dev < 1e-6);
  }
}

TEST_CASE("LinuxCNC peer: the boat xyzbc program parses completely") {
  const std::string file = NCPOST_SOURCE_DIR "/tests/data/real/linuxcnc_boat-xyzbc.ngc";
  // expected motions, counted independently: lines with an axis word outside (...) and ; comments
  std::ifstream in(file);
  std::string line;
  std::size_t expected = 0, expected_inverse_time = 0;
  bool g93 = false;
  while (std::getline(in, line)) {
    std::string code;
    bool in_comment = false;
    for (char c : line) {
      if (c == ';' && !in_comment) break;
      if (c == '(') in_comment = true;
      if (!in_comment) code += c;
      if (c == ')') in_comment = false;
    }
    if (code.find("G93") != std::string::npos) g93 = true;
    if (code.find("G94") != std::string::npos) g93 = false;
    if (code.find("M30") != std::string::npos) break;
    if (code.find_first_of("XYZBC") != std::string::npos && code.find('%') == std::string::npos) {
      ++expected;
      if (g93 && code.find('F') != std::string::npos) ++expected_inverse_time;
    }
  }
  const Machine m = load_machine(NCPOST_SOURCE_DIR "/machines/haas-umc750.toml");  // a B/C table
  gcode::GcodeReaderOptions parse_only;  // B reaches -38.8 deg, beyond the UMC-750's -35: a post refuses it (exit 3)
  parse_only.check_limits = false;
  auto reader = gcode::open_gcode(file, m, Setup{}, parse_only);
  std::size_t motions = 0, inverse_time = 0, comments = 0, ends = 0, tools = 0;
  while (auto record = reader->next()) {
    if (const auto* mo = std::get_if<cl::Motion>(&*record)) {
      ++motions;
      if (mo->inverse_time) ++inverse_time;
      REQUIRE(mo->point.tip_mm.allFinite());
      CHECK(std::abs(mo->point.axis.norm() - 1.0) < 1e-12);
    }
    if (std::holds_alternative<cl::Comment>(*record)) ++comments;
    if (std::holds_alternative<cl::End>(*record)) ++ends;
    if (std::holds_alternative<cl::ToolChange>(*record)) ++tools;
  }
  CHECK(motions == expected);
  CHECK(inverse_time == expected_inverse_time);
  CHECK(motions > 1700);
  CHECK(comments >= 6);
  CHECK(ends == 1);
  CHECK(tools == 1);
  const auto notices = reader->take_notices();
  for (const auto& n : notices) std::cout << "boat notice: " << n << "\n";
}

TEST_CASE("NX post output for the Haas UMC-750 (G234, G20, G28, arcs) reads completely") {
  const Machine m = load_machine(NCPOST_SOURCE_DIR "/machines/haas-umc750.toml");
  for (const char* name : {"nx_PostProcessed_SimpleMillPlane.txt", "nx_PostProcessed_Variable_Axis.txt",
                           "nx_PostProcessed_Zig_Zag_Smoothed.txt"}) {
    INFO(name);
    const std::string file = std::string(NCPOST_SOURCE_DIR "/tests/data/real/") + name;
    // lines that move, counted independently: an axis word outside comments, not G28, before M30
    std::set<int> expected_lines;
    bool started = false;
    std::set<int> arc_lines;
    {
      std::ifstream in(file);
      std::string line;
      int number = 0;
      while (std::getline(in, line)) {
        ++number;
        std::string code;
        bool in_comment = false;
        for (char c : line) {
          if (c == '(') in_comment = true;
          if (!in_comment) code += c;
          if (c == ')') in_comment = false;
        }
        if (code.find("M30") != std::string::npos) break;
        if (code.find("G28") != std::string::npos) continue;
        bool axis = false;
        for (std::size_t i = 0; i < code.size(); ++i)
          if (std::string("XYZBC").find(code[i]) != std::string::npos && i + 1 < code.size() &&
              (std::isdigit(static_cast<unsigned char>(code[i + 1])) || code[i + 1] == '-' || code[i + 1] == '.'))
            axis = true;
        // G53 (machine coordinates) before the program's first position moves nothing: where the
        // tool stands is not known yet; after it, a G53 retract is a motion
        const bool g53 = code.find("G53") != std::string::npos;
        if (axis && g53 && !started) continue;
        if (axis && !g53) started = true;
        if (axis) expected_lines.insert(number);
        if (code.find("G02") != std::string::npos || code.find("G03") != std::string::npos) arc_lines.insert(number);
      }
    }
    auto reader = gcode::open_gcode(file, m, Setup{});
    std::set<int> motion_lines;
    std::map<int, int> per_line;
    int ends = 0, tools = 0;
    while (auto record = reader->next()) {
      if (const auto* mo = std::get_if<cl::Motion>(&*record)) {
        motion_lines.insert(mo->where.line);
        ++per_line[mo->where.line];
        REQUIRE(mo->point.tip_mm.allFinite());
      }
      if (std::holds_alternative<cl::End>(*record)) ++ends;
      if (std::holds_alternative<cl::ToolChange>(*record)) ++tools;
    }
    CHECK(motion_lines == expected_lines);
    for (const auto& [line, count] : per_line)
      if (!arc_lines.count(line)) CHECK(count == 1);  // one motion per block, arcs aside
    CHECK(ends == 1);
    CHECK(tools == 1);
  }
}
