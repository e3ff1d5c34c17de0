// SPDX-License-Identifier: Apache-2.0
// Klartext with a tilted plane, M128 and Q parameters re-posted (post_request.hpp) and both sides
// executed independently: the input by the tests' own Klartext interpreter (klartext_interpreter.hpp)
// with the control's rotary angles computed here in closed form, the written Fanuc program by
// nc_executor.hpp. At the end of every input L block the tool tip of the input must be reached by
// the output (within 1 µm, in order), with the same tool axis.
//
// The control's angles (TNC 640 manual, PLANE ... SEQ): the tool axis u = W_R_plane · e_z.
//   AC trunnion (A about +X carrying C about +Z, table side): u = (sin a sin c, sin a cos c, cos a),
//     so a = ±acos(u_z) (SEQ+: a >= 0, A being the master axis), c = atan2(u_x / sin a, u_y / sin a).
//   B head about +Y, C table about +Z: R_t e_z = (sin b, 0, cos b) = R_z(c) u, so b = ±acos(u_z)
//     (SEQ+: b >= 0, B the master axis) and c turns u's XY direction onto +X:
//     c = atan2(-u_y / sin b, u_x / sin b).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "klartext_interpreter.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

constexpr double kDeg = M_PI / 180.0;

std::map<char, double> ac_angles(const test::M3& R, int seq) {
  const test::V3 u = R.col(2);
  const double a = (seq < 0 ? -1.0 : 1.0) * std::acos(std::clamp(u.z(), -1.0, 1.0));
  const double c = std::atan2(u.x() / std::sin(a), u.y() / std::sin(a));
  return {{'A', a / kDeg}, {'C', c / kDeg}};
}

std::map<char, double> bc_head_table_angles(const test::M3& R, int seq) {
  const test::V3 u = R.col(2);
  const double b = (seq < 0 ? -1.0 : 1.0) * std::acos(std::clamp(u.z(), -1.0, 1.0));
  const double c = std::atan2(-u.y() / std::sin(b), u.x() / std::sin(b));
  return {{'B', b / kDeg}, {'C', c / kDeg}};
}

struct Case {
  std::string machine_file;  ///< under machines/
  Setup setup;
  test::PlaneAnglesFn angles;
};

std::string post_text(const std::string& text, const Case& c) {
  PostRequest r;
  r.machine = serial_post_machine(load_machine(test::source("machines/" + c.machine_file)));
  r.setup = c.setup;
  r.dialect = dialect_named("fanuc");
  r.threads = 1;
  r.input_name = "plane.h";
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

/// Every input block end reached by the output, in order; returns the output's block ends.
std::vector<test::ExecPose> check_reposted(const std::string& text, const Case& c) {
  const std::string nc = post_text(text, c);
  INFO(nc);
  test::ExecJob job;
  job.workpiece_origin_mm = c.setup.workpiece_origin_mm;
  job.tool_length_mm = c.setup.tool_length_mm;
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/" + c.machine_file));
  test::KlartextInterpreter input(m, job, c.angles);
  const std::vector<test::KlartextEnd> want = input.run(text);
  const test::Executor out(test::source("machines/" + c.machine_file), job, nc);
  std::vector<test::ExecPose> got;
  for (const test::ExecBlock& b : out.blocks) got.push_back(out.at(b, 1.0));
  std::size_t next = 0;
  for (const test::KlartextEnd& e : want) {
    INFO("input line " << e.line << " tip " << e.tip_W.transpose());
    while (next < got.size() &&
           ((got[next].tip_W - e.tip_W).norm() > 1e-3 || (got[next].axis_W - e.axis_W).norm() > 2e-5))
      ++next;
    REQUIRE(next < got.size());
    CHECK((got[next].tip_W - e.tip_W).norm() < 1e-3);
  }
  return got;
}

/// The output's rotary words (deg) of every block, for the angles the control would take.
std::vector<std::map<char, double>> rotary_words(const std::string& nc, const Case& c) {
  test::ExecJob job;
  const test::Executor out(test::source("machines/" + c.machine_file), job, nc);
  std::vector<std::map<char, double>> words;
  for (const test::ExecBlock& b : out.blocks) words.push_back(b.to);
  return words;
}

Setup setup_of(double tool_length_mm, const Vec3d& origin_mm) {
  Setup s;
  s.tool_length_mm = tool_length_mm;
  s.workpiece_origin_mm = origin_mm;
  return s;
}

std::string plane_program(const std::string& plane, const std::string& rotary_words) {
  return "0 BEGIN PGM PLANE MM\n"
         "1 TOOL CALL 1 Z S5000\n"
         "2 L X+0 Y+0 Z+150 R0 FMAX M3\n"
         "3 " +
         plane +
         "\n"
         "4 L " +
         rotary_words +
         " R0 FMAX\n"
         "5 L X+10 Y+5 Z+20 FMAX\n"
         "6 L Z+0 F500\n"
         "7 L X+40 F800\n"
         "8 L Y+30\n"
         "9 L IX-30 IY-25\n"
         "10 L Z+20 FMAX\n"
         "11 PLANE RESET STAY\n"
         "12 L Z+250 FMAX\n"
         "13 M30\n"
         "14 END PGM PLANE MM\n";
}

}  // namespace

