// SPDX-License-Identifier: Apache-2.0
// The parameter kinds residual analysis adds behave as docs/conventions.md says (sphere deviations,
// ballbar lengths, predicted through the error model exactly as identification predicts them):
// squareness, scale, harmonic component errors relative to the set-up at home, reversal as a
// play (static positions approached from above read command + b), drift zero at t = 0 and
// following lin·t + exp·(1 − e^(−t/tau)), and the instrument offsets.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/prediction.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

const Machine& machine() {
  static const Machine m =
      load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  return m;
}

MeasurementRow row(Vec3d xyz, double a_deg, double c_deg, double t = 0.0) {
  MeasurementRow r;
  r.command.linear_mm = xyz;
  r.command.rotary_rad = Eigen::Vector2d(deg_to_rad(a_deg), deg_to_rad(c_deg));
  r.time_s = t;
  return r;
}

MeasurementSet sphere_set(std::vector<MeasurementRow> rows) {
  MeasurementSet s;
  s.type = MeasurementType::sphere;
  s.sphere_mm = Vec3d(120, 40, 80);
  s.rows = std::move(rows);
  return s;
}

/// Predicted (dx, dy, dz) of every row (mm) with the given parameters.
std::vector<Vec3d> deviations(const MeasurementSet& s, const ErrorParameters& p) {
  const ModelLayout layout(machine(), p.names());
  const std::vector<double> v = predict_set<double>(machine(), s, layout, p.values().data());
  std::vector<Vec3d> out;
  for (std::size_t k = 0; k < s.rows.size(); ++k) out.emplace_back(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
  return out;
}

ErrorParameters one(const char* name, double value) {
  ErrorParameters p;
  p.set(name, value);
  return p;
}

}  // namespace

TEST_CASE("squareness EC0Y and scale EXX:p1 act on the relative motion of the tool", "[diagnose][conventions]") {
  const MeasurementSet s = sphere_set({row({0, 200, 0}, 0, 0), row({150, 0, 0}, 0, 0)});
  // ŷ = (−EC0Y, 1, 0): moving Y by y moves the tool by −EC0Y·y in X; the probed centre relative
  // to the tool therefore deviates by +EC0Y·y
  const auto sq = deviations(s, one("EC0Y", 4e-5));
  CHECK(sq[0].x() == Approx(4e-5 * 200).margin(1e-9));
  CHECK(sq[0].tail<2>().norm() < 1e-9);
  // EXX(x) = value·x: the tool goes value·x further along X, the centre reads −value·x
  const auto sc = deviations(s, one("EXX:p1", 4e-5));
  CHECK(sc[1].x() == Approx(-4e-5 * 150).margin(1e-9));
  CHECK(sc[0].norm() < 1e-9);
}

TEST_CASE("harmonic component errors act relative to the set-up at home", "[diagnose][conventions]") {
  // ECC:h2:cos = v turns the table by v·(cos 2C − 1) about the C line: nothing at C = 0 and 180°,
  // −2v at C = 90°, a displacement of 2v·r of the sphere (r its distance from the C line)
  const MeasurementSet s = sphere_set({row({0, 0, 0}, 0, 0), row({0, 0, 0}, 0, 90), row({0, 0, 0}, 0, 180)});
  const auto d = deviations(s, one("ECC:h2:cos", 4e-5));
  CHECK(d[0].norm() < 1e-9);
  CHECK(d[2].norm() < 1e-9);
  CHECK(d[1].norm() == Approx(2 * 4e-5 * std::hypot(120.0, 40.0)).epsilon(1e-6));
  CHECK(std::abs(d[1].z()) < 1e-9);
}

TEST_CASE("reversal is a play: a position approached from above reads command + b", "[diagnose][conventions]") {
  const double b = 5e-5;
  const MeasurementSet s = sphere_set({row({0, 0, 0}, 0, 0), row({0, 0, 0}, 0, 60), row({0, 0, 0}, 0, 30)});
  const auto with_play = deviations(s, one("reversal:C", b));
  const auto none = deviations(s, ErrorParameters());
  CHECK((with_play[0] - none[0]).norm() < 1e-12);  // first row: from below
  CHECK((with_play[1] - none[1]).norm() < 1e-12);  // rising: actual = command
  // falling to 30°: the table stands at 30° + b, so the centre is off by b·r along the turn
  const Vec3d play = with_play[2] - none[2];
  CHECK(play.norm() == Approx(b * std::hypot(120.0, 40.0)).epsilon(1e-4));
  CHECK(std::abs(play.z()) < 1e-9);
}

TEST_CASE("drift is zero at t = 0 and follows lin·t + exp·(1 − e^(−t/tau))", "[diagnose][conventions]") {
  const MeasurementSet s =
      sphere_set({row({0, 0, 0}, 0, 0, 0.0), row({0, 0, 0}, 0, 0, 900.0), row({0, 0, 0}, 0, 0, 1800.0)});
  ErrorParameters p;
  p.set("drift:Z:t:lin", 1e-6);
  p.set("drift:Z:t:exp", 0.012);
  p.set("drift:Z:t:tau", 900.0);
  const auto d = deviations(s, p);
  CHECK(d[0].norm() < 1e-12);
  // the tool drifts up (+Z) relative to the table: the centre relative to the tool reads −drift
  for (int k : {1, 2}) {
    const double t = k == 1 ? 900.0 : 1800.0;
    CHECK(d[static_cast<std::size_t>(k)].z() == Approx(-(1e-6 * t + 0.012 * (1 - std::exp(-t / 900.0)))).epsilon(1e-9));
    CHECK(d[static_cast<std::size_t>(k)].head<2>().norm() < 1e-12);
  }
}

TEST_CASE("instrument offsets: ballbar length and sphere position", "[diagnose][conventions]") {
  MeasurementSet bb;
  bb.type = MeasurementType::ballbar;
  bb.table_ball_mm = Vec3d(0, -100, 250);
  bb.tool_ball_mm = Vec3d::Zero();
  bb.rows = {row({0, 0, 250}, 0, 0), row({0, 0, 250}, 0, 90)};
  const ModelLayout layout(machine(), {"ballbar:length"});
  const double v = 0.008;
  const std::vector<double> L = predict_set<double>(machine(), bb, layout, &v);
  CHECK(L[0] == Approx(100.008).epsilon(1e-12));
  CHECK(L[1] == Approx(100.008).epsilon(1e-12));  // the tool ball is on the C line: C does not change L
  // the sphere centre offset turns with the table: at C = 0 it reads itself, at C = 90° turned
  const MeasurementSet s = sphere_set({row({0, 0, 0}, 0, 0), row({0, 0, 0}, 0, 90)});
  const auto d = deviations(s, one("sphere:position:x", 0.005));
  CHECK(d[0].x() == Approx(0.005).epsilon(1e-9));
  CHECK(d[1].norm() == Approx(0.005).epsilon(1e-9));
  CHECK(std::abs(d[1].x()) < 1e-9);
}
