// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <tuple>
#include <utility>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "ncpost/compensation/diagnose_attribution.hpp"
#include "ncpost/compensation/diagnose_effect_size.hpp"
#include "ncpost/compensation/diagnose_screening.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/compensation/residuals.hpp"

namespace ncpost::comp {
namespace {

double sum_of_squares(const IdentifyResult& r, Eigen::Index m) {
  const double rms_mm = 1e-3 * r.rms_after_um;
  return rms_mm * rms_mm * double(m);
}

/// The model being built: fitted names, held values, its fit.
struct Model {
  std::vector<std::string> names;
  ErrorParameters held;
  IdentifyResult fit;
};

std::vector<std::string> layout_names(const Model& model) {
  std::vector<std::string> n = model.names;
  for (const auto& h : model.held.names())
    if (std::find(n.begin(), n.end(), h) == n.end()) n.push_back(h);
  return n;
}

/// The layout with the user's fixed parameters after it, and the value of each: fitted, else
/// held, else fixed, else 0 (the point the screening and the separation test linearize at).
std::pair<std::vector<std::string>, std::vector<double>> layout_with_values(const Model& model,
                                                                            const ErrorParameters& fixed) {
  std::vector<std::string> names = layout_names(model);
  for (const auto& f : fixed.names())
    if (std::find(names.begin(), names.end(), f) == names.end()) names.push_back(f);
  std::vector<double> values;
  for (const auto& n : names)
    values.push_back(model.fit.parameters.value_or(n, model.held.value_or(n, fixed.value_or(n, 0.0))));
  return {std::move(names), std::move(values)};
}

/// Residual (mm) of a fitted model: fitted values, held values, prior (0) for pinned ones.
Eigen::VectorXd residual_of(const Machine& m, const std::vector<MeasurementSet>& sets, const Model& model,
                            const IdentifyOptions& o) {
  std::vector<std::string> names = layout_names(model);
  for (const auto& f : o.fixed.names())
    if (std::find(names.begin(), names.end(), f) == names.end()) names.push_back(f);
  ResidualProblem prob{&m, &sets, ModelLayout(m, names)};
  std::vector<double> values;
  for (const auto& n : names)
    values.push_back(model.fit.parameters.value_or(n, model.held.value_or(n, o.fixed.value_or(n, 0.0))));
  return prob.residuals(values);
}

/// The fit of `names` with `held` fixed; it starts from `start` (a fit of a model this one
/// extends or retunes: a warm start, the same minimum in fewer iterations).
IdentifyResult fit_model(const Machine& m, const std::vector<MeasurementSet>& sets,
                         const std::vector<std::string>& names, const ErrorParameters& held,
                         const IdentifyOptions& base, const ErrorParameters& start = {}) {
  IdentifyOptions o = base;
  for (std::size_t i = 0; i < held.size(); ++i) o.fixed.set(held.names()[i], held.values()[i]);
  for (std::size_t i = 0; i < start.size(); ++i)
    if (!o.start.contains(start.names()[i])) o.start.set(start.names()[i], start.values()[i]);
  return identify(m, sets, names, o);
}

/// Time stamp of every residual (stacked as residuals.hpp).
Eigen::VectorXd residual_times(const std::vector<MeasurementSet>& sets) {
  std::vector<double> t;
  for (const auto& s : sets)
    for (const auto& row : s.rows)
      for (int v = 0; v < s.values_per_row(); ++v) t.push_back(row.time_s);
  return Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
}

struct Screened {
  int candidate = -1;
  Candidate spec;  ///< with the chosen drift terms and tau
  double drop = 0.0;
  double p_linear = 1.0;
  Eigen::MatrixXd basis;                ///< orthonormal new directions it adds to the model
  std::vector<std::string> equivalent;  ///< candidates with the same effect on these data
};

/// Re-chooses the time constant of every drift in the model by refits (its screening chose it
/// with the model of that step: effects added later change the best value): the sum of squares
/// at tau·2^(j/2), j = −2..2 (moved on while the best is at an end, up to 4 times), then a
/// parabola in log tau through the best and its neighbours.
void retune_drift(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseOptions& o, double t_span,
                  Model& model, Eigen::Index count) {
  const std::vector<std::string> held = model.held.names();
  const double step = 0.5 * std::log(2.0), lo = std::log(30.0), hi = std::log(4.0 * t_span);
  for (const auto& name : held) {
    if (name.size() < 4 || name.substr(name.size() - 4) != ":tau") continue;
    std::map<int, std::pair<double, Model>> fits;  // grid index → (sum of squares, fit)
    const double origin = std::log(*model.held.get(name));
    auto at = [&](int j) -> double {
      auto it = fits.find(j);
      if (it != fits.end()) return it->second.first;
      const double log_tau = origin + step * j;
      if (log_tau < lo || log_tau > hi) return 1e300;
      Model trial = model;
      trial.held.set(name, std::exp(log_tau));
      trial.fit = fit_model(m, sets, trial.names, trial.held, o.identify, model.fit.parameters);
      const double ssr = trial.fit.converged ? sum_of_squares(trial.fit, count) : 1e300;
      fits.emplace(j, std::make_pair(ssr, std::move(trial)));
      return ssr;
    };
    int best = 0;
    for (int j = -2; j <= 2; ++j)
      if (at(j) < at(best)) best = j;
    for (int moves = 0; moves < 4 && (at(best - 1) < at(best) || at(best + 1) < at(best)); ++moves)
      best = at(best - 1) < at(best + 1) ? best - 1 : best + 1;
    Model chosen = fits.at(best).second;
    double chosen_ssr = at(best);
    const double a = at(best - 1), c = at(best + 1), den = a - 2.0 * chosen_ssr + c;
    if (a < 1e299 && c < 1e299 && den > 0.0) {
      const double shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
      Model refined = model;
      refined.held.set(name, std::exp(origin + step * (best + shift)));
      refined.fit = fit_model(m, sets, refined.names, refined.held, o.identify, model.fit.parameters);
      const double r = sum_of_squares(refined.fit, count);
      if (refined.fit.converged && r < chosen_ssr) chosen = std::move(refined), chosen_ssr = r;
    }
    if (chosen.fit.converged && chosen.fit.identifiability.pinned == model.fit.identifiability.pinned)
      model = std::move(chosen);
  }
}

/// Sets the size of an added effect; returns why it is not plausible (empty if it is).
std::string apply_size(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseOptions& o,
                       AddedEffect& e) {
  const EffectSize size = effect_size(m, sets, e.candidate, e.values, e.uncertainty, o.plausible);
  e.size = size.size;
  e.size_sigma = size.sigma;
  e.size_is_angle = size.is_angle;
  return size.implausible;
}

/// Orthonormal basis of the (normalised) columns of J listed in `cols`.
Eigen::MatrixXd basis_of(const Eigen::MatrixXd& J, const std::vector<int>& cols) {
  Eigen::MatrixXd K(J.rows(), static_cast<Eigen::Index>(cols.size()));
  for (std::size_t j = 0; j < cols.size(); ++j) {
    K.col(static_cast<Eigen::Index>(j)) = J.col(cols[j]);
    if (K.col(static_cast<Eigen::Index>(j)).norm() > 0) K.col(static_cast<Eigen::Index>(j)).normalize();
  }
  if (K.cols() == 0) return K;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(K);
  return qr.householderQ() * Eigen::MatrixXd::Identity(J.rows(), K.cols());
}

/// Orthonormal basis of the column space of M (its numerical rank only: a rank-deficient M, e.g.
/// two alternatives that act alike, must not bring arbitrary directions in).
Eigen::MatrixXd range_of(const Eigen::MatrixXd& M) {
  if (M.cols() == 0) return M;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeThinU);
  const Eigen::VectorXd sv = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sv.size() && sv[rank] > 1e-6 * std::max(sv[0], 1e-300)) ++rank;
  return svd.matrixU().leftCols(rank);
}

