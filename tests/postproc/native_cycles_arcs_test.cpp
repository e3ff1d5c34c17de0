// SPDX-License-Identifier: Apache-2.0
// CIRCLE records written as G2/G3 (post.hpp `native_arcs`) and CYCLE holes as G81/G83: the arc
// directions of NX's own post on the same files, the same tool path as the point expansion when
// the program is read back, and the cycle words of a Creo drilling file.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/post.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

/// Posts a real APT file on `machine` and returns the program text.
std::string post(const std::string& file, const Machine& m, bool native_arcs, PostSummary* summary = nullptr) {
  std::ifstream in(test::data("real/" + file), std::ios::binary);
  cl::AptReader reader(in, file);
  const std::string out_path = "native_cycles_arcs_test_" + std::to_string(native_arcs) + ".nc";
  {
    AtomicFile out(out_path);
    std::string letters;
    for (const Axis& a : m.axes) letters += a.letter;
    NcWriter writer(out, dialect_named("fanuc"), letters);
    PostOptions o;
    o.native_arcs = native_arcs;
    const PostSummary s = post_program(reader, file, NominalSolver(m, Setup{}), writer, o);
    if (summary) *summary = s;
    out.commit();
  }
  return test::read_text_file(out_path);
}

/// The arc words (2 or 3) of a program, in order; with `min_chord_mm`, arcs shorter than that
/// between start and end are left out.
std::vector<int> arc_directions(const std::string& program) {
  std::vector<int> out;
  static const std::regex word(R"((^|[ N0-9])G0?([23])[ X])");
  std::istringstream lines(program);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, word)) out.push_back(m[2].str()[0] - '0');
  }
  return out;
}

/// Tool-tip path length (W) of a program read back through the nominal kinematics, arcs expanded.
double path_length_mm(const std::string& program, const Machine& m, std::size_t* motions) {
  std::istringstream in(program);
  gcode::GcodeReaderOptions o;
  o.kind = gcode::InputKind::machine;
  gcode::GcodeClReader reader(in, "program", m, Setup{}, o);
  double length = 0.0;
  std::optional<Vec3d> last;
  *motions = 0;
  while (auto r = reader.next()) {
    const auto* mo = std::get_if<cl::Motion>(&*r);
    if (!mo) continue;
    if (last && !mo->rapid) length += (mo->point.tip_mm - *last).norm();
    last = mo->point.tip_mm;
    ++*motions;
  }
  return length;
}

}  // namespace

TEST_CASE("G2/G3 from NX CIRCLE records: NX's own post's directions") {
  const Machine m = load_machine(test::source("machines/haas-umc750.toml"));
  const std::string ours = post("nx_APT_SimpleMillPlane.txt", m, true);
  const std::string theirs = test::read_text_file(test::data("real/nx_PostProcessed_SimpleMillPlane.txt"));
  CHECK(arc_directions(ours) == arc_directions(theirs));
  CHECK(arc_directions(ours) == std::vector<int>{3, 3});
  CHECK_THAT(ours,
             Catch::Contains("G3 X-265.0000 Y164.9997 Z100.0000 I7.5000 J0.0000"));  // NX: G03 X-10.4331 Y6.4961 I.2953

  // Zig-zag: 35 CIRCLE records; NX writes the 0.85-degree one (chord 0.036 mm) as a line, we as an arc
  std::vector<int> zz = arc_directions(post("nx_APT_Zig_Zag_Smoothed.txt", m, true));
  const std::vector<int> nx =
      arc_directions(test::read_text_file(test::data("real/nx_PostProcessed_Zig_Zag_Smoothed.txt")));
  REQUIRE(zz.size() == 35);
  REQUIRE(nx.size() == 34);
  zz.erase(zz.begin() + 2);  // the tiny arc, third in the file
  CHECK(zz == nx);
}

