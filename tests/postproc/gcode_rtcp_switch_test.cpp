// SPDX-License-Identifier: Apache-2.0
// Issue 27.3: when a program switches RTCP off (G49 after G43.4) or on, the machine axes stay
// where they physically are: the reader converts the position between the tool tip in W and the
// machine axes, it does not re-label the words. Expected positions are computed here by hand from
// docs/conventions.md ("Nominal closure": (X, Y, Z) = T_w(q)·(workpiece_origin + p)) and the
// geometry of machines/ac-trunnion.toml (w C' A' Y' b X Z t, A about +X and C about +Z through
// the origin of M, Z travel -600 .. 600 mm).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

constexpr double kHalfTurn = 3.14159265358979323846;  // pi

/// T_w(A, C) = Rot(x, A) · Rot(z, C) applied to `v` (the table's turn on the AC trunnion).
Vec3d table_turn(double a_deg, double c_deg, const Vec3d& v) {
  const double a = a_deg * kHalfTurn / 180.0, c = c_deg * kHalfTurn / 180.0;
  const Vec3d after_c(std::cos(c) * v.x() - std::sin(c) * v.y(), std::sin(c) * v.x() + std::cos(c) * v.y(), v.z());
  return {after_c.x(), std::cos(a) * after_c.y() - std::sin(a) * after_c.z(),
          std::sin(a) * after_c.y() + std::cos(a) * after_c.z()};
}

/// The inverse turn: Rot(z, -C) · Rot(x, -A).
Vec3d table_unturn(double a_deg, double c_deg, const Vec3d& v) {
  const double a = -a_deg * kHalfTurn / 180.0, c = -c_deg * kHalfTurn / 180.0;
  const Vec3d after_a(v.x(), std::cos(a) * v.y() - std::sin(a) * v.z(), std::sin(a) * v.y() + std::cos(a) * v.z());
  return {std::cos(c) * after_a.x() - std::sin(c) * after_a.y(), std::sin(c) * after_a.x() + std::cos(c) * after_a.y(),
          after_a.z()};
}

std::vector<cl::Motion> motions(const std::string& text, const Setup& setup) {
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), setup);
  return test::only<cl::Motion>(test::all_records(r));
}

}  // namespace

TEST_CASE("gcode RTCP switch: after G49 the reference return moves machine Z only (issue 27.3)") {
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 50);
  const std::string program =
      "%\nO0001\nG90 G21 G94 G17 G40 G49 G80\nT3 M6\nG43.4 H3\nS2000 M3\n"
      "G0 X10.0000 Y0.0000 Z50.0000 A0.0000 C0.0000\nG94 G1 Z0.0000 F500.0\nX30.0000 Y10.0000 A30.0000 C0.0000\n"
      "G49\nG91 G28 Z0\nG90\nM30\n%\n";
  const auto ms = motions(program, setup);
  REQUIRE(ms.size() == 4);
  const Vec3d last_tip_W(30, 10, 0);
  CHECK(ms[2].point.tip_mm.isApprox(last_tip_W, 1e-9));
  // where the machine stands at the end of the cut: (X, Y, Z) = Rot(x, 30°)·(origin + tip)
  const Vec3d machine_at_cut = table_turn(30, 0, setup.workpiece_origin_mm + last_tip_W);
  CHECK(machine_at_cut.y() == Approx(10 * std::cos(kHalfTurn / 6) - 50 * std::sin(kHalfTurn / 6)));  // -16.340 mm
  // G91 G28 Z0: Z to its reference, the top of its travel (600 mm); X, Y, A, C stay
  const Vec3d machine_at_return(machine_at_cut.x(), machine_at_cut.y(), 600.0);
  const Vec3d expected_tip_W = table_unturn(30, 0, machine_at_return) - setup.workpiece_origin_mm;
  const cl::Motion& ret = ms[3];
  CHECK(ret.rapid);
  CHECK((ret.point.tip_mm - expected_tip_W).norm() < 1e-6);
  // the tip moved along machine Z seen from the table: no sideways move in machine X or Y
  const Vec3d moved_M = table_turn(30, 0, ret.point.tip_mm - ms[2].point.tip_mm);
  CHECK(std::abs(moved_M.x()) < 1e-6);
  CHECK(std::abs(moved_M.y()) < 1e-6);
  CHECK(moved_M.z() == Approx(600.0 - machine_at_cut.z()));
}

TEST_CASE("gcode RTCP switch: switching RTCP on reads the machine's position as the tool tip it puts in W") {
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 50);
  // the machine at X30 Y-16.3397 Z48.3013 A30: the tip at (30, 10, 0) in W (hand computation)
  const Vec3d machine = table_turn(30, 0, Vec3d(30, 10, 50));
  const std::string text = "G21 G90 G94\nG43 H1\nG0 X" + std::to_string(machine.x()) + " Y" +
                           std::to_string(machine.y()) + " Z" + std::to_string(machine.z()) +
                           " A30 C0\nG43.4 H1\nG1 Z5 F100\nM30\n";
  const auto ms = motions(text, setup);
  REQUIRE(ms.size() == 2);
  CHECK((ms[0].point.tip_mm - Vec3d(30, 10, 0)).norm() < 1e-5);  // std::to_string: 6 decimals
  // under RTCP, Z5 moves the tip in W from (30, 10, 0) to (30, 10, 5): X and Y are the tip's
  CHECK((ms[1].point.tip_mm - Vec3d(30, 10, 5)).norm() < 1e-5);
}
