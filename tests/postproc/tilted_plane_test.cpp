// SPDX-License-Identifier: Apache-2.0
// `post --tilted-plane` (tilted_plane.hpp, the dialects' [tilted_plane]): two positional
// operations on two tilted planes (tests/data/tilted/two_planes.cls) posted in every dialect with a
// tilted plane; the frame words are read back from the program text with this file's own reading
// of each control's convention (Fanuc G68.2 / Haas G268 Q313: Euler Z-X'-Z''; Sinumerik CYCLE800
// _MODE 27: Z, Y', X''; Heidenhain CYCL DEF 7 + PLANE SPATIAL: about the fixed X, Y, Z), every
// in-plane X Y Z is mapped back to W and must land on the CL data; the frame's Z must be the CL
// tool axis. Fanuc: the reviewed program text. Also: the vertical plane (no frame), continuity of
// the angles, and --verify through the plane.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "cli_run.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/write/tilted_plane.hpp"
#include "ncpost/postproc/verify/verify.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const Vec3d kWorkpieceOrigin(0, 0, 80);  // P (M at home) = W + this on the AC trunnion (pivots at M's origin)

PostRequest request(const std::string& dialect, bool tilted) {
  PostRequest r;
  r.machine = serial_post_machine(load_machine(test::source("machines/ac-trunnion.toml")));
  r.machine_source = "machines/ac-trunnion.toml";
  r.setup.workpiece_origin_mm = kWorkpieceOrigin;
  r.dialect = dialect_named(dialect);
  r.tilted_plane = tilted;
  r.tolerance_mm.reset();
  r.threads = 1;
  r.input_name = "two_planes.cls";
  return r;
}

std::string post_text(const std::string& cl_text, const PostRequest& r, PostResult* result = nullptr) {
  std::istringstream in(cl_text);
  std::ostringstream out;
  PostResult res = post(in, out, r);
  if (result) *result = res;
  return out.str();
}

struct ClPointRow {
  Vec3d tip, axis;
};

/// The GOTO points of an APT text (6 values), axis normalised.
std::vector<ClPointRow> goto_points(const std::string& text) {
  std::vector<ClPointRow> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("GOTO/", 0) != 0) continue;
    std::vector<double> v;
    std::stringstream ss(line.substr(5));
    std::string item;
    while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
    REQUIRE(v.size() == 6);
    out.push_back({Vec3d(v[0], v[1], v[2]), Vec3d(v[3], v[4], v[5]).normalized()});
  }
  return out;
}

Mat3d rz(double d) { return Eigen::AngleAxisd(d * kDeg, Vec3d::UnitZ()).toRotationMatrix(); }
Mat3d ry(double d) { return Eigen::AngleAxisd(d * kDeg, Vec3d::UnitY()).toRotationMatrix(); }
Mat3d rx(double d) { return Eigen::AngleAxisd(d * kDeg, Vec3d::UnitX()).toRotationMatrix(); }

/// A frame read back from the words: P_p = origin + R F_p.
struct ReadFrame {
  Vec3d origin = Vec3d::Zero();
  Mat3d R = Mat3d::Identity();
  std::vector<Vec3d> ends_W;       ///< every block end in the plane, mapped to W
  std::vector<Vec3d> feed_ends_W;  ///< the feed blocks' ends (G1/G2/G3/cycle, L .. F)
};

double number_after(const std::string& line, const std::string& word) {
  const std::regex re(word + R"(([-+]?[0-9]*\.?[0-9]+))");
  std::smatch m;
  REQUIRE(std::regex_search(line, m, re));
  return std::stod(m[1].str());
}

bool has_word(const std::string& line, char letter) {
  const std::regex re(std::string("(^|[ ])") + letter + R"([-+]?[0-9.])");
  return std::regex_search(line, re);
}

