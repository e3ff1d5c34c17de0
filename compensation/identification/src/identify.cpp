// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/identify.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ncpost/compensation/fit/damped_least_squares.hpp"
#include "ncpost/compensation/fit/scaled_svd.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/compensation/residuals.hpp"

namespace ncpost::comp {
namespace {

void residual_stats_um(const Eigen::VectorXd& r, double& rms_um, double& max_um) {
  rms_um = r.size() ? 1e3 * std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
  max_um = r.size() ? 1e3 * r.cwiseAbs().maxCoeff() : 0.0;
}

char letter_of(int component) { return "XYZABC"[component]; }

/// A plausible size of a parameter (fit/rank.hpp): 10 µm, 50 µrad, over 300 mm of travel
/// for polynomial terms, over an hour for drift rates.
double typical_size(const Machine& m, const ParameterSpec& s) {
  const double base = s.is_angle() ? 5e-5 : 0.01;
  switch (s.kind) {
    case ParameterKind::polynomial:
      return base / std::pow(300.0, s.order);
    case ParameterKind::reversal:
      return m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary() ? 5e-5 : 0.01;
    case ParameterKind::drift:
      switch (s.drift) {
        case DriftBasis::linear:
          return 0.01 / 3600.0;
        case DriftBasis::quadratic:
          return 0.01 / (3600.0 * 3600.0);
        case DriftBasis::exponential:
          return 0.01;
        case DriftBasis::time_constant:
          return 300.0;
      }
      return 0.01;
    default:
      return base;
  }
}

/// A null vector's component below this is left out of the null direction ...
constexpr double kNullComponent = 1e-12;
/// ... and below this out of the combinations reported for a pinned parameter.
constexpr double kCombinationWeightBallbar = 0.05;

/// Row weights of the fit (IdentifyOptions::set_weights), scaled to rms 1; ones without weights.
Eigen::VectorXd row_weights(const std::vector<MeasurementSet>& sets, const IdentifyOptions& o, Eigen::Index m_count) {
  Eigen::VectorXd row_weight = Eigen::VectorXd::Ones(m_count);
  if (o.set_weights.empty()) return row_weight;
  if (o.set_weights.size() != sets.size()) throw std::invalid_argument("set_weights: one weight per measurement set");
  Eigen::Index at = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const Eigen::Index len = static_cast<Eigen::Index>(sets[s].rows.size()) * sets[s].values_per_row();
    row_weight.segment(at, len).setConstant(o.set_weights[s]);
    at += len;
  }
  if (m_count > 0) row_weight /= std::sqrt(row_weight.squaredNorm() / double(m_count));
  return row_weight;
}

/// The fit of the `kept` parameters (layout indices) from `values` by the fitting core; the
/// residuals weighted by `row_weight`.
DampedSummary fit_kept(const ResidualProblem& prob, const std::vector<int>& kept, const Eigen::VectorXd& row_weight,
                       const IdentifyOptions& o, const std::vector<double>& values, const Eigen::VectorXd& r0) {
  auto full = [&](const Eigen::VectorXd& x) {
    std::vector<double> v = values;
    for (std::size_t i = 0; i < kept.size(); ++i)
      v[static_cast<std::size_t>(kept[i])] = x[static_cast<Eigen::Index>(i)];
    return v;
  };
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    return row_weight.cwiseProduct(prob.residuals(full(x)));
  };
  p.jacobian = [&](const Eigen::VectorXd& x) -> Eigen::MatrixXd {
    return row_weight.asDiagonal() * prob.jacobian(full(x), kept);
  };
  Eigen::VectorXd x0(static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i)
    x0[static_cast<Eigen::Index>(i)] = values[static_cast<std::size_t>(kept[i])];
  DampedOptions d;
  d.loss = {o.loss, o.loss_scale_um * 1e-3};
  d.max_iterations = o.max_iterations;
  d.initial_damping = 0.0;  // Gauss–Newton first: the residuals are nearly linear in the errors
  return levenberg_marquardt(p, x0, row_weight.cwiseProduct(r0), d);
}