/// Could the other components of the same order explain what an added effect explains? Its
/// columns and theirs (`alternatives`, pairs cos/sin, named `names`), both off the rest of the model
/// (`Q`; `off` its own columns off it): the smallest canonical correlation over its directions,
/// and the alternatives that carry it (correlation above 0.5).
void alias_evidence(const Eigen::MatrixXd& J, const Eigen::MatrixXd& Q, const Eigen::MatrixXd& off,
                    const std::vector<int>& alternatives, const std::vector<std::string>& names, AddedEffect& e) {
  e.alias_correlation = 0.0;
  e.alias_of.clear();
  if (alternatives.empty()) return;
  const Eigen::MatrixXd A = basis_of(J, alternatives);
  const Eigen::MatrixXd alt_off = A - Q * (Q.transpose() * A);
  const Eigen::MatrixXd QA = range_of(alt_off), QE = range_of(off);
  Eigen::VectorXd rho;
  if (QA.cols() > 0 && QE.cols() > 0) rho = Eigen::JacobiSVD<Eigen::MatrixXd>(QE.transpose() * QA).singularValues();
  // every direction of it, not just one: the smallest of its QE.cols() canonical correlations
  e.alias_correlation = rho.size() >= QE.cols() && rho.size() ? rho.minCoeff() : 0.0;
  // the alternatives that carry it: those whose own columns correlate most with it
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::vector<int> pair{alternatives[2 * k], alternatives[2 * k + 1]};
    const Eigen::MatrixXd P = basis_of(J, pair);
    const Eigen::MatrixXd p_off = P - Q * (Q.transpose() * P);
    const Eigen::MatrixXd QP = range_of(p_off);
    const double r = QP.cols() && QE.cols()
                         ? Eigen::JacobiSVD<Eigen::MatrixXd>(QE.transpose() * QP).singularValues().maxCoeff()
                         : 0.0;
    if (r > 0.5) e.alias_of.push_back(fmt::format("{} ({:.2f})", names[k], r));
  }
}