/// Reads the frames of a program of `dialect` and maps every in-plane block end back to W.
std::vector<ReadFrame> read_frames(const std::string& program, const std::string& dialect) {
  std::vector<ReadFrame> frames;
  std::istringstream lines(program);
  std::string line;
  bool in_plane = false;
  Vec3d xyz = Vec3d::Constant(std::nan(""));
  Vec3d heidenhain_shift = Vec3d::Zero();
  bool last_feed = false;  // the modal motion word (G0, or G1/G2/G3/G81)
  auto block_end = [&](bool feed) {
    ReadFrame& f = frames.back();
    const Vec3d w = f.origin + f.R * xyz - kWorkpieceOrigin;
    f.ends_W.push_back(w);
    if (feed) f.feed_ends_W.push_back(w);
  };
  while (std::getline(lines, line)) {
    if (dialect == "fanuc" || dialect == "haas") {
      if (line.rfind(dialect == "fanuc" ? "G68.2 " : "G268 ", 0) == 0) {
        ReadFrame f;
        f.origin = {number_after(line, "X"), number_after(line, "Y"), number_after(line, "Z")};
        f.R = rz(number_after(line, "I")) * rx(number_after(line, "J")) * rz(number_after(line, "K"));
        if (dialect == "haas") CHECK_THAT(line, Catch::EndsWith(" Q313"));
        frames.push_back(f);
        in_plane = true;
        xyz = Vec3d::Constant(std::nan(""));
        continue;
      }
    } else if (dialect == "sinumerik") {
      if (line.rfind("CYCLE800(", 0) == 0 && line != "CYCLE800()") {
        std::vector<std::string> p;
        std::stringstream ss(line.substr(9, line.size() - 10));
        std::string item;
        while (std::getline(ss, item, ',')) p.push_back(item);
        REQUIRE(p.size() == 15);
        CHECK(p[3] == "27");  // axis-by-axis, sequence Z Y X
        ReadFrame f;
        f.origin = {std::stod(p[4]), std::stod(p[5]), std::stod(p[6])};
        f.R = rz(std::stod(p[7])) * ry(std::stod(p[8])) * rx(std::stod(p[9]));
        frames.push_back(f);
        in_plane = true;
        xyz = Vec3d::Constant(std::nan(""));
        continue;
      }
    } else if (dialect == "heidenhain") {
      const auto body = line.substr(line.find(' ') + 1);  // after the block number
      for (int i = 0; i < 3; ++i)
        if (body.rfind(std::string("CYCL DEF 7.") + char('1' + i) + " ", 0) == 0)
          heidenhain_shift[i] = number_after(body, std::string(1, "XYZ"[i]));
      if (body.rfind("PLANE SPATIAL ", 0) == 0) {
        ReadFrame f;
        f.origin = heidenhain_shift;
        f.R = rz(number_after(body, "SPC")) * ry(number_after(body, "SPB")) * rx(number_after(body, "SPA"));
        CHECK_THAT(body, Catch::EndsWith(" STAY"));
        frames.push_back(f);
        in_plane = true;
        xyz = Vec3d::Constant(std::nan(""));
        continue;
      }
      if (body.rfind("PLANE RESET", 0) == 0) in_plane = false;
      if (in_plane && body.rfind("L ", 0) == 0 && (has_word(body, 'X') || has_word(body, 'Y') || has_word(body, 'Z'))) {
        for (int i = 0; i < 3; ++i)
          if (has_word(body, "XYZ"[i])) xyz[i] = number_after(body, std::string(" ") + "XYZ"[i]);
        block_end(body.find("FMAX") == std::string::npos);
      }
      continue;
    }
    if (line == "G69" || line == "G269" || line == "CYCLE800()") {
      in_plane = false;
      continue;
    }
    if (!in_plane) continue;
    if (!(has_word(line, 'X') || has_word(line, 'Y') || has_word(line, 'Z'))) continue;
    for (int i = 0; i < 3; ++i)
      if (has_word(line, "XYZ"[i])) xyz[i] = number_after(line, std::string(" ?") + "XYZ"[i]);
    static const std::regex rapid(R"((^|[ ])G0([ ]|$))");
    const bool g0 = std::regex_search(line, rapid);
    static const std::regex feed_word(R"((^|[ ])G(1|2|3|81)([ ]|$))");
    if (g0) last_feed = false;
    if (std::regex_search(line, feed_word)) last_feed = true;
    block_end(last_feed);
  }
  return frames;
}

