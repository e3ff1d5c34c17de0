// SPDX-License-Identifier: Apache-2.0
// TRR-XY kinematics (docs/trr-xy.md): forward(inverse(x)) = x over the workspace, on the nominal
// machine and on machines with random errors; two routes agree (closed-form home geometry,
// nominal inverse against Newton forward); out-of-reach poses fail with a message.
#include <catch2/catch.hpp>

#include <random>

#include "ncpost/kinematics/trr_xy_inverse.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

double draw(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

trr::Machine seed_machine() {
  trr::Machine m;
  m.table_limits[0] = AxisLimits{-400, 400};
  m.table_limits[1] = AxisLimits{-400, 400};
  for (auto& l : m.slider_limits) l = AxisLimits{0, 600};
  return m;
}

/// A random CL point: tilt up to `max_tilt_deg`, TCP height between 200 and 400 mm below home.
ClPoint random_cl(std::mt19937& rng, double max_tilt_deg) {
  const double tilt = deg_to_rad(max_tilt_deg) * std::sqrt(draw(rng, 0, 1));
  const double az = draw(rng, -kPi, kPi);
  ClPoint cl;
  cl.axis = Vec3d(std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt));
  cl.tip_mm = Vec3d(draw(rng, -150, 150), draw(rng, -150, 150), draw(rng, -100, 100));
  return cl;
}

Errors random_errors(std::mt19937& rng, double scale) {
  Errors e;
  for (int k = 0; k < kParameterCount; ++k) e[k] = draw(rng, -scale, scale) * (Errors::is_angle(k) ? 1e-3 : 1.0);
  return e;
}

struct RoundTrip {
  int solved = 0;
  double worst_tip_mm = 0, worst_axis_rad = 0;
};

RoundTrip round_trip(const Kinematics& k, std::mt19937& rng, int n, double max_tilt_deg) {
  const Vec3d origin(5.0, -8.0, -300.0);
  RoundTrip r;
  for (int i = 0; i < n; ++i) {
    const ClPoint cl = random_cl(rng, max_tilt_deg);
    const InverseOutcome ik = inverse(k, cl, origin);
    INFO(ik.failure);
    REQUIRE(ik.ok());
    // forward from the home pose (not the inverse's plate): an independent start
    std::string why;
    const auto tp = k.tool(ik.command->slider_mm, std::nullopt, &why);
    INFO(why);
    REQUIRE(tp);
    const Vec3d tip = Kinematics::tip_in_workpiece(*tp, *ik.command, origin);
    r.worst_tip_mm = std::max(r.worst_tip_mm, (tip - cl.tip_mm).norm());
    r.worst_axis_rad = std::max(
        r.worst_axis_rad, std::atan2(tp->axis.cross(cl.axis.normalized()).norm(), tp->axis.dot(cl.axis.normalized())));
    ++r.solved;
  }
  return r;
}

}  // namespace

TEST_CASE("home: all sliders 0, level plate, TCP at the origin of M") {
  const Kinematics k(seed_machine());
  const Geometry& g = k.geometry();
  CHECK(g.pin_height_mm() == Approx(std::sqrt(1020.0 * 1020.0 - 295.0 * 295.0) + 412.0));
  CHECK((k.home_plate().t - Vec3d(0, 0, 412.0)).norm() < 1e-9);
  CHECK((k.home_plate().R - Mat3d::Identity()).norm() < 1e-12);
  const InverseOutcome ik = inverse(k, ClPoint{Vec3d(0, 0, 300.0), Vec3d::UnitZ()}, Vec3d(0, 0, -300.0));
  REQUIRE(ik.ok());
  CHECK(ik.command->words().norm() < 1e-9);
}