/// The verdict on an added effect from its evidence: an alias of the other components of its
/// order, an alias of the model, or real.
std::string separation_text(const AddedEffect& e, bool has_alternatives) {
  std::string with;
  for (const auto& [n, rho] : e.correlated)
    with += fmt::format("{}{} (correlation {:.3f})", with.empty() ? "" : ", ", n, rho);
  std::string alts;
  for (const auto& n : e.alias_of) alts += (alts.empty() ? "" : ", ") + n;
  if (e.alias_correlation > 0.99)
    return fmt::format(
        "an alias of {}: what it explains, the same order of the other components explains as "
        "well (canonical correlation {:.4f} off the rest of the model); the data cannot tell "
        "them apart — measure from a second sphere position (another height and radius)",
        alts.empty() ? "the other components of its order" : alts, e.alias_correlation);
  if (e.separation_sine < 0.05)
    return fmt::format(
        "an alias{}: its columns lie within sine {:.3f} of the rest of the model, the data "
        "cannot separate it",
        with.empty() ? " of the model" : " of " + with, e.separation_sine);
  return fmt::format(
      "real: separable from the rest of the model (sine {:.3f}){}{}, significant on its own "
      "(F = {:.4g})",
      e.separation_sine, with.empty() ? "" : "; correlated with " + with,
      !has_alternatives ? std::string()
                        : fmt::format("; the other components of its order reproduce it only to "
                                      "canonical correlation {:.4f}{}",
                                      e.alias_correlation, alts.empty() ? "" : " (" + alts + ")"),
      e.f_statistic);
}

/// The columns a separation test looks at: the names and values of the model's layout, the
/// fitted ones (indices into names), and for each added harmonic its alternatives.
struct SeparationColumns {
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<int> fitted;
  std::vector<std::vector<int>> alternatives;  ///< per added effect: the alternatives' columns (into fitted)
  std::vector<std::vector<std::string>> alternative_names;
};

/// Whether `n` is a parameter of the machine that the first `model_names` names do not hold.
bool usable_alternative(const Machine& m, const std::vector<std::string>& names, std::size_t model_names,
                        const std::string& n) {
  const auto end = names.begin() + static_cast<long>(model_names);
  return std::find(names.begin(), end, n) == end && parse_parameter_name(n, m).spec;
}

/// The alternatives of each added harmonic: the same order of the axis's other components that
/// are not in the model (for a radial EXC:h2, the tilts EAC:h2 and EBC:h2 among them), at 0,
/// appended to the columns (one column each, shared by the effects).
void add_alternatives(const Machine& m, const std::vector<AddedEffect>& added, SeparationColumns& cols) {
  cols.alternatives.assign(added.size(), {});
  cols.alternative_names.assign(added.size(), {});
  const std::size_t model_names = cols.names.size();
  std::map<std::string, int> alternative_column;
  for (std::size_t a = 0; a < added.size(); ++a) {
    const std::string& e = added[a].candidate.effect;
    const ParseResult spec = parse_parameter_name(added[a].candidate.parameters.front(), m);
    if (!spec.spec || spec.spec->kind != ParameterKind::harmonic) continue;
    for (const char c : std::string("XYZABC")) {
      if (c == e[1]) continue;
      const std::string alt = fmt::format("E{}{}", c, e.substr(2));
      bool usable = true;
      for (const char* part : {":cos", ":sin"})
        if (!usable_alternative(m, cols.names, model_names, alt + part)) usable = false;
      if (!usable) continue;
      cols.alternative_names[a].push_back(alt);
      for (const char* part : {":cos", ":sin"}) {
        const std::string n = alt + part;
        if (!alternative_column.count(n)) {
          cols.names.push_back(n);
          cols.values.push_back(0.0);
          alternative_column[n] = static_cast<int>(cols.fitted.size());
          cols.fitted.push_back(static_cast<int>(cols.names.size()) - 1);
        }
        cols.alternatives[a].push_back(alternative_column[n]);
      }
    }
  }
}

/// The columns (into `fitted`) of a candidate's parameters.
std::vector<int> columns_of(const SeparationColumns& cols, const Candidate& c) {
  std::vector<int> out;
  for (std::size_t j = 0; j < cols.fitted.size(); ++j)
    if (std::find(c.parameters.begin(), c.parameters.end(), cols.names[static_cast<std::size_t>(cols.fitted[j])]) !=
        c.parameters.end())
      out.push_back(static_cast<int>(j));
  return out;
}

