// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_identify.hpp"

#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include "ncpost/compensation/fit/damped_least_squares.hpp"
#include "ncpost/compensation/fit/scaled_svd.hpp"

namespace ncpost::trr {
namespace {

/// Central-difference steps of the Jacobian (header comment): 0.01 mm, 1e-5 rad.
constexpr double kDifferenceStepMm = 1e-2;
constexpr double kDifferenceStepRad = 1e-5;
/// A Jacobian column below this share of the largest is a parameter the data cannot see at all.
constexpr double kUnseenColumnShare = 1e-7;
/// Null-space weights below this are left out of the report.
constexpr double kShownNullWeight = 0.05;
/// A parameter with at least this share of its variance in the null space is not determined.
constexpr double kUndeterminedNullShare = 1e-6;
/// The fit has converged when no parameter moves by more than this (mm, rad).
constexpr double kConvergedMm = 1e-8;
constexpr double kConvergedRad = 1e-11;

Eigen::VectorXd residuals(const Machine& m, const Errors& e, const Kinematics& nominal,
                          const std::vector<ProbeMeasurement>& data) {
  const Kinematics k(m, e);
  Eigen::VectorXd r(3 * static_cast<Eigen::Index>(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i) {
    const auto p = predicted_deviation(k, nominal, data[i].slider_mm, data[i].stylus_mm);
    if (!p) throw std::runtime_error("identify: a probing pose cannot be solved on the model");
    r.segment<3>(3 * static_cast<Eigen::Index>(i)) = data[i].deviation_mm - *p;
  }
  return r;
}

void stats_um(const Eigen::VectorXd& r, double& rms, double& max) {
  rms = 1000.0 * std::sqrt(r.squaredNorm() / std::max<Eigen::Index>(1, r.size()));
  max = 1000.0 * (r.size() ? r.cwiseAbs().maxCoeff() : 0.0);
}

/// The fit's problem: the machine, the nominal machine the deviations are measured against, the data.
struct Problem {
  const Machine& machine;
  const Kinematics& nominal;
  const std::vector<ProbeMeasurement>& data;
  Eigen::VectorXd residuals_at(const Errors& e) const { return residuals(machine, e, nominal, data); }
};

/// d residual / d parameter by central differences (the residual is measured − predicted).
Eigen::MatrixXd jacobian(const Problem& p, const Errors& e, Eigen::Index rows) {
  Eigen::MatrixXd J(rows, kParameterCount);
  for (int k = 0; k < kParameterCount; ++k) {
    const double h = Errors::is_angle(k) ? kDifferenceStepRad : kDifferenceStepMm;
    Errors ep = e, em = e;
    ep[k] += h;
    em[k] -= h;
    J.col(k) = (p.residuals_at(ep) - p.residuals_at(em)) / (2.0 * h);
  }
  return J;
}

Errors errors_of(const Eigen::VectorXd& x) {
  Errors e;
  for (int k = 0; k < kParameterCount; ++k) e[k] = x[k];
  return e;
}

/// The directions the data cannot see, in the column-scaled parameters (each parameter in units
/// of equal effect), and the standard deviations (mm, rad) from the residual `r` through the seen
/// directions: −1 for a parameter with a share in the null space (it is not determined).
void identifiability_and_uncertainty(const comp::ScaledSvd& svd, const Eigen::VectorXd& r, IdentifyResult& res) {
  comp::Identifiability& id = res.identifiability;
  id.rank = svd.rank;
  id.parameters = kParameterCount;
  for (const Eigen::VectorXd& d : svd.null_space()) {
    comp::NullDirection dir;
    for (int k = 0; k < kParameterCount; ++k)
      if (std::abs(d[k]) >= kShownNullWeight) dir.emplace_back(Errors::name(k), d[k]);
    id.null_space.push_back(dir);
  }
  const double dof = std::max<double>(1.0, static_cast<double>(r.size() - svd.rank));
  const Eigen::MatrixXd cov = svd.covariance(r.squaredNorm() / dof);
  const Eigen::VectorXd null_share = svd.null_share();
  res.uncertainty.assign(kParameterCount, -1.0);
  for (int k = 0; k < kParameterCount; ++k)
    if (null_share[k] < kUndeterminedNullShare)
      res.uncertainty[static_cast<std::size_t>(k)] = std::sqrt(std::max(0.0, cov(k, k)));
  const Eigen::VectorXd& sv = svd.svd.singularValues();
  res.singular_values.assign(sv.data(), sv.data() + sv.size());
}

}  // namespace

std::vector<Command> probing_commands(const Machine& m) {
  const Kinematics nominal(m);
  std::vector<Command> poses;
  for (double z : {-170.0, -260.0, -350.0})
    for (double tilt_deg : {0.0, 10.0, 20.0, 30.0})
      for (int j = 0; j < (tilt_deg == 0.0 ? 1 : 12); ++j) {
        const double tilt = deg_to_rad(tilt_deg), az = deg_to_rad(30.0 * j + 15.0);
        ClPoint cl;
        cl.axis = Vec3d(std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt));
        cl.tip_mm = Vec3d(0, 0, z);
        const InverseOutcome ik = inverse(nominal, cl, Vec3d::Zero());
        if (ik.ok()) poses.push_back(*ik.command);
      }
  return poses;
}

std::vector<Vec3d> probing_poses(const Machine& m) {
  std::vector<Vec3d> s;
  for (const Command& c : probing_commands(m)) s.push_back(c.slider_mm);
  return s;
}

std::optional<Vec3d> predicted_deviation(const Kinematics& k, const Kinematics& nominal, const Vec3d& slider_mm,
                                         double stylus_mm) {
  const auto t = k.tool(slider_mm), n = nominal.tool(slider_mm);
  if (!t || !n) return std::nullopt;
  const Vec3d p_true = t->tcp_mm - stylus_mm * t->axis, p_nominal = n->tcp_mm - stylus_mm * n->axis;
  return -(p_true - p_nominal);
}

std::vector<ProbeMeasurement> simulate_probing(const Kinematics& truth, const std::vector<Vec3d>& poses,
                                               const std::vector<double>& styli_mm, double noise_um, unsigned seed) {
  const Kinematics nominal(truth.machine());
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_um / 1000.0);
  std::vector<ProbeMeasurement> out;
  for (double L : styli_mm)
    for (const Vec3d& s : poses) {
      const auto d = predicted_deviation(truth, nominal, s, L);
      if (!d) throw std::runtime_error("simulate: a probing pose cannot be solved on the true machine");
      ProbeMeasurement pm{s, L, *d};
      for (int c = 0; c < 3; ++c) pm.deviation_mm[c] += noise(rng);
      out.push_back(pm);
    }
  return out;
}