double distance_to_path(const Vec3d& p, const std::vector<Vec3d>& path) {
  double best = 1e300;
  for (std::size_t i = 0; i < path.size(); ++i) {
    best = std::min(best, (p - path[i]).norm());
    if (i + 1 < path.size()) best = std::min(best, distance_to_segment(p, path[i], path[i + 1]));
  }
  return best;
}

}  // namespace

TEST_CASE("tilted planes: the angles give the rotation back, nearest the previous ones") {
  for (const auto convention : {TiltedPlaneWords::Angles::euler_zxz, TiltedPlaneWords::Angles::fixed_xyz}) {
    for (const std::array<double, 3> t : {std::array<double, 3>{30, 40, -75}, {-170, 12, 160}, {5, -80, 100}}) {
      const Mat3d R = plane_rotation(convention, t);
      const auto back = plane_angles(convention, R, std::nullopt);
      CHECK((plane_rotation(convention, back) - R).norm() < 1e-12);
      const auto near = plane_angles(convention, R, t);  // the triple itself is the nearest
      for (int i = 0; i < 3; ++i)
        CHECK(near[static_cast<std::size_t>(i)] == Approx(t[static_cast<std::size_t>(i)]).margin(1e-9));
    }
  }
  // across ±180: continuous, not the principal value
  const Mat3d R = plane_rotation(TiltedPlaneWords::Angles::euler_zxz, {181.5, 30, -181.5});
  const auto a = plane_angles(TiltedPlaneWords::Angles::euler_zxz, R, std::array<double, 3>{178.0, 30.0, -178.0});
  CHECK(a[0] == Approx(181.5));
  CHECK(a[2] == Approx(-181.5));
  CHECK(plane_angles(TiltedPlaneWords::Angles::euler_zxz, R, std::nullopt)[0] == Approx(-178.5));
  // not unique (b = 180: only a - c counts): a keeps its previous value
  const Mat3d down = plane_rotation(TiltedPlaneWords::Angles::euler_zxz, {40, 180, 10});
  const auto d = plane_angles(TiltedPlaneWords::Angles::euler_zxz, down, std::array<double, 3>{55.0, 170.0, 0.0});
  CHECK(d[0] == Approx(55.0));
  CHECK((plane_rotation(TiltedPlaneWords::Angles::euler_zxz, d) - down).norm() < 1e-12);
  // fixed_xyz b = 90: c keeps its previous value
  const Mat3d side = plane_rotation(TiltedPlaneWords::Angles::fixed_xyz, {20, 90, 35});
  const auto s = plane_angles(TiltedPlaneWords::Angles::fixed_xyz, side, std::array<double, 3>{0.0, 80.0, -12.0});
  CHECK(s[2] == Approx(-12.0));
  CHECK((plane_rotation(TiltedPlaneWords::Angles::fixed_xyz, s) - side).norm() < 1e-12);
}

