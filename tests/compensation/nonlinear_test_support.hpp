// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test support for the nonlinear-error tests: a small geometric error functor, random blocks,
// the seed 001 sample segment, and the GOTO points of the public dome path.
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"

namespace ncpost::test {

inline Machine machine_file(const std::string& name) {
  return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/" + name);
}

/// Location errors of both rotary axes and a command-dependent error motion (mm, rad), about the
/// size of tests/data/scenarios/public-clean/truth.json.
struct LocationErrors {
  template <class S>
  AxisErrorTerms<S> operator()(int axis_index, const S& q, bool /*at_home*/) const {
    AxisErrorTerms<S> e;
    using std::sin;
    if (axis_index == 3) {
      e.location_offset_mm = Vec3<S>(S(0.0), S(0.018), S(-0.012));
      e.location_tilt_rad = Vec3<S>(S(0.0), S(4e-5), S(-2.5e-5));
      e.motion_mm = Vec3<S>(S(0), S(0.004) * sin(q), S(0));
    } else if (axis_index == 4) {
      e.location_offset_mm = Vec3<S>(S(0.015), S(-0.022), S(0.0));
      e.location_tilt_rad = Vec3<S>(S(3e-5), S(-3.5e-5), S(0.0));
      e.motion_rad = Vec3<S>(S(0), S(0), S(2e-5) * sin(S(2) * q));
    }
    return e;
  }
};

/// The seed 001 sample segment (Zhang, Wang, Tang 2023), axes normalised.
inline ClPoint seed001_start() {
  return {Vec3d(-192.4037, 12.3508, 8.6182), Vec3d(0.011639, -0.036377, 0.99027).normalized()};
}
inline ClPoint seed001_end() {
  return {Vec3d(-192.4057, 14.5159, 8.9093), Vec3d(0.005393, -0.068922, 0.99960).normalized()};
}
/// The seed 001 segment as a block on `m`, on the paper's branch: A = arccos(k) >= 0,
/// C = atan2(i, j) (the solution nearest A = 0, C = 180 deg).
inline nonlinear::ClBlock seed001_block(const Machine& m, const Setup& s) {
  AxisPosition previous = home_of(m);
  previous.rotary_rad = Eigen::Vector2d(0.0, 3.14159265358979323846);
  const AxisPosition q0 = *solve(m, seed001_start(), s, previous).position;
  const AxisPosition q1 = *solve(m, seed001_end(), s, q0).position;
  return {seed001_start(), seed001_end(), q0, q1};
}

/// One GOTO of a CL file with its source line.
struct ClLine {
  ClPoint point;
  int line = 0;
  bool rapid = false;  ///< the GOTO follows RAPID
};

/// The GOTO/x,y,z,i,j,k points of a simple APT file (the dome path): enough for these tests,
/// not a CL reader (that is postproc's).
inline std::vector<ClLine> read_gotos(const std::string& path) {
  std::ifstream in(path);
  std::vector<ClLine> out;
  std::string text;
  int line = 0;
  bool rapid = false;
  while (std::getline(in, text)) {
    ++line;
    if (text.rfind("RAPID", 0) == 0) rapid = true;
    if (text.rfind("GOTO/", 0) != 0) continue;
    std::stringstream ss(text.substr(5));
    double v[6] = {0, 0, 0, 0, 0, 1};
    char comma;
    for (int i = 0; i < 6 && ss >> v[i]; ++i) ss >> comma;
    out.push_back({{Vec3d(v[0], v[1], v[2]), Vec3d(v[3], v[4], v[5]).normalized()}, line, rapid});
    rapid = false;
  }
  return out;
}

inline std::string dome_path() {
  return std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/path.cls";
}
inline Setup dome_setup() {
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 80);  // job.json
  return s;
}

/// The blocks of a CL point sequence on the nominal IK, continuity from the previous pose (rapid
/// moves skipped).
inline std::vector<nonlinear::ClBlock> blocks_of(const Machine& m, const Setup& s, const std::vector<ClLine>& path) {
  std::vector<nonlinear::ClBlock> blocks;
  AxisPosition previous = home_of(m);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const IkOutcome o = solve(m, path[i].point, s, previous);
    if (!o.ok()) throw std::runtime_error("IK failed on line " + std::to_string(path[i].line));
    if (i > 0 && !path[i].rapid) blocks.push_back({path[i - 1].point, path[i].point, previous, *o.position});
    previous = *o.position;
  }
  return blocks;
}

/// Inverse kinematics of the actual machine for tests: the nominal solution, then Gauss-Newton on
/// the forward chain with `Errors` (tip and axis residual, finite-difference Jacobian).
template <class Errors>
struct ModelSolver {
  const Machine& machine;
  Setup setup;
  Errors errors;
  IkOutcome operator()(const ClPoint& cl, const AxisPosition& previous) const {
    IkOutcome o = solve(machine, cl, setup, previous);
    if (!o.ok()) return o;
    AxisPosition q = *o.position;
    auto residual = [&](const AxisPosition& x) {
      const auto pose = tool_pose<double>(machine, x, setup, errors);
      Eigen::Matrix<double, 6, 1> r;
      r << pose.tip_mm - cl.tip_mm, 100.0 * (pose.axis - cl.axis.normalized());
      return r;
    };
    for (int it = 0; it < 6; ++it) {
      const Eigen::Matrix<double, 6, 1> r0 = residual(q);
      if (r0.norm() < 1e-11) break;
      Eigen::Matrix<double, 6, 5> jac;
      for (int j = 0; j < 5; ++j) {
        AxisPosition x = q;
        const double h = j < 3 ? 1e-6 : 1e-8;
        x[j] += h;
        jac.col(j) = (residual(x) - r0) / h;
      }
      const Eigen::Matrix<double, 5, 1> step = jac.colPivHouseholderQr().solve(-r0);
      for (int j = 0; j < 5; ++j) q[j] += step[j];
    }
    o.position = q;
    return o;
  }
};

}  // namespace ncpost::test