TEST_CASE("G2/G3 output follows the same path as the expanded points (NX and Creo conventions)") {
  // (nx_APT_Project2.txt's helices, CIRCLE/...,TIMES,7, are points: never G2/G3); creo_profilfraesen_2.ncl has
  // clockwise CIRCLEs about (0,0,-1)
  for (const char* file : {"creo_profilfraesen_2.ncl", "creo_schruppen_1.ncl", "nx_APT_Zig_Zag_Smoothed.txt"}) {
    INFO(file);
    const Machine m = load_machine(test::source("machines/haas-umc750.toml"));
    PostSummary with_arcs;
    const std::string native = post(file, m, true, &with_arcs);
    const std::string points = post(file, m, false);
    std::size_t n_native = 0, n_points = 0;
    const double l_native = path_length_mm(native, m, &n_native);
    const double l_points = path_length_mm(points, m, &n_points);
    std::printf("%-28s %zu arcs as G2/G3: path %.3f mm vs points %.3f mm\n", file, with_arcs.arcs_out, l_native,
                l_points);
    CHECK(with_arcs.arcs_out > 0);
    CHECK(std::abs(l_native - l_points) < 1e-4 * l_points);  // a wrong direction goes the other way round
  }
}

TEST_CASE("CYCLE/DEEP as G83 where the hole runs down Z, explicit pecks otherwise") {
  const std::string file = "creo_bohren_1.ncl";  // CYCLE/DEEP, DEPTH 3.5, STEP 1, MMPM 50, CLEAR 1; holes at z 0.5
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  PostSummary s;
  const std::string program = post(file, m, true, &s);
  CHECK(s.cycles_out == 2);
  // no retract plane in the record: back to the R plane (G99), the second hole continues the cycle
  CHECK_THAT(program, Catch::Contains("Z1.5000\nG94 G99 G83 X-7.2291 Y-23.0000 Z-3.0000 R1.5000 Q1.0000 F50.0\n"
                                      "X-16.7804\n"));
  CHECK_THAT(program, Catch::Contains("G80"));
  // Sinumerik has no G83: the pecks are written as moves (depth reached at Z-3)
  std::ifstream in(test::data("real/" + file), std::ios::binary);
  cl::AptReader reader(in, file);
  {
    AtomicFile out("native_cycles_sinumerik.nc");
    NcWriter writer(out, dialect_named("sinumerik"), "XYZAC");
    const PostSummary e = post_program(reader, file, NominalSolver(m, Setup{}), writer, PostOptions{});
    CHECK(e.cycles_out == 0);
    out.commit();
  }
  const std::string expanded = test::read_text_file("native_cycles_sinumerik.nc");
  CHECK_THAT(expanded, !Catch::Contains("G83") && Catch::Contains("Z-3.0000"));
}

TEST_CASE("rapid moves: up first when the target is higher, down last when it is lower") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  const std::string cl =
      "UNITS/MM\nMULTAX/ON\nRAPID\nGOTO/0,0,50,0,0,1\nFEDRAT/MMPM,500\nGOTO/10,0,0,0,0,1\n"
      "RAPID\nGOTO/40,30,5,0,0.5,0.8660254\nRAPID\nGOTO/40,30,60,0,0.5,0.8660254\nEND\n";
  std::istringstream in(cl);
  cl::AptReader reader(in, "rapids.cls");
  {
    AtomicFile out("native_rapids.nc");
    NcWriter writer(out, dialect_named("fanuc"), "XYZAC");
    const PostSummary s = post_program(reader, "rapids.cls", NominalSolver(m, Setup{}), writer, PostOptions{});
    CHECK(s.rapid_splits >= 1);
    out.commit();
  }
  const std::string p = test::read_text_file("native_rapids.nc");
  // from the bottom of the cut (Z0) to a tilted point 5 mm up: Z rises first, alone
  const auto cut = p.find("X10.0000");
  REQUIRE(cut != std::string::npos);
  std::istringstream lines(p.substr(cut));
  std::string line;
  std::getline(lines, line);  // the cut
  std::getline(lines, line);
  CHECK(line.rfind("G0 Z", 0) == 0);
  CHECK(line.find('X') == std::string::npos);
  CHECK(line.find('A') == std::string::npos);
  std::getline(lines, line);
  CHECK(line.find('A') != std::string::npos);  // then travel and turn
}