TEST_CASE("tilted planes: two planes in every dialect land on the CL points") {
  const std::string cl = test::read_text_file(test::data("tilted/two_planes.cls"));
  const std::vector<ClPointRow> points = goto_points(cl);
  // the CL points of each tilted run, in order (the holes: their bottoms 5 mm down the axis, and
  // the hole axis from the retract plane 25 mm up)
  std::vector<std::vector<Vec3d>> runs;
  std::vector<Vec3d> run_axes;
  for (const ClPointRow& p : points) {
    if (p.axis.z() > 1.0 - 1e-12) continue;
    if (run_axes.empty() || (run_axes.back() - p.axis).norm() > 1e-9) {
      runs.emplace_back();
      run_axes.push_back(p.axis);
    }
    runs.back().push_back(p.tip);
  }
  REQUIRE(runs.size() == 2);
  std::vector<Vec3d> hole_path;  // run 2 as the tool goes: retract, bottom, retract, ...
  for (std::size_t i = 1; i + 1 < runs[1].size(); ++i) {
    hole_path.push_back(runs[1][i] + 25.0 * run_axes[1]);
    hole_path.push_back(runs[1][i] - 5.0 * run_axes[1]);
    hole_path.push_back(runs[1][i] + 25.0 * run_axes[1]);
  }
  for (const std::string dialect : {"fanuc", "haas", "sinumerik", "heidenhain"}) {
    INFO(dialect);
    PostResult result;
    PostRequest r = request(dialect, true);
    r.verify = true;
    const std::string program = post_text(cl, r, &result);
    INFO(program);
    CHECK(result.summary.tilted_planes == 2);
    const std::vector<ReadFrame> frames = read_frames(program, dialect);
    REQUIRE(frames.size() == 2);
    for (std::size_t f = 0; f < 2; ++f) {
      // the plane's Z is the tool axis (angles with 4 decimals: within 1.2e-6 rad, see conventions.md)
      CHECK((frames[f].R.col(2) - run_axes[f]).norm() < 1.3e-6);
      CHECK(std::abs(frames[f].R.determinant() - 1.0) < 1e-12);
    }
    // plane 1: every CL point is a block end, every feed block ends on the CL contour (the arc's
    // points on its circle in dialects that expand it)
    const Vec3d centre = Vec3d(15, -11.339746, 35);
    for (const Vec3d& p : runs[0]) {
      double best = 1e300;
      for (const Vec3d& e : frames[0].ends_W) best = std::min(best, (e - p).norm());
      CHECK(best < 0.001);
    }
    for (const Vec3d& e : frames[0].feed_ends_W) {
      const double on_circle = std::abs((e - centre).norm() - 10.0) + std::abs((e - centre).dot(run_axes[0]));
      CHECK(std::min(distance_to_path(e, runs[0]), on_circle) < 0.001);
    }
    // plane 2: both bottoms reached, every block end on the approach or a hole axis
    for (std::size_t i = 1; i + 1 < runs[1].size(); ++i) {
      double best = 1e300;
      for (const Vec3d& e : frames[1].ends_W) best = std::min(best, (e - (runs[1][i] - 5.0 * run_axes[1])).norm());
      CHECK(best < 0.001);
    }
    for (const Vec3d& e : frames[1].feed_ends_W) CHECK(distance_to_path(e, hole_path) < 0.001);
    // --verify re-executes the tilted blocks through the plane: block ends within the words' rounding
    CHECK(result.verified);
    CHECK(result.summary.verify.blocks > 0);
    CHECK(result.summary.verify.max_endpoint_mm < 0.001);
    CHECK(result.summary.verify.max_contour_mm < 0.001);
  }
}

TEST_CASE("tilted planes: Fanuc G68.2 / G53.1 / G69, the reviewed program") {
  const std::string cl = test::read_text_file(test::data("tilted/two_planes.cls"));
  const std::string program = post_text(cl, request("fanuc", true));
  const std::string expected = test::read_text_file(test::data("tilted/two_planes_fanuc.nc"));
  // from the first tool block on (the header names the version)
  const auto body = [](const std::string& t) { return t.substr(t.find("T1 M6")); };
  CHECK(body(program) == body(expected));
  // the frame blocks in order
  std::vector<std::string> frame_blocks;
  std::istringstream lines(program);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind("G68.2", 0) == 0 || line == "G53.1" || line == "G69") frame_blocks.push_back(line.substr(0, 5));
  CHECK(frame_blocks == std::vector<std::string>{"G68.2", "G53.1", "G69", "G68.2", "G53.1", "G69"});
}

