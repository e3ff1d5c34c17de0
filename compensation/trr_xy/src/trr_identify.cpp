// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_identify.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace ncpost::trr {
namespace {

struct Residual {
  Eigen::VectorXd r;  ///< measured − predicted (mm)
};

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
  Errors e;
  Eigen::VectorXd r = residuals(m, e, nominal, data);
  stats_um(r, res.rms_before_um, res.max_before_um);
  const Eigen::Index n = kParameterCount;
  Eigen::MatrixXd J(r.size(), n);
  Eigen::VectorXd scale(n);
  for (int it = 0; it < o.max_iterations; ++it) {
    for (int k = 0; k < kParameterCount; ++k) {
      const double h = Errors::is_angle(k) ? 1e-5 : 1e-2;
      Errors ep = e, em = e;
      ep[k] += h;
      em[k] -= h;
      // d(predicted)/dp = −d(residual)/dp
      J.col(k) = (residuals(m, em, nominal, data) - residuals(m, ep, nominal, data)) / (2.0 * h);
      scale[k] = J.col(k).norm();
    }
    // a column that is (nearly) zero is a parameter the data cannot see at all: scaling it to unit
    // norm would only magnify the differencing noise, so it stays zero
    const double floor = 1e-7 * scale.maxCoeff();
    Eigen::MatrixXd Js = J;
    for (int k = 0; k < kParameterCount; ++k) {
      if (scale[k] > floor) Js.col(k) /= scale[k];
      else { Js.col(k).setZero(); scale[k] = 1.0; }
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const double cut = o.rank_tolerance * sv[0];
    Eigen::VectorXd step_scaled = Eigen::VectorXd::Zero(n);
    int rank = 0;
    for (Eigen::Index i = 0; i < sv.size(); ++i) {
      if (sv[i] <= cut) continue;
      ++rank;
      step_scaled += svd.matrixV().col(i) * (svd.matrixU().col(i).dot(r) / sv[i]);
    }
    res.iterations = it + 1;
    res.singular_values.assign(sv.data(), sv.data() + sv.size());
    res.identifiability.rank = rank;
    res.identifiability.parameters = kParameterCount;
    res.identifiability.null_space.clear();
    for (Eigen::Index i = 0; i < sv.size(); ++i) {
      if (sv[i] > cut) continue;
      // the direction in the column-scaled parameters (each parameter in units of equal effect)
      const Eigen::VectorXd d = svd.matrixV().col(i);
      comp::NullDirection dir;
      for (int k = 0; k < kParameterCount; ++k)
        if (std::abs(d[k]) >= 0.05) dir.emplace_back(Errors::name(k), d[k]);
      res.identifiability.null_space.push_back(dir);
    }
    // standard deviations from the residual at this iterate (noise estimate) through the seen
    // directions; a parameter with a share in the null space gets none (it is not determined)
    {
      const double dof = std::max<double>(1.0, static_cast<double>(r.size() - rank));
      const double sigma2 = r.squaredNorm() / dof;
      res.uncertainty.assign(kParameterCount, -1.0);
      for (int k = 0; k < kParameterCount; ++k) {
        double var = 0.0, null_share = 0.0;
        for (Eigen::Index i = 0; i < sv.size(); ++i) {
          const double v = svd.matrixV()(k, i);
          if (sv[i] > cut) var += v * v / (sv[i] * sv[i]);
          else null_share += v * v;
        }
        if (null_share < 1e-6) res.uncertainty[static_cast<std::size_t>(k)] = std::sqrt(sigma2 * var) / scale[k];
      }
    }
    const Eigen::VectorXd step = scale.cwiseInverse().asDiagonal() * step_scaled;
    // take the step, halved while the model cannot be solved or the residual grows
    double factor = 1.0;
    bool taken = false;
    for (int tries = 0; tries < 20 && !taken; ++tries, factor *= 0.5) {
      Errors trial = e;
      for (int k = 0; k < kParameterCount; ++k) trial[k] += factor * step[k];
      try {
        const Eigen::VectorXd rt = residuals(m, trial, nominal, data);
        if (rt.squaredNorm() <= r.squaredNorm() * (1.0 + 1e-12)) {
          e = trial;
          r = rt;
          taken = true;
        }
      } catch (const std::runtime_error&) {
      }
    }
    if (!taken) break;
    bool small = true;
    for (int k = 0; k < kParameterCount; ++k)
      if (std::abs(factor * 2.0 * step[k]) > (Errors::is_angle(k) ? 1e-11 : 1e-8)) small = false;
    if (small) break;
  }
  stats_um(r, res.rms_after_um, res.max_after_um);
  res.errors = e;
  return res;
}

}  // namespace ncpost::trr