TEST_CASE(
    "klartext PLANE SPATIAL ... STAY + L A+Q120 C+Q122 on the AC trunnion: the control's angles, the tip on the "
    "plane") {
  const Case ac{"ac-trunnion.toml", setup_of(100.0, Vec3d(0, 0, 0)), ac_angles};
  for (const char* seq : {"SEQ+", "SEQ-"}) {
    INFO(seq);
    const std::string text =
        plane_program(std::string("PLANE SPATIAL SPA+30 SPB+0 SPC+45 STAY ") + seq, "A+Q120 C+Q122");
    check_reposted(text, ac);
    // the angles of the block after the PLANE, by the closed form: u = Rz(45) Rx(30) e_z
    const test::M3 R =
        (Eigen::AngleAxisd(45 * kDeg, test::V3::UnitZ()) * Eigen::AngleAxisd(30 * kDeg, test::V3::UnitX()))
            .toRotationMatrix();
    const auto want = ac_angles(R, std::string(seq) == "SEQ+" ? 1 : -1);
    CHECK(std::abs(want.at('A')) == Approx(30.0));  // the tilt of the plane
    bool found = false;
    for (const auto& w : rotary_words(post_text(text, ac), ac))
      found = found || (std::abs(w.at('A') - want.at('A')) < 1e-3 && std::abs(w.at('C') - want.at('C')) < 1e-3);
    CHECK(found);
  }
}

TEST_CASE("klartext PLANE PROJECTED ... STAY: the rotation alone is read; projection angles are refused") {
  const Case ac{"ac-trunnion.toml", setup_of(100.0, Vec3d(0, 0, 0)), ac_angles};
  // ROT turns about the tool axis as cycle 10 does: the same plane, and program, as PLANE SPATIAL SPC
  // (the tool axis stays vertical: C is free there, so the tests' own angle check does not apply)
  const std::string text = plane_program("PLANE PROJECTED PROPR+0 PROMIN+0 ROT+15 STAY SEQ+", "A+Q120 C+Q122");
  CHECK(post_text(text, ac) ==
        post_text(plane_program("PLANE SPATIAL SPA+0 SPB+0 SPC+15 STAY SEQ+", "A+Q120 C+Q122"), ac));
}

TEST_CASE("klartext PLANE SPATIAL on the head-table machine (B head, C table): Q121 and Q122 are the control's") {
  const Case bc{"head-table-bc.toml", setup_of(120.0, Vec3d(0, 0, -300)), bc_head_table_angles};
  for (const char* plane :
       {"PLANE SPATIAL SPA+0 SPB+40 SPC+30 STAY SEQ+", "PLANE SPATIAL SPA-25 SPB+10 SPC+0 STAY SEQ-"}) {
    INFO(plane);
    check_reposted(plane_program(plane, "B+Q121 C+Q122"), bc);
  }
}