TEST_CASE("tilted planes: a vertical tool axis opens no plane; LinuxCNC writes machine axes") {
  const std::string vertical =
      "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,100,0,0,1\nRAPID\nGOTO/10,5,20,0,0,1\n"
      "FEDRAT/MMPM,300\nGOTO/10,5,0,0,0,1\nGOTO/30,5,0,0,0,1\nRAPID\nGOTO/30,5,100,0,0,1\nFINI\n";
  PostResult with;
  const std::string a = post_text(vertical, request("fanuc", true), &with);
  CHECK(with.summary.tilted_planes == 0);
  CHECK(a == post_text(vertical, request("fanuc", false)));
  const std::string cl = test::read_text_file(test::data("tilted/two_planes.cls"));
  PostResult lcnc;
  CHECK(post_text(cl, request("linuxcnc", true), &lcnc) == post_text(cl, request("linuxcnc", false)));
  CHECK(lcnc.summary.tilted_planes == 0);
  REQUIRE(!lcnc.summary.notices.empty());
  CHECK_THAT(lcnc.summary.notices.back(), Catch::Contains("has no tilted work plane"));
}

TEST_CASE("tilted planes: the Euler angles stay continuous across ±180 degrees") {
  // two planes whose first Euler angle is 177.71 and -177.71 as principal values
  const std::string cl =
      "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,100,0,0,1\n"
      "RAPID\nGOTO/5,5,20,0.02,0.5,0.8657945\nFEDRAT/MMPM,300\nGOTO/5,5,10,0.02,0.5,0.8657945\n"
      "RAPID\nGOTO/-5,5,20,-0.02,0.5,0.8657945\nFEDRAT/MMPM,300\nGOTO/-5,5,10,-0.02,0.5,0.8657945\n"
      "RAPID\nGOTO/0,0,100,0,0,1\nFINI\n";
  PostRequest r = request("fanuc", true);
  r.verify = true;
  PostResult result;
  const std::string program = post_text(cl, r, &result);
  INFO(program);
  std::vector<double> first;
  std::istringstream lines(program);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind("G68.2", 0) == 0) first.push_back(number_after(line, "I"));
  REQUIRE(first.size() == 2);
  CHECK(std::abs(first[0]) > 177.0);
  CHECK(std::abs(first[1] - first[0]) < 5.0);  // 177.71 then 182.29, not -177.71
  CHECK(result.summary.verify.max_endpoint_mm < 0.001);
}

TEST_CASE("tilted planes: verify measures where the plane's words put the tool") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  Setup setup;
  setup.workpiece_origin_mm = kWorkpieceOrigin;
  const NominalSolver solver(m, setup);
  const Vec3d k = Vec3d(0, -0.5, std::sqrt(3.0) / 2.0);
  const ClPoint a{Vec3d(10, -20, 30), k}, b{Vec3d(25, -20, 30), k};
  const IkOutcome ik = solver.solve(a, AxisPosition{});
  REQUIRE(ik.ok());
  TiltedPlane plane;
  plane.P_R_F = plane_frame(k, Vec3d::UnitX(), Vec3d::UnitY());
  plane.origin_P_mm = a.tip_mm + kWorkpieceOrigin;
  const Eigen::Vector2d rotary = ik.position->rotary_rad;
  SolverData data;
  const AxisPosition qa =
      executed_in_plane(solver, data, plane, kWorkpieceOrigin, rotary, plane.to_plane(a.tip_mm + kWorkpieceOrigin));
  const AxisPosition qb =
      executed_in_plane(solver, data, plane, kWorkpieceOrigin, rotary, plane.to_plane(b.tip_mm + kWorkpieceOrigin));
  VerifyReport good;
  CHECK(verify_block(solver, data, a, qa, b, qb, 1, good) < 1e-9);
  CHECK(good.max_endpoint_mm < 1e-9);
  // words that would not land on the CL point: 0.05 mm off in the plane's Y
  const AxisPosition wrong = executed_in_plane(solver, data, plane, kWorkpieceOrigin, rotary,
                                               plane.to_plane(b.tip_mm + kWorkpieceOrigin) + Vec3d(0, 0.05, 0));
  VerifyReport bad;
  CHECK(verify_block(solver, data, a, qa, b, wrong, 1, bad) == Approx(0.05).margin(1e-6));
  CHECK(bad.max_endpoint_mm == Approx(0.05).margin(1e-6));
}