IdentifyResult identify(const Machine& m, const std::vector<ProbeMeasurement>& data, const IdentifyOptions& o) {
  IdentifyResult res;
  const Kinematics nominal(m);
  const Problem problem{m, nominal, data};
  const Eigen::VectorXd r0 = problem.residuals_at(Errors{});
  stats_um(r0, res.rms_before_um, res.max_before_um);
  comp::LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    try {
      return problem.residuals_at(errors_of(x));
    } catch (const std::runtime_error&) {
      return std::nullopt;  // a probing pose the trial model cannot solve: the step is rejected
    }
  };
  p.jacobian = [&](const Eigen::VectorXd& x) { return jacobian(problem, errors_of(x), r0.size()); };
  comp::DampedOptions d;
  d.max_iterations = o.max_iterations;
  d.initial_damping = 0.0;
  d.unseen_share = kUnseenColumnShare;
  d.relative_cut = o.rank_tolerance;
  d.step_tolerance.resize(kParameterCount);
  for (int k = 0; k < kParameterCount; ++k) d.step_tolerance[k] = Errors::is_angle(k) ? kConvergedRad : kConvergedMm;
  const comp::DampedSummary sol = comp::levenberg_marquardt(p, Eigen::VectorXd::Zero(kParameterCount), r0, d);
  res.errors = errors_of(sol.x);
  res.iterations = sol.iterations;
  stats_um(sol.r, res.rms_after_um, res.max_after_um);
  identifiability_and_uncertainty(
      comp::scaled_svd(jacobian(problem, res.errors, r0.size()), kUnseenColumnShare, o.rank_tolerance), sol.r, res);
  return res;
}

}  // namespace ncpost::trr