/// The separation of the added effect `a` from the rest of the model's columns of J, the added
/// effects it correlates with, and the evidence against its alternatives.
void separate_effect(const Eigen::MatrixXd& J, const SeparationColumns& cols, std::size_t a,
                     std::vector<AddedEffect>& added) {
  AddedEffect& e = added[a];
  const std::vector<int> own = columns_of(cols, e.candidate);
  if (own.empty()) return;
  std::vector<int> rest;
  for (int j = 0; j < static_cast<int>(cols.fitted.size()); ++j)
    if (std::find(own.begin(), own.end(), j) == own.end()) rest.push_back(j);
  const Eigen::MatrixXd Q = basis_of(J, rest), E = basis_of(J, own);
  const Eigen::MatrixXd off = E - Q * (Q.transpose() * E);
  e.separation_sine = Eigen::JacobiSVD<Eigen::MatrixXd>(off).singularValues().minCoeff();
  e.correlated.clear();
  for (const auto& other : added) {
    if (&other == &e) continue;
    const std::vector<int> theirs = columns_of(cols, other.candidate);
    if (theirs.empty()) continue;
    const Eigen::MatrixXd F = basis_of(J, theirs);
    const double rho = Eigen::JacobiSVD<Eigen::MatrixXd>(E.transpose() * F).singularValues().maxCoeff();
    if (rho > 0.9) e.correlated.emplace_back(other.candidate.effect, rho);
  }
  alias_evidence(J, Q, off, cols.alternatives[a], cols.alternative_names[a], e);
  e.separation = separation_text(e, !cols.alternatives[a].empty());
}

/// Whether the data can tell each added effect from the rest of the final model (issue 17):
/// the sine of its columns to the span of all other fitted columns, and the added effects its
/// columns correlate with (largest canonical correlation above 0.9).
void separate_effects(const Machine& m, const std::vector<MeasurementSet>& sets, const Model& model,
                      const DiagnoseOptions& o, DiagnoseResult& out) {
  if (out.added.empty() || !model.fit.converged) return;
  SeparationColumns cols;
  std::tie(cols.names, cols.values) = layout_with_values(model, o.identify.fixed);
  for (std::size_t i = 0; i < cols.names.size(); ++i)
    if (model.fit.uncertainty.contains(cols.names[i])) cols.fitted.push_back(static_cast<int>(i));
  const std::size_t model_columns = cols.fitted.size();
  add_alternatives(m, out.added, cols);
  const ResidualProblem prob{&m, &sets, ModelLayout(m, cols.names)};
  const Eigen::MatrixXd J = prob.jacobian(cols.values, cols.fitted);
  cols.fitted.resize(model_columns);
  for (std::size_t a = 0; a < out.added.size(); ++a) separate_effect(J, cols, a, out.added);
}

/// Step 1 of diagnose(): the candidates screened at the current solution (linearised), sorted by
/// the drop in Σr² they buy, those that act alike on the data merged into one class.
struct ScreenStep {
  std::vector<Screened> screened;
  int tested = 0;   ///< candidates not aliased with the model
  double s0 = 0.0;  ///< Σr² of the current model (mm²)
};

/// Candidates that act alike on these data (their bases span the same directions within `tol`)
/// form one class, represented by the first in catalogue order (e.g. EXC:h1 and EYC:h1 once the
/// location offsets of C are in); `screened` is sorted by drop, only its first 24 are compared.
std::vector<Screened> merge_equivalent(std::vector<Screened> screened, double tol) {
  std::vector<Screened> classes;
  const std::size_t compare = std::min<std::size_t>(screened.size(), 24);
  std::vector<bool> merged(screened.size(), false);
  for (std::size_t i = 0; i < screened.size(); ++i) {
    if (merged[i]) continue;
    std::vector<std::size_t> members{i};
    if (i < compare)
      for (std::size_t j = i + 1; j < compare; ++j)
        if (!merged[j] && same_directions(screened[i].basis, screened[j].basis, tol)) {
          members.push_back(j);
          merged[j] = true;
        }
    std::size_t lead = members.front();
    for (std::size_t k : members)
      if (screened[k].candidate < screened[lead].candidate) lead = k;
    Screened c = screened[lead];
    for (std::size_t k : members)
      if (k != lead) c.equivalent.push_back(screened[k].spec.effect);
    classes.push_back(std::move(c));
  }
  return classes;
}