TEST_CASE("tilted planes: [tilted_plane] of a dialect file is checked") {
  const std::string fanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));
  const Dialect d = parse_dialect(fanuc, "fanuc.toml");
  REQUIRE(d.tilted_plane);
  CHECK(d.tilted_plane->angles == TiltedPlaneWords::Angles::euler_zxz);
  CHECK(d.tilted_plane->on == std::vector<std::string>{"G68.2 X{x} Y{y} Z{z} I{a} J{b} K{c}", "G53.1"});
  CHECK(d.tilted_plane->off == std::vector<std::string>{"G69"});
  auto error_of = [&](const std::string& from, const std::string& to) {
    std::string text = fanuc;
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    try {
      parse_dialect(text, "mine.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error_of("angles = \"euler_zxz\"", "angles = \"zyz\""),
             Catch::Contains("euler_zxz") && Catch::Contains("mine.toml:"));
  CHECK_THAT(error_of(" K{c}\"", "\""), Catch::Contains("{c} is missing"));
  CHECK_THAT(error_of("G53.1\"]", "G53.1 {tool}\"]"), Catch::Contains("unknown placeholder '{tool}'"));
  CHECK_THAT(error_of("native = true\nangles", "native = true\nangle_words = 1\nangles"),
             Catch::Contains("unknown key 'angle_words'"));
  // a file without the section (an older copy) has no tilted plane
  const std::string old = fanuc.substr(0, fanuc.find("\n[tilted_plane]"));
  CHECK_FALSE(parse_dialect(old, "old.toml").tilted_plane);
}

TEST_CASE("tilted planes: the command line") {
  const std::string dir = test::make_temp_dir("tilted_plane_cli");
  CHECK(test::run_ncpost("post --help", dir + "/help.txt") == 0);
  CHECK_THAT(test::read_text_file(dir + "/help.txt"), Catch::Contains("--tilted-plane") && Catch::Contains("G68.2"));
  const std::string base =
      "post --machine '" + test::source("machines/ac-trunnion.toml") + "' --workpiece-origin 0,0,80 --tilted-plane ";
  const std::string cl = "'" + test::data("tilted/two_planes.cls") + "'";
  CHECK(test::run_ncpost(base + "--rtcp -o '" + dir + "/a.nc' " + cl, dir + "/rtcp.txt") == 1);
  CHECK_THAT(test::read_text_file(dir + "/rtcp.txt"), Catch::Contains("--tilted-plane: not with --rtcp"));
  CHECK(test::run_ncpost(base + "--verify --tolerance 0.005 -o '" + dir + "/b.nc' " + cl, dir + "/verify.txt") == 0);
  const std::string log = test::read_text_file(dir + "/verify.txt");
  INFO(log);
  CHECK_THAT(log, Catch::Contains("block ends 0.0000 mm"));
  CHECK_THAT(test::read_text_file(dir + "/b.nc"),
             Catch::Contains("G68.2 X10.0000 Y-40.0000 Z144.6410 I0.0000 J30.0000 K0.0000\nG53.1\n"));
}

TEST_CASE("tilted planes: a point out of the travel in the plane ends it and is refused as without it") {
  // X 600 mm: beyond the AC trunnion's X travel (±500) on both rotary solutions
  const std::string cl =
      "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,100,0,0,1\nRAPID\nGOTO/10,-40,64.641016,0,-0.5,0.866025\n"
      "FEDRAT/MMPM,300\nGOTO/10,-20,30,0,-0.5,0.866025\nGOTO/600,-20,30,0,-0.5,0.866025\nFINI\n";
  std::string with, without;
  try {
    post_text(cl, request("fanuc", true));
  } catch (const Infeasible& e) {
    with = e.what();
  }
  try {
    post_text(cl, request("fanuc", false));
  } catch (const Infeasible& e) {
    without = e.what();
  }
  CHECK_THAT(with, Catch::Contains("two_planes.cls:9"));
  CHECK(with == without);
}
