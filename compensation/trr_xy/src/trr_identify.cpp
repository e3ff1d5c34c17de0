// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_identify.hpp"

#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

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
/// Halvings of a step that cannot be solved or makes the residual grow, before the fit stops.
constexpr int kStepHalvings = 20;
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

/// The Jacobian of the predicted deviations by central differences, its columns scaled to unit norm
/// (`scale` holds the norms; an unseen column stays zero with scale 1: scaling it up would only
/// magnify the differencing noise).
struct ScaledJacobian {
  Eigen::MatrixXd columns;
  Eigen::VectorXd scale;
};

ScaledJacobian scaled_jacobian(const Problem& p, const Errors& e, Eigen::Index rows) {
  Eigen::MatrixXd J(rows, kParameterCount);
  Eigen::VectorXd scale(kParameterCount);
  for (int k = 0; k < kParameterCount; ++k) {
    const double h = Errors::is_angle(k) ? kDifferenceStepRad : kDifferenceStepMm;
    Errors ep = e, em = e;
    ep[k] += h;
    em[k] -= h;
    // d(predicted)/dp = −d(residual)/dp
    J.col(k) = (p.residuals_at(em) - p.residuals_at(ep)) / (2.0 * h);
    scale[k] = J.col(k).norm();
  }
  const double floor = kUnseenColumnShare * scale.maxCoeff();
  for (int k = 0; k < kParameterCount; ++k) {
    if (scale[k] > floor) {
      J.col(k) /= scale[k];
    } else {
      J.col(k).setZero();
      scale[k] = 1.0;
    }
  }
  return {std::move(J), std::move(scale)};
}

using Svd = Eigen::JacobiSVD<Eigen::MatrixXd>;

/// The minimum-norm Gauss–Newton step in the scaled parameters through the directions above `cut`,
/// and how many there are (the rank).
Eigen::VectorXd truncated_step(const Svd& svd, const Eigen::VectorXd& r, double cut, int& rank) {
  const Eigen::VectorXd& sv = svd.singularValues();
  Eigen::VectorXd step_scaled = Eigen::VectorXd::Zero(kParameterCount);
  rank = 0;
  for (Eigen::Index i = 0; i < sv.size(); ++i) {
    if (sv[i] <= cut) continue;
    ++rank;
    step_scaled += svd.matrixV().col(i) * (svd.matrixU().col(i).dot(r) / sv[i]);
  }
  return step_scaled;
}

/// The directions the data cannot see (singular values at or below `cut`), in the column-scaled
/// parameters (each parameter in units of equal effect).
comp::Identifiability identifiability_of(const Svd& svd, double cut, int rank) {
  comp::Identifiability id;
  id.rank = rank;
  id.parameters = kParameterCount;
  const Eigen::VectorXd& sv = svd.singularValues();
  for (Eigen::Index i = 0; i < sv.size(); ++i) {
    if (sv[i] > cut) continue;
    const Eigen::VectorXd d = svd.matrixV().col(i);
    comp::NullDirection dir;
    for (int k = 0; k < kParameterCount; ++k)
      if (std::abs(d[k]) >= kShownNullWeight) dir.emplace_back(Errors::name(k), d[k]);
    id.null_space.push_back(dir);
  }
  return id;
}

/// Standard deviations (mm, rad) from the residual `r` (noise estimate) through the seen directions;
/// −1 for a parameter with a share in the null space (it is not determined).
std::vector<double> uncertainty_of(const Svd& svd, double cut, const Eigen::VectorXd& scale, const Eigen::VectorXd& r,
                                   int rank) {
  const Eigen::VectorXd& sv = svd.singularValues();
  const double dof = std::max<double>(1.0, static_cast<double>(r.size() - rank));
  const double sigma2 = r.squaredNorm() / dof;
  std::vector<double> out(kParameterCount, -1.0);
  for (int k = 0; k < kParameterCount; ++k) {
    double var = 0.0, null_share = 0.0;
    for (Eigen::Index i = 0; i < sv.size(); ++i) {
      const double v = svd.matrixV()(k, i);
      if (sv[i] > cut) var += v * v / (sv[i] * sv[i]);
      else null_share += v * v;
    }
    if (null_share < kUndeterminedNullShare) out[static_cast<std::size_t>(k)] = std::sqrt(sigma2 * var) / scale[k];
  }
  return out;
}

/// Takes `step` from `e` (residual `r`), halved while the model cannot be solved or the residual
/// grows: the factor taken (e and r updated), or nullopt when no halving helps.
std::optional<double> take_step(const Problem& p, const Eigen::VectorXd& step, Errors& e, Eigen::VectorXd& r) {
  double factor = 1.0;
  for (int tries = 0; tries < kStepHalvings; ++tries, factor *= 0.5) {
    Errors trial = e;
    for (int k = 0; k < kParameterCount; ++k) trial[k] += factor * step[k];
    try {
      const Eigen::VectorXd rt = p.residuals_at(trial);
      if (rt.squaredNorm() <= r.squaredNorm() * (1.0 + 1e-12)) {
        e = trial;
        r = rt;
        return factor;
      }
    } catch (const std::runtime_error&) {
    }
  }
  return std::nullopt;
}

/// True when the step taken (`factor` of `step`) moves no parameter by more than the convergence bounds.
bool converged(const Eigen::VectorXd& step, double factor) {
  for (int k = 0; k < kParameterCount; ++k)
    if (std::abs(factor * step[k]) > (Errors::is_angle(k) ? kConvergedRad : kConvergedMm)) return false;
  return true;
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
  Errors e;
  Eigen::VectorXd r = problem.residuals_at(e);
  stats_um(r, res.rms_before_um, res.max_before_um);
  for (int it = 0; it < o.max_iterations; ++it) {
    const ScaledJacobian J = scaled_jacobian(problem, e, r.size());
    const Svd svd(J.columns, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const double cut = o.rank_tolerance * sv[0];
    int rank = 0;
    const Eigen::VectorXd step_scaled = truncated_step(svd, r, cut, rank);
    res.iterations = it + 1;
    res.singular_values.assign(sv.data(), sv.data() + sv.size());
    res.identifiability = identifiability_of(svd, cut, rank);
    res.uncertainty = uncertainty_of(svd, cut, J.scale, r, rank);  // at this iterate
    const Eigen::VectorXd step = J.scale.cwiseInverse().asDiagonal() * step_scaled;
    const std::optional<double> factor = take_step(problem, step, e, r);
    if (!factor || converged(step, *factor)) break;
  }
  stats_um(r, res.rms_after_um, res.max_after_um);
  res.errors = e;
  return res;
}

}  // namespace ncpost::trr