ScreenStep screen_step(const Machine& m, const std::vector<MeasurementSet>& sets, const Model& model,
                       const std::vector<Candidate>& catalogue, const DiagnoseOptions& o, const Eigen::VectorXd& times,
                       double t_span, Eigen::Index count) {
  auto [names, values] = layout_with_values(model, o.identify.fixed);
  std::vector<int> kept;
  for (std::size_t i = 0; i < model.names.size(); ++i)
    if (model.fit.uncertainty.contains(model.names[i])) kept.push_back(static_cast<int>(i));
  std::vector<std::vector<int>> cand_columns(catalogue.size());
  std::vector<int> columns = kept;
  for (std::size_t c = 0; c < catalogue.size(); ++c) {
    for (const auto& p : catalogue[c].parameters) {
      names.push_back(p);
      values.push_back(0.0);
      cand_columns[c].push_back(static_cast<int>(columns.size()));
      columns.push_back(static_cast<int>(names.size()) - 1);
    }
    for (std::size_t h = 0; h < catalogue[c].held.size(); ++h) {
      names.push_back(catalogue[c].held.names()[h]);
      values.push_back(catalogue[c].held.values()[h]);
    }
  }
  const ResidualProblem prob{&m, &sets, ModelLayout(m, names)};
  const Eigen::VectorXd r = prob.residuals(values);
  const Eigen::MatrixXd J = prob.jacobian(values, columns);
  const Eigen::Index p0 = static_cast<Eigen::Index>(kept.size());
  Eigen::MatrixXd Q(count, 0);
  if (p0 > 0) {
    Eigen::MatrixXd K = J.leftCols(p0);
    for (Eigen::Index c = 0; c < p0; ++c)
      if (K.col(c).norm() > 0) K.col(c).normalize();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(K);
    Q = qr.householderQ() * Eigen::MatrixXd::Identity(count, p0);
  }
  const double s0 = r.squaredNorm();
  std::vector<Screened> screened;
  int tested = 0;
  for (std::size_t c = 0; c < catalogue.size(); ++c) {
    Screened s;
    s.candidate = static_cast<int>(c);
    s.spec = catalogue[c];
    Eigen::MatrixXd C(count, static_cast<Eigen::Index>(cand_columns[c].size()));
    for (std::size_t j = 0; j < cand_columns[c].size(); ++j)
      C.col(static_cast<Eigen::Index>(j)) = J.col(cand_columns[c][j]);
    int aliased = -1;
    if (s.spec.kind == CandidateKind::drift) {
      const DriftScreen drift =
          screen_drift(s.spec.effect, Q, C.col(0), r, times, t_span, o.alias_tolerance, o.significance);
      aliased = drift.aliased ? 0 : -1;
      s.spec.parameters = drift.parameters;
      s.spec.held = drift.held;
      s.drop = drift.drop;
      s.basis = drift.basis;
    } else {
      s.basis = added_basis(Q, C, o.alias_tolerance, aliased);
      s.drop = (s.basis.transpose() * r).squaredNorm();
    }
    if (aliased >= 0) continue;
    ++tested;
    const double k = double(s.spec.parameters.size());
    const double dof = double(count - p0) - k;
    s.p_linear = f_upper_tail((s.drop / k) / (std::max(s0 - s.drop, 1e-300) / dof), k, dof);
    screened.push_back(s);
  }
  std::sort(screened.begin(), screened.end(), [](const Screened& a, const Screened& b) { return a.drop > b.drop; });
  screened = merge_equivalent(std::move(screened), 10.0 * o.alias_tolerance);
  return {std::move(screened), tested, s0};
}

/// Step 2 of diagnose(): the best few screened candidates refitted and weighed (partial F test,
/// identifiability, size, an instrument's own signature); the accepted one with the smallest BIC
/// and the model with it, or none. Why the others were not taken goes to `rejected`.
struct WeighStep {
  std::optional<AddedEffect> best;
  Model model;
};