TEST_CASE("parasitic motion: a tilted axis moves the plate sideways and spins it; the table takes it up") {
  const Kinematics k(seed_machine());
  const double tilt = deg_to_rad(25.0);
  const ClPoint cl{Vec3d(0, 0, 0), Vec3d(std::sin(tilt), 0, std::cos(tilt))};
  const InverseOutcome ik = inverse(k, cl, Vec3d(0, 0, -250.0));
  REQUIRE(ik.ok());
  // the pin-plane constraints hold on the nominal machine
  for (const ChainFrame& c : k.chains())
    CHECK(std::abs(ik.machine_T_plate.apply(c.ball_in_plate_mm).dot(c.tangential)) < 1e-9);
  // a tilt toward +X (toward chain a) in the plane of chain a: no spin, plate shifted in x only
  const Vec3d tcp = ik.machine_T_plate.t - k.geometry().tip_offset_mm() * cl.axis;
  CHECK(std::abs(tcp.x()) > 1.0);  // the parasitic translation is not small
  CHECK(ik.command->table_mm.x() == Approx(-tcp.x()).margin(1e-9));
  CHECK(std::abs(ik.command->table_mm.y()) < 1e-9);
  // chains b and c are mirror images about the XZ plane
  CHECK(ik.command->slider_mm[1] == Approx(ik.command->slider_mm[2]).margin(1e-9));
  // a general tilt: the pin-plane constraints leave no torsion (in tilt-and-torsion angles: the
  // plate is the level plate turned about e_z × u), but x, y move with the azimuth
  const double az = deg_to_rad(40.0);
  const ClPoint cl2{Vec3d(0, 0, 0),
                    Vec3d(std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt))};
  const InverseOutcome ik2 = inverse(k, cl2, Vec3d(0, 0, -250.0));
  REQUIRE(ik2.ok());
  const Mat3d no_torsion = Eigen::AngleAxisd(tilt, Vec3d::UnitZ().cross(cl2.axis).normalized()).toRotationMatrix();
  CHECK((ik2.machine_T_plate.R - no_torsion).norm() < 1e-9);
  const Vec3d tcp2 = ik2.machine_T_plate.t - k.geometry().tip_offset_mm() * cl2.axis;
  CHECK(std::abs(tcp2.y()) > 1.0);
}

TEST_CASE("forward(inverse(x)) = x over the workspace, nominal machine") {
  const Kinematics k(seed_machine());
  std::mt19937 rng(7);
  const RoundTrip r = round_trip(k, rng, 3000, 30.0);
  WARN("nominal round trip: " << r.solved << " poses, tip " << r.worst_tip_mm << " mm, axis " << r.worst_axis_rad
                              << " rad");
  CHECK(r.worst_tip_mm < 1e-9);
  CHECK(r.worst_axis_rad < 1e-11);
}

TEST_CASE("forward(inverse(x)) = x with errors of 0.05 mm / 0.05 mrad and of 0.5 mm / 0.5 mrad") {
  for (double scale : {0.05, 0.5}) {
    std::mt19937 rng(11 + static_cast<int>(scale * 100));
    const Kinematics k(seed_machine(), random_errors(rng, scale));
    const RoundTrip r = round_trip(k, rng, 500, 30.0);
    WARN("round trip with errors " << scale << ": tip " << r.worst_tip_mm << " mm, axis " << r.worst_axis_rad
                                   << " rad");
    CHECK(r.worst_tip_mm < 1e-8);
    CHECK(r.worst_axis_rad < 1e-11);
  }
}

TEST_CASE("errors act relative to home: at home the actual machine's tool is at the origin, along +Z") {
  std::mt19937 rng(3);
  const Kinematics k(seed_machine(), random_errors(rng, 0.2));
  const auto tp = k.tool(Vec3d::Zero());
  REQUIRE(tp);
  CHECK(tp->tcp_mm.norm() < 1e-12);
  CHECK((tp->axis - Vec3d::UnitZ()).norm() < 1e-12);
  // but away from home the errors show
  const auto moved = k.tool(Vec3d(200, 150, 250));
  const Kinematics nominal(seed_machine());
  const auto moved_nominal = nominal.tool(Vec3d(200, 150, 250));
  REQUIRE(moved);
  REQUIRE(moved_nominal);
  CHECK((moved->tcp_mm - moved_nominal->tcp_mm).norm() > 1e-3);
}