/// The values and standard uncertainties of the kept parameters, and their covariance, into res:
/// s²·(JᵀWJ)⁻¹ (scaled_svd.hpp), s² = Σ w r² / (m − n), W the robust weights at the solution.
void kept_results(const std::vector<std::string>& names, const std::vector<int>& kept, const Eigen::MatrixXd& J_kept,
                  const IdentifyOptions& o, const std::vector<double>& values, const Eigen::VectorXd& r_weighted,
                  IdentifyResult& res) {
  const Eigen::Index n = static_cast<Eigen::Index>(kept.size());
  const Eigen::VectorXd w = RobustLoss{o.loss, o.loss_scale_um * 1e-3}.weights(r_weighted);
  const double dof = std::max<double>(1.0, double(r_weighted.size() - n));
  const double s2 = (w.array() * r_weighted.array().square()).sum() / dof;
  const Eigen::MatrixXd cov = scaled_svd(w.cwiseSqrt().asDiagonal() * J_kept).covariance(s2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::string& name = names[static_cast<std::size_t>(kept[static_cast<std::size_t>(i)])];
    res.parameters.set(name, values[static_cast<std::size_t>(kept[static_cast<std::size_t>(i)])]);
    res.uncertainty.set(name, std::sqrt(std::max(0.0, cov(i, i))));
  }
  res.covariance = cov;
}

/// What the data cannot separate (at the prior): the pinned parameters, their null directions and
/// the combinations the kept ones stand for.
void describe_identifiability(const RankAnalysis& prior_rank, const std::vector<std::string>& names,
                              const std::vector<int>& free, const std::vector<double>& values, IdentifyResult& res) {
  Identifiability& id = res.identifiability;
  id.rank = res.rank.rank;
  id.parameters = static_cast<int>(free.size());
  for (std::size_t p = 0; p < prior_rank.pinned.size(); ++p) {
    const int col = prior_rank.pinned[p];
    const std::string& pname = names[static_cast<std::size_t>(free[static_cast<std::size_t>(col)])];
    id.pinned.push_back(pname);
    const Eigen::VectorXd& v = prior_rank.null_vectors[p];
    NullDirection dir;
    for (Eigen::Index c = 0; c < v.size(); ++c)
      if (std::abs(v[c]) > kNullComponent)
        dir.emplace_back(names[static_cast<std::size_t>(free[static_cast<std::size_t>(c)])], v[c]);
    id.null_space.push_back(dir);
    // fitted kept value = true value + coefficient · (true value of the pinned one − prior)
    std::string text;
    const double up = v[col] / prior_rank.column_norms[col];
    for (Eigen::Index c = 0; c < v.size(); ++c) {
      if (c == col || std::abs(v[c]) < kCombinationWeightBallbar || prior_rank.column_norms[c] <= 0.0) continue;
      const double coef = -(v[c] / prior_rank.column_norms[c]) / up;
      const std::string& kname = names[static_cast<std::size_t>(free[static_cast<std::size_t>(c)])];
      text += fmt::format("{}{} stands for {} {} {:.6g}·{}", text.empty() ? "" : "; ", kname, kname,
                          coef < 0 ? "-" : "+", std::abs(coef), pname);
    }
    if (text.empty()) text = pname + " has no effect on these data";
    id.combinations.push_back(fmt::format("{} pinned at {:g} ({})", pname,
                                          values[static_cast<std::size_t>(free[static_cast<std::size_t>(col)])], text));
  }
}

/// The residual statistics per file, before (`r0`) and after (`r`), unweighted.
void file_residuals(const std::vector<MeasurementSet>& sets, const Eigen::VectorXd& r0, const Eigen::VectorXd& r,
                    IdentifyResult& res) {
  Eigen::Index at = 0;
  for (const auto& s : sets) {
    FileResidual f;
    f.file = s.file;
    f.type = s.type;
    const Eigen::Index len = static_cast<Eigen::Index>(s.rows.size()) * s.values_per_row();
    f.values = static_cast<std::size_t>(len);
    residual_stats_um(r0.segment(at, len), f.rms_nominal_um, f.max_nominal_um);
    residual_stats_um(r.segment(at, len), f.rms_after_um, f.max_after_um);
    res.files.push_back(f);
    at += len;
  }
}

}  // namespace

std::string IdentifyOptions::validate() const {
  if (!(loss_scale_um > 0.0)) return "the loss scale must be positive";
  if (max_iterations < 1) return "max_iterations must be at least 1";
  if (!(rank_tolerance > 0.0 && rank_tolerance < 1.0)) return "rank_tolerance must be in (0, 1)";
  for (double w : set_weights)
    if (!(w > 0.0 && std::isfinite(w))) return "set weights must be positive";
  return {};
}

std::vector<std::string> basic_parameters(const Machine& m) {
  std::vector<std::string> names, zeros;
  for (int k = 0; k < m.rotary_count(); ++k) {
    const Axis& a = m.rotary(k);
    for (int c = 0; c < 6; ++c) {
      Vec3d e = Vec3d::Zero();
      e[c % 3] = 1.0;
      const std::string n = fmt::format("E{}0{}", letter_of(c), a.letter);
      const bool along = std::abs(e.dot(a.direction)) > 0.999;
      if (c < 3 && !along) names.push_back(n);
      if (c >= 3) (along ? zeros : names).push_back(n);
    }
  }
  // offsets and tilts axis by axis, then the zero errors
  names.insert(names.end(), zeros.begin(), zeros.end());
  return names;
}