WeighStep weigh_step(const Machine& m, const std::vector<MeasurementSet>& sets, const Model& model,
                     const ScreenStep& step, const DiagnoseOptions& o, double alpha, Eigen::Index count,
                     std::vector<RejectedEffect>& rejected) {
  const std::vector<Screened>& screened = step.screened;
  const int tested = step.tested;
  const double s0 = step.s0;
  std::optional<AddedEffect> best;
  Model best_model;
  int refits = 0;
  for (const Screened& s : screened) {
    if (refits >= o.refit_top || s.p_linear >= alpha) break;
    ++refits;
    Model trial = model;
    for (const auto& p : s.spec.parameters) trial.names.push_back(p);
    for (std::size_t h = 0; h < s.spec.held.size(); ++h)
      trial.held.set(s.spec.held.names()[h], s.spec.held.values()[h]);
    trial.fit = fit_model(m, sets, trial.names, trial.held, o.identify, model.fit.parameters);
    RejectedEffect rej{s.spec.effect, trial.fit.rms_after_um, 1.0, {}};
    const double s1 = sum_of_squares(trial.fit, count);
    const int p1 = static_cast<int>(trial.fit.uncertainty.size());
    const double k = double(s.spec.parameters.size());
    const double dof = double(count - p1);
    AddedEffect e;
    e.candidate = s.spec;
    e.equivalent = s.equivalent;
    e.tested = tested;
    e.f_statistic = ((s0 - s1) / k) / (std::max(s1, 1e-300) / dof);
    e.p_value = f_upper_tail(e.f_statistic, k, dof);
    rej.p_value = e.p_value;
    for (const auto& p : s.spec.parameters) {
      e.values.set(p, trial.fit.parameters.value_or(p, 0.0));
      e.uncertainty.set(p, trial.fit.uncertainty.value_or(p, 0.0));
    }
    for (std::size_t h = 0; h < s.spec.held.size(); ++h) e.values.set(s.spec.held.names()[h], s.spec.held.values()[h]);
    std::string why;
    if (!trial.fit.converged) why = "the fit did not converge";
    for (const auto& p : s.spec.parameters)
      if (why.empty() && !trial.fit.uncertainty.contains(p)) why = p + " is pinned: not identifiable with the model";
    if (why.empty() && trial.fit.identifiability.pinned != model.fit.identifiability.pinned)
      why = "it makes a parameter of the model unidentifiable";
    if (why.empty() && !(e.p_value < alpha))
      why = fmt::format("not significant (p = {:.3g}, needs < {:.3g})", e.p_value, alpha);
    if (why.empty()) why = apply_size(m, sets, o, e);
    // an instrument term needs its own signature: with it, the sets it acts on are at their
    // noise (no structure left against any rotary axis); otherwise it is only the closest-
    // looking term to an effect the catalogue does not hold (issue 17)
    if (why.empty() && s.spec.kind == CandidateKind::instrument) {
      const MeasurementType type =
          s.spec.effect == "ballbar:length" ? MeasurementType::ballbar : MeasurementType::sphere;
      const auto left = residual_structure(m, sets, residual_of(m, sets, trial, o.identify), o.significance, &type);
      if (!left.empty())
        why = fmt::format("its own signature is not shown: with it, {} {} against {} still has structure ({})",
                          left.front().file, left.front().value, left.front().axis, left.front().shape);
    }
    if (!why.empty()) {
      rej.reason = why;
      rejected.push_back(rej);
      continue;
    }
    e.rms_before_um = model.fit.rms_after_um;
    e.max_before_um = model.fit.max_after_um;
    e.rms_after_um = trial.fit.rms_after_um;
    e.max_after_um = trial.fit.max_after_um;
    // among the accepted, the one the evidence prefers: the smallest Bayesian information
    // criterion m·ln(S1/m) + p1·ln(m), so a table (tens of nodes) wins over a compact form only
    // where the compact form leaves what the nodes explain (issue 17); for candidates with the
    // same number of parameters this is the smallest S1, as before
    e.bic = double(count) * std::log(std::max(s1, 1e-300) / double(count)) + double(p1) * std::log(double(count));
    if (!best || e.bic < best->bic) {
      if (best) rejected.push_back({best->candidate.effect, best->rms_after_um, best->p_value, "explains less"});
      best = e;
      best_model = trial;
    } else {
      rejected.push_back(
          {e.candidate.effect, e.rms_after_um, e.p_value, "explains less than " + best->candidate.effect});
    }
  }
  return {std::move(best), std::move(best_model)};
}

/// Keeps the added effects that stand on their own evidence beside the structure the final model
/// leaves (diagnose_attribution.hpp); the others go to `not_attributed` and out of the model.
void attribute_with_structure(const Machine& m, const std::vector<MeasurementSet>& sets,
                              const std::vector<std::string>& basic_names, const DiagnoseOptions& o, Model& model,
                              DiagnoseResult& out, const std::function<void(const std::string&)>& say) {
  const Eigen::VectorXd r = residual_of(m, sets, model, o.identify);
  const auto left = residual_structure(m, sets, r, o.significance);
  if (left.empty()) return;
  auto [names, values] = layout_with_values(model, o.identify.fixed);
  std::vector<int> columns;
  std::vector<std::string> fitted;
  for (const auto& n : model.names)
    if (model.fit.uncertainty.contains(n)) {
      columns.push_back(static_cast<int>(std::find(names.begin(), names.end(), n) - names.begin()));
      fitted.push_back(n);
    }
  const ResidualProblem prob{&m, &sets, ModelLayout(m, names)};
  const Eigen::MatrixXd J = prob.jacobian(values, columns);
  const Eigen::MatrixXd nuisance = structure_nuisance(sets, residual_columns(m, sets, r), left, r.size());
  std::vector<AddedEffect> kept;
  std::string dropped;
  for (AddedEffect& e : out.added) {
    std::vector<int> cols;
    Eigen::VectorXd beta(static_cast<Eigen::Index>(e.candidate.parameters.size()));
    for (std::size_t j = 0; j < e.candidate.parameters.size(); ++j) {
      const std::string& p = e.candidate.parameters[j];
      cols.push_back(static_cast<int>(std::find(fitted.begin(), fitted.end(), p) - fitted.begin()));
      beta[static_cast<Eigen::Index>(j)] = model.fit.parameters.value_or(p, 0.0);
    }
    const bool all_fitted =
        std::all_of(cols.begin(), cols.end(), [&](int c) { return c < static_cast<int>(fitted.size()); });
    const OwnEvidence ev = all_fitted ? own_evidence(J, r, cols, beta, nuisance) : OwnEvidence{};
    const double alpha = o.significance / std::max(1, e.tested);
    const bool own = ev.separation > o.alias_tolerance && ev.p_value < alpha;
    say(fmt::format(
        "{} beside the unexplained structure: separation {:.3g}, F = {:.4g}, p = {:.3g} (needs < {:.3g}): {}",
        e.candidate.effect, ev.separation, ev.f_statistic, ev.p_value, alpha, own ? "kept" : "not attributed"));
    if (own) {
      kept.push_back(e);
    } else {
      out.not_attributed.push_back(e.candidate.effect);
      dropped += (dropped.empty() ? "" : ", ") + e.candidate.effect;
    }
  }
  if (dropped.empty()) return;
  out.stop_reason += fmt::format(
      "; structure remains that no candidate explains ({} {} against {}: {}); {} not attributed "
      "(no evidence of {} own once that structure is absorbed)",
      left.front().file, left.front().value, left.front().axis, left.front().shape, dropped,
      out.not_attributed.size() == 1 ? "its" : "their");
  say("not attributed: " + dropped);
  out.added = std::move(kept);
  Model refit{basic_names, {}, out.basic};
  for (const auto& e : out.added) {
    for (const auto& p : e.candidate.parameters) refit.names.push_back(p);
    for (std::size_t h = 0; h < e.candidate.held.size(); ++h)
      refit.held.set(e.candidate.held.names()[h],
                     model.held.value_or(e.candidate.held.names()[h], e.candidate.held.values()[h]));
  }
  if (!out.added.empty()) refit.fit = fit_model(m, sets, refit.names, refit.held, o.identify, model.fit.parameters);
  if (!refit.fit.converged) refit = Model{basic_names, {}, out.basic}, out.added.clear();
  model = std::move(refit);
}
/// The noise differs between sets (e.g. probing vs ballbar): the final model refitted by weighted
/// least squares, each set weighted by 1/σ, σ its residual rms under the final model.
void refit_weighted_by_set_noise(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseOptions& o,
                                 Model& model, DiagnoseResult& out) {
  if (!o.weight_by_set_noise || sets.size() <= 1 || !model.fit.converged) return;
  IdentifyOptions weighted = o.identify;
  for (const auto& f : model.fit.files) weighted.set_weights.push_back(1.0 / std::max(f.rms_after_um, 1e-3));
  IdentifyResult refit = fit_model(m, sets, model.names, model.held, weighted, model.fit.parameters);
  if (refit.converged && refit.identifiability.pinned == model.fit.identifiability.pinned) {
    model.fit = std::move(refit);
    out.set_noise_um.clear();
    for (const auto& f : model.fit.files) out.set_noise_um.push_back(f.rms_after_um);
  }
}