TEST_CASE("a slider length error of chain a lengthens the screw travel: first-order check") {
  // ds_a shifts pin a by -ds·d_a: the same as commanding s_a + ds on the nominal machine,
  // apart from the home reference.
  trr::Machine m = seed_machine();
  Errors e;
  e.chain[0].ds = 0.3;
  const Kinematics k(m, e), nominal(m);
  const Vec3d s(180, 200, 220);
  const auto a = k.plate(s), b = nominal.plate(s + Vec3d(0.3, 0, 0));
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK((a.machine_T_plate->t - b.machine_T_plate->t).norm() < 1e-9);
}

TEST_CASE("out of reach: a clear failure naming the cause") {
  const Kinematics k(seed_machine());
  SECTION("tool axis tilted too far: a link leaves its reach") {
    trr::Machine narrow;  // no axis limits; links may lean at most 18 deg (16.8 at home, 19.2 at 30 deg tilt)
    narrow.geometry.max_link_angle_rad = deg_to_rad(18.0);
    const Kinematics ku(narrow);
    CHECK(inverse(ku, ClPoint{Vec3d(0, 0, 0), Vec3d::UnitZ()}, Vec3d(0, 0, -300)).ok());
    const double tilt = deg_to_rad(30.0);
    const InverseOutcome ik =
        inverse(ku, ClPoint{Vec3d(0, 0, 0), Vec3d(std::sin(tilt), 0, std::cos(tilt))}, Vec3d(0, 0, -300));
    CHECK_FALSE(ik.ok());
    INFO(ik.failure);
    CHECK(ik.failure.find("link of chain") != std::string::npos);
  }
  SECTION("above home: a slider below 0") {
    const InverseOutcome ik = inverse(k, ClPoint{Vec3d(0, 0, 0), Vec3d::UnitZ()}, Vec3d(0, 0, 20));
    CHECK_FALSE(ik.ok());
    INFO(ik.failure);
    CHECK(ik.failure.find("U-20.0000 is outside the limits [0, 600]") != std::string::npos);
  }
  SECTION("table beyond its travel") {
    const InverseOutcome ik = inverse(k, ClPoint{Vec3d(450, 0, 0), Vec3d::UnitZ()}, Vec3d(0, 0, -300));
    CHECK_FALSE(ik.ok());
    CHECK(ik.failure.find("X450.0000") != std::string::npos);
  }
  SECTION("tool axis horizontal") {
    const InverseOutcome ik = inverse(k, ClPoint{Vec3d(0, 0, 0), Vec3d::UnitX()}, Vec3d(0, 0, -300));
    CHECK_FALSE(ik.ok());
    CHECK_FALSE(ik.failure.empty());
  }
}

TEST_CASE("the forward solve's analytic Jacobian agrees with central differences") {
  std::mt19937 rng(5);
  const Errors e = random_errors(rng, 0.5);
  const auto chains = chain_frames(Geometry{}, e);
  for (int n = 0; n < 20; ++n) {
    Rigidd pose;
    pose.R = rotation_vector<double>(Vec3d(draw(rng, -0.4, 0.4), draw(rng, -0.4, 0.4), draw(rng, -0.1, 0.1)));
    pose.t = Vec3d(draw(rng, -50, 50), draw(rng, -50, 50), draw(rng, 0, 300));
    const Vec3d s(draw(rng, 0, 500), draw(rng, 0, 500), draw(rng, 0, 500));
    Eigen::Matrix<double, 6, 1> f0, fp, fm;
    Eigen::Matrix<double, 6, 6> J, unused, fd;
    plate_residuals(chains, s, pose, f0, J);
    for (int k = 0; k < 6; ++k) {
      const double h = k < 3 ? 1e-4 : 1e-7;
      Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
      d[k] = h;
      Rigidd plus = pose, minus = pose;
      plus.t += d.head<3>();
      plus.R = rotation_vector<double>(Vec3d(d.tail<3>())) * pose.R;
      minus.t -= d.head<3>();
      minus.R = rotation_vector<double>(Vec3d(-d.tail<3>())) * pose.R;
      plate_residuals(chains, s, plus, fp, unused);
      plate_residuals(chains, s, minus, fm, unused);
      fd.col(k) = (fp - fm) / (2 * h);
    }
    CHECK((fd - J).norm() < 1e-5 * J.norm());
  }
}
