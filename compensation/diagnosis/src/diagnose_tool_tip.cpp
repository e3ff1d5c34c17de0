// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_tool_tip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

PoseRegion measured_region(const Machine& m, const std::vector<MeasurementSet>& sets) {
  PoseRegion r;
  r.lo.assign(m.axes.size(), INFINITY);
  r.hi.assign(m.axes.size(), -INFINITY);
  for (const auto& s : sets)
    for (const auto& row : s.rows)
      for (std::size_t i = 0; i < m.axes.size(); ++i) {
        r.lo[i] = std::min(r.lo[i], row.command[static_cast<int>(i)]);
        r.hi[i] = std::max(r.hi[i], row.command[static_cast<int>(i)]);
      }
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    if (r.lo[i] > r.hi[i]) r.lo[i] = r.hi[i] = 0.0;  // no rows
  return r;
}

namespace {

/// An axis counts as held at one position when its commands span less than this (mm or rad).
constexpr double kOnePositionMm = 1e-3, kOnePositionRad = 1e-5;

bool one_position(const Axis& a, double lo, double hi) {
  return hi - lo < (a.is_rotary() ? kOnePositionRad : kOnePositionMm);
}

}  // namespace

std::string PoseRegion::description(const Machine& m) const {
  std::string out;
  for (std::size_t i = 0; i < m.axes.size() && i < lo.size(); ++i) {
    const Axis& a = m.axes[i];
    const double k = a.is_rotary() ? 180.0 / kPi : 1.0;
    const char* unit = a.is_rotary() ? "°" : " mm";
    out += (out.empty() ? "" : ", ") + (one_position(a, lo[i], hi[i])
                                            ? fmt::format("{} {:g}{} only", a.letter, lo[i] * k, unit)
                                            : fmt::format("{} {:g} … {:g}{}", a.letter, lo[i] * k, hi[i] * k, unit));
  }
  return out;
}

std::string PoseRegion::single_position_axes(const Machine& m) const {
  std::string out;
  for (std::size_t i = 0; i < m.axes.size() && i < lo.size(); ++i)
    if (one_position(m.axes[i], lo[i], hi[i])) out += (out.empty() ? "" : ", ") + std::string(1, m.axes[i].letter);
  return out;
}

ToolTipComparison compare_tool_tip(const Machine& m, const ErrorParameters& final_model,
                                   const ErrorParameters& basic_model, const ErrorParameters& final_sigma,
                                   const Eigen::MatrixXd& final_covariance, int poses, const PoseRegion* region) {
  const MachineModel actual(m, final_model);
  const MachineModel basic(m, basic_model);
  // models with one fitted parameter stepped by its standard deviation (finite differences)
  const Eigen::Index n = static_cast<Eigen::Index>(final_sigma.size());
  const bool with_sigma = n > 0 && final_covariance.rows() == n && final_covariance.cols() == n;
  std::vector<std::unique_ptr<MachineModel>> stepped;
  std::vector<double> step;
  if (with_sigma)
    for (Eigen::Index i = 0; i < n; ++i) {
      ErrorParameters p = final_model;
      const std::string& name = final_sigma.names()[static_cast<std::size_t>(i)];
      step.push_back(std::max(final_sigma.values()[static_cast<std::size_t>(i)], 1e-12));
      p.set(name, final_model.value_or(name, 0.0) + step.back());
      stepped.push_back(std::make_unique<MachineModel>(m, p));
    }
  double sum_s = 0.0;
  const Setup setup;
  std::mt19937_64 rng(20261122);
  ToolTipComparison c;
  c.poses = poses;
  double sum_u = 0.0, sum_b = 0.0;
  for (int k = 0; k < poses; ++k) {
    AxisPosition q;
    for (std::size_t i = 0; i < m.axes.size(); ++i) {
      const Axis& a = m.axes[i];
      double lo = a.is_rotary() ? -kPi : -250.0, hi = a.is_rotary() ? kPi : 250.0;
      if (a.limits) {
        lo = std::max(lo, a.limits->min);
        hi = std::min(hi, a.limits->max);
      }
      if (region && i < region->lo.size()) lo = region->lo[i], hi = region->hi[i];
      q[static_cast<int>(i)] = hi > lo ? std::uniform_real_distribution<double>(lo, hi)(rng) : lo;
    }
    const auto pa = actual.tool_pose(q, setup);
    const auto pb = basic.tool_pose(q, setup);
    const auto pn = forward(m, q, setup);
    const double u = 1e3 * (pa.tip_mm - pn.tip_mm).norm();
    const double b = 1e3 * (pa.tip_mm - pb.tip_mm).norm();
    c.uncompensated_max_um = std::max(c.uncompensated_max_um, u);
    c.basic_left_max_um = std::max(c.basic_left_max_um, b);
    c.basic_left_axis_max_urad = std::max(c.basic_left_axis_max_urad, 1e6 * (pa.axis - pb.axis).norm());
    sum_u += u * u;
    sum_b += b * b;
    if (with_sigma) {
      Eigen::MatrixXd J(3, n);
      for (Eigen::Index i = 0; i < n; ++i)
        J.col(i) = (stepped[static_cast<std::size_t>(i)]->tool_pose(q, setup).tip_mm - pa.tip_mm) /
                   step[static_cast<std::size_t>(i)];
      const double s = 1e3 * std::sqrt(std::max(0.0, (J * final_covariance * J.transpose()).trace()));
      c.final_sigma_max_um = std::max(c.final_sigma_max_um, s);
      sum_s += s * s;
    }
  }
  if (poses > 0) {
    c.uncompensated_rms_um = std::sqrt(sum_u / poses);
    c.basic_left_rms_um = std::sqrt(sum_b / poses);
    c.final_sigma_rms_um = std::sqrt(sum_s / poses);
  }
  return c;
}

ToolTipComparison within_measured_region(ToolTipComparison c, const Machine& m, const std::vector<MeasurementSet>& sets,
                                         const ErrorParameters& final_model, const ErrorParameters& basic_model,
                                         const ErrorParameters& final_sigma, const Eigen::MatrixXd& final_covariance,
                                         int poses) {
  const PoseRegion region = measured_region(m, sets);
  const ToolTipComparison inside =
      compare_tool_tip(m, final_model, basic_model, final_sigma, final_covariance, poses, &region);
  c.measured_region = region.description(m);
  c.single_position_axes = region.single_position_axes(m);
  c.measured_uncompensated_max_um = inside.uncompensated_max_um;
  c.measured_sigma_max_um = inside.final_sigma_max_um;
  c.measured_sigma_rms_um = inside.final_sigma_rms_um;
  return c;
}

}  // namespace ncpost::comp