/// The values of earlier effects move in later refits: the final ones into every added effect.
void report_final_values(const Model& model, DiagnoseResult& out) {
  for (auto& e : out.added) {
    for (const auto& p : e.candidate.parameters) {
      e.values.set(p, model.fit.parameters.value_or(p, 0.0));
      e.uncertainty.set(p, model.fit.uncertainty.value_or(p, 0.0));
    }
    for (std::size_t h = 0; h < e.candidate.held.size(); ++h) {
      const std::string& n = e.candidate.held.names()[h];
      const double v = model.held.value_or(n, e.candidate.held.values()[h]);
      e.candidate.held.set(n, v);
      e.values.set(n, v);
    }
  }
}
/// The effect `added` out of the catalogue; a table holds every shape of its function: the
/// harmonics of the same component and axis are then no longer separate candidates
/// (E<c><axis>:t → E<c><axis>:h*).
void drop_from_catalogue(std::vector<Candidate>& catalogue, const std::string& added) {
  const bool table = added.size() > 2 && added.substr(added.size() - 2) == ":t";
  const std::string family = added.substr(0, 3);
  catalogue.erase(std::remove_if(catalogue.begin(), catalogue.end(),
                                 [&](const Candidate& c) {
                                   return c.effect == added || (table && c.effect.rfind(family + ":h", 0) == 0);
                                 }),
                  catalogue.end());
}

}  // namespace

std::string DiagnoseOptions::validate() const {
  if (const std::string why = identify.validate(); !why.empty()) return why;
  if (!(significance > 0.0 && significance < 1.0)) return "significance must be in (0, 1)";
  if (max_effects < 0) return "max_effects must not be negative";
  if (refit_top < 1) return "refit_top must be at least 1";
  if (!(alias_tolerance > 0.0 && alias_tolerance < 1.0)) return "alias_tolerance must be in (0, 1)";
  if (!plausible.valid()) return "the plausible sizes must be positive";
  return {};
}

std::vector<std::string> DiagnoseResult::effects_added() const {
  std::vector<std::string> out;
  for (const auto& e : added) out.push_back(e.candidate.effect);
  return out;
}