TEST_CASE("klartext M128 on the head-table and the nutating-head machines: the tool tip is the programmed point") {
  const std::string text =
      "0 BEGIN PGM TCPM MM\n"
      "1 TOOL CALL 1 Z S8000\n"
      "2 L X+0 Y+0 Z+100 B+10 C+0 R0 FMAX M3\n"  // (away from the pole B0, where C is free)
      "3 M128\n"
      "4 L X+10 Y+0 Z+50 FMAX\n"
      "5 L X+20 Y+10 Z+5 B+30 C+45 F1000\n"
      "6 L X+30 Y+20 Z+5 B+35 C+60\n"
      "7 L X+30 Y-20 Z+8 B+20 C-30\n"
      "8 L Z+60 FMAX\n"
      "9 M129\n"
      "10 L Z+200 FMAX\n"
      "11 M30\n"
      "12 END PGM TCPM MM\n";
  check_reposted(text, {"head-table-bc.toml", setup_of(120.0, Vec3d(0, 0, -300)), bc_head_table_angles});
  check_reposted(text, {"nutating-head-bc.toml", setup_of(120.0, Vec3d(0, 0, -300)), bc_head_table_angles});
}

TEST_CASE("klartext Q parameters, a section repeat and a subprogram: executed as the control runs them") {
  const std::string text =
      "0 BEGIN PGM Q MM\n"
      "1 TOOL CALL 1 Z S5000\n"
      "2 Q1 = 10\n"
      "3 Q2 = Q1 * 2\n"
      "4 FN 0: Q3 = +5\n"
      "5 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX M3\n"
      "6 LBL 1\n"
      "7 L IX+Q1 F500\n"
      "8 L Y+Q2\n"
      "9 L Y+0\n"
      "10 CALL LBL 1 REP 2\n"
      "11 CALL LBL 5\n"
      "12 L X-Q2 Y-Q3 FMAX\n"
      "13 M30\n"
      "14 LBL 5\n"
      "15 L Z+Q3 FMAX\n"
      "16 LBL 0\n"
      "17 END PGM Q MM\n";
  const Case ac{"ac-trunnion.toml", setup_of(100.0, Vec3d(0, 0, 0)), ac_angles};
  const auto got = check_reposted(text, ac);
  // by hand: three passes of 10 mm in X (the section and its 2 repeats), then Z+5, then (-20, -5)
  const auto reached = [&](const test::V3& p) {
    for (const auto& e : got)
      if ((e.tip_W - p).norm() < 1e-6) return true;
    return false;
  };
  CHECK(reached(test::V3(30, 0, 50)));
  CHECK(reached(test::V3(30, 0, 5)));
  CHECK(reached(test::V3(-20, -5, 5)));
}

TEST_CASE(
    "klartext PLANE POINTS ... STAY SEQ+ on the AC trunnion: the plane through three points, the control's angles") {
  const Case ac{"ac-trunnion.toml", setup_of(100.0, Vec3d(0, 0, 0)), ac_angles};
  const std::string text =
      plane_program("PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+10 P2Y+10 P2Z+0 P3X-5 P3Y+5 P3Z+5 STAY SEQ+", "A+Q120 C+Q122");
  check_reposted(text, ac);
  // by hand: X = (1, 1, 0)/sqrt2, P3 - P1 = (-5, 5, 5) is square to X, so Y = (-1, 1, 1)/sqrt3 and the
  // tool axis Z = X x Y = (1, -1, 2)/sqrt6: A = acos(2/sqrt6) = 35.26 deg (SEQ+), C = atan2(1, -1) = 135 deg
  const double a = std::acos(2.0 / std::sqrt(6.0)) / kDeg;
  bool found = false;
  for (const auto& w : rotary_words(post_text(text, ac), ac))
    found = found || (std::abs(w.at('A') - a) < 1e-3 && std::abs(std::remainder(w.at('C') - 135.0, 360.0)) < 1e-3);
  CHECK(found);
}