IdentifyResult identify(const Machine& m, const std::vector<MeasurementSet>& sets,
                        const std::vector<std::string>& candidates, const IdentifyOptions& o) {
  if (const std::string why = o.validate(); !why.empty()) throw std::invalid_argument(why);
  IdentifyResult res;
  res.candidates = candidates;
  std::vector<std::string> names = candidates;
  for (const auto& n : o.fixed.names())
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  ResidualProblem prob{&m, &sets, ModelLayout(m, names)};
  std::vector<double> values(names.size(), 0.0);
  for (std::size_t i = 0; i < names.size(); ++i) values[i] = o.fixed.value_or(names[i], 0.0);
  std::vector<int> free;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (!o.fixed.contains(candidates[i])) free.push_back(static_cast<int>(i));

  const Eigen::VectorXd r0 = prob.residuals(values);
  res.nominal = prob.predictions(values);
  residual_stats_um(r0, res.rms_nominal_um, res.max_nominal_um);
  const Eigen::VectorXd row_weight = row_weights(sets, o, r0.size());

  // 1. identifiability at the prior
  Eigen::VectorXd typical(static_cast<Eigen::Index>(free.size()));
  for (std::size_t i = 0; i < free.size(); ++i)
    typical[static_cast<Eigen::Index>(i)] = typical_size(m, prob.layout.spec(free[i]));
  const RankAnalysis prior_rank = analyse_rank(prob.jacobian(values, free), o.rank_tolerance, typical);
  std::vector<int> kept;
  for (int c : prior_rank.kept) kept.push_back(free[static_cast<std::size_t>(c)]);

  // 2. Levenberg–Marquardt on the kept parameters (residuals weighted during the fit)
  std::vector<double> start = values;
  for (int k : kept)
    start[static_cast<std::size_t>(k)] =
        o.start.value_or(names[static_cast<std::size_t>(k)], values[static_cast<std::size_t>(k)]);
  const DampedSummary fit = fit_kept(prob, kept, row_weight, o, start, o.start.size() ? prob.residuals(start) : r0);
  for (std::size_t i = 0; i < kept.size(); ++i)
    values[static_cast<std::size_t>(kept[i])] = fit.x[static_cast<Eigen::Index>(i)];
  res.iterations = fit.iterations;
  res.converged = fit.converged;
  res.message = fit.converged ? fmt::format("converged in {} iterations", res.iterations)
                              : fmt::format("did not converge in {} iterations", res.iterations);

  // 3. results, uncertainty, identifiability at the solution (one Jacobian: kept ⊂ free)
  const Eigen::MatrixXd J_free = prob.jacobian(values, free);
  res.rank = analyse_rank(J_free, o.rank_tolerance, typical);
  Eigen::MatrixXd J_kept(J_free.rows(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < prior_rank.kept.size(); ++i)
    J_kept.col(static_cast<Eigen::Index>(i)) = row_weight.cwiseProduct(J_free.col(prior_rank.kept[i]));
  kept_results(names, kept, J_kept, o, values, fit.r, res);
  for (const auto& f : o.fixed.names()) res.parameters.set(f, o.fixed.value_or(f, 0.0));
  describe_identifiability(prior_rank, names, free, values, res);

  res.fitted = prob.predictions(values);
  const Eigen::VectorXd r = prob.residuals(values);  // statistics unweighted, in mm
  residual_stats_um(r, res.rms_after_um, res.max_after_um);
  file_residuals(sets, r0, r, res);
  return res;
}

ModelFile to_model_file(const Machine& m, const IdentifyResult& r) {
  ModelFile f;
  f.machine = m.name;
  f.axes = model_axes(m);
  f.parameters = r.parameters;
  f.uncertainty = r.uncertainty;
  f.identifiability = r.identifiability;
  FitSummary s;
  s.rms_before_um = r.rms_after_um;  // basic model = final model until residual analysis adds effects
  s.max_before_um = r.max_after_um;
  s.rms_after_um = r.rms_after_um;
  s.max_after_um = r.max_after_um;
  s.rms_nominal_um = r.rms_nominal_um;
  s.max_nominal_um = r.max_nominal_um;
  f.fit = s;
  return f;
}

}  // namespace ncpost::comp