DiagnoseResult diagnose(const Machine& m, const std::vector<MeasurementSet>& sets,
                        const std::vector<std::string>& basic_names, const DiagnoseOptions& o) {
  if (const std::string why = o.validate(); !why.empty()) throw std::invalid_argument(why);
  auto say = [&](const std::string& s) {
    if (o.progress) o.progress(s);
  };
  DiagnoseResult out;
  Model model{basic_names, {}, fit_model(m, sets, basic_names, {}, o.identify)};
  out.basic = model.fit;
  out.residual_before_mm = residual_of(m, sets, model, o.identify);
  const Eigen::Index count = out.residual_before_mm.size();
  const Eigen::VectorXd times = residual_times(sets);
  double t_span = times.size() ? times.maxCoeff() : 0.0;
  t_span = std::max(t_span, 60.0);
  say(fmt::format("basic model: rms {:.3f} um, max {:.3f} um", model.fit.rms_after_um, model.fit.max_after_um));

  std::vector<std::string> all_present = basic_names;
  for (const auto& f : o.identify.fixed.names()) all_present.push_back(f);
  std::vector<Candidate> catalogue = candidate_catalogue(m, sets, all_present);

  out.stop_reason = "no candidate effects";
  while (static_cast<int>(out.added.size()) < o.max_effects && !catalogue.empty()) {
    if (!model.fit.converged) {
      out.stop_reason = "the fit did not converge";
      break;
    }
    // ---- 1. screening at the current solution
    const ScreenStep step = screen_step(m, sets, model, catalogue, o, times, t_span, count);
    const std::vector<Screened>& screened = step.screened;
    const double alpha = o.significance / std::max(1, step.tested);
    // ---- 2. refit the best few and weigh the evidence
    out.last_rejected.clear();
    WeighStep weighed = weigh_step(m, sets, model, step, o, alpha, count, out.last_rejected);
    std::optional<AddedEffect>& best = weighed.best;
    Model& best_model = weighed.model;
    const int tested = step.tested;
    if (!best) {
      out.stop_reason = screened.empty() || screened.front().p_linear >= alpha
                            ? fmt::format(
                                  "no candidate explains a significant part of the residual (best: {}, p = {:.3g}; "
                                  "needs < {:.3g})",
                                  screened.empty() ? "none" : screened.front().spec.effect,
                                  screened.empty() ? 1.0 : screened.front().p_linear, alpha)
                            : "no significant candidate is identifiable and plausible";
      break;
    }
    say(fmt::format("added {}: rms {:.3f} -> {:.3f} µm (F = {:.4g}, p = {:.3g}, {} candidates)", best->candidate.effect,
                    best->rms_before_um, best->rms_after_um, best->f_statistic, best->p_value, tested));
    out.added.push_back(*best);
    model = best_model;
    retune_drift(m, sets, o, t_span, model, count);
    drop_from_catalogue(catalogue, best->candidate.effect);
    out.stop_reason = "max_effects reached";
  }
  // No false attribution (issue 17): an effect is found only if, with it, what is left is at the
  // noise or explained by the effects added after it. When the final model still leaves
  // structure, each added effect must stand on its own evidence with every one-axis shape of that
  // structure absorbed (diagnose_attribution.hpp): the ones that only chased it are not
  // attributed, the others are kept and the model refitted with them; the structure is reported
  // (diagnosis.unexplained, with the measurement that would resolve it).
  if (!out.added.empty() && model.fit.converged) attribute_with_structure(m, sets, basic_names, o, model, out, say);
  refit_weighted_by_set_noise(m, sets, o, model, out);
  report_final_values(model, out);
  for (auto& e : out.added) apply_size(m, sets, o, e);
  out.final_fit = model.fit;
  out.final_names = model.names;
  out.held = model.held;
  out.residual_after_mm = residual_of(m, sets, model, o.identify);
  out.noise_um = noise_from_differences_um(sets, out.residual_after_mm);
  out.unexplained = residual_structure(m, sets, out.residual_after_mm, o.significance);
  separate_effects(m, sets, model, o, out);
  out.before = residual_signature(m, sets, out.residual_before_mm);
  out.after = residual_signature(m, sets, out.residual_after_mm);
  return out;
}

ModelFile to_model_file(const Machine& m, const DiagnoseResult& r) {
  ModelFile f = to_model_file(m, r.final_fit);
  f.effects_added = r.effects_added();
  nlohmann::ordered_json d;
  d["effects"] = nlohmann::ordered_json::array();
  for (const auto& e : r.added)
    d["effects"].push_back({{"effect", e.candidate.effect},
                            {"separation_sine", e.separation_sine},
                            {"alias_correlation", e.alias_correlation},
                            {"alias_of", e.alias_of},
                            {"separation", e.separation}});
  d["not_attributed"] = r.not_attributed;
  d["unexplained"] = nlohmann::ordered_json::array();
  for (const auto& u : r.unexplained)
    d["unexplained"].push_back({{"file", u.file},
                                {"component", u.value},
                                {"against", std::string(1, u.axis)},
                                {"shape", u.shape},
                                {"order", u.order},
                                {"spread_um", u.spread_um},
                                {"largest_um", u.largest_um},
                                {"at_deg", u.at_deg},
                                {"F", u.f_statistic},
                                {"p", u.p_value},
                                {"proposal", u.proposal}});
  f.extra["diagnosis"] = d.dump(2);
  if (f.fit) {
    f.fit->rms_before_um = r.basic.rms_after_um;
    f.fit->max_before_um = r.basic.max_after_um;
    f.fit->rms_after_um = r.final_fit.rms_after_um;
    f.fit->max_after_um = r.final_fit.max_after_um;
  }
  return f;
}

}  // namespace ncpost::comp
