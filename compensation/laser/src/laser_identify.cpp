// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_identify.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/fit/damped_least_squares.hpp"
#include "ncpost/compensation/fit/scaled_svd.hpp"
#include "ncpost/compensation/laser_reading.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "laser_problem.hpp"

namespace ncpost::comp {
namespace {

using laser::fill_approach;
using laser::kComponents;
using laser::priority_of;
using laser::Problem;

void stats(const Eigen::VectorXd& r, double& rms, double& max) {
  rms = r.size() ? std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
  max = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
}

std::string why_unseen(const LaserFunction& f) {
  const std::string k = f.kind();
  if (k == "positioning") return "needs a positioning line of the axis";
  if (k.rfind("straightness", 0) == 0) return fmt::format("needs a straightness line in {}", f.component);
  if (k == "roll") return "roll needs straightness lines at two different offsets (ISO 230-1)";
  return fmt::format("{} needs positioning (or straightness) lines at different Abbe offsets", k);
}

/// Two nodes of an axis closer than this are one (mm); a node this near 0 is home.
constexpr double kSameNodeMm = 1e-4;
/// Typical size of a parameter, for the rank analysis: 50 µrad for an angle, 10 µm for a length.
constexpr double kTypicalAngleRad = 5e-5;
constexpr double kTypicalLengthMm = 0.01;
/// The fit stops when no step moves a value by more than this many units ...
constexpr double kConvergedUnits = 1e-3;
/// ... of 1 µrad (angles) and 0.1 µm (lengths).
constexpr double kAngleUnitRad = 1e-6;
constexpr double kLengthUnitMm = 1e-4;
/// The combinations reported: at most this many pinned columns, each with its largest terms
/// (at most kCombinationTerms, each at least kCombinationWeight of the null vector).
constexpr std::size_t kMaxCombinations = 12;
constexpr int kCombinationTerms = 3;
constexpr double kCombinationWeight = 0.05;

/// A parameter that may be fitted, in the order its column is tried (priority_of).
struct Candidate {
  int priority;
  int layout_index;
};

/// The sets into `pb` (approach filled in, moving axis, nodes) and which axes were approached
/// from below and from above; a message when a set is not laser data with values.
std::string gather_sets(Problem& pb, const std::vector<MeasurementSet>& input, std::array<bool, 3>& up,
                        std::array<bool, 3>& down) {
  pb.sets = input;
  for (auto& s : pb.sets) {
    if (!s.has_values) return s.file + ": a plan without values";
    fill_approach(s);
    const int j = laser_moving_axis(s);
    pb.moving.push_back(j);
    for (const auto& r : s.rows) {
      auto& x = pb.nodes[static_cast<std::size_t>(j)];
      if (std::none_of(x.begin(), x.end(), [&](double v) { return std::abs(v - r.command[j]) < kSameNodeMm; }))
        x.push_back(r.command[j]);
      (r.approach > 0 ? up : down)[static_cast<std::size_t>(j)] = true;
    }
    pb.rows += static_cast<Eigen::Index>(s.rows.size());
  }
  return {};
}

/// The layout: every node of every measured axis (home included, fixed at 0) for the six
/// components, and the reversal where an axis was approached both ways; the candidates to fit.
std::vector<Candidate> lay_out(Problem& pb, bool fit_reversal, const std::array<bool, 3>& up,
                               const std::array<bool, 3>& down) {
  std::vector<Candidate> cand;
  for (int a = 0; a < 3; ++a) {
    auto& x = pb.nodes[static_cast<std::size_t>(a)];
    if (x.empty()) continue;
    if (std::none_of(x.begin(), x.end(), [](double v) { return std::abs(v) < kSameNodeMm; })) x.push_back(0.0);
    std::sort(x.begin(), x.end());
    for (int c = 0; c < 6; ++c)
      for (double at : x) {
        const int idx = static_cast<int>(pb.names.size());
        pb.names.push_back(table_parameter_name(kComponents[c], static_cast<char>('X' + a), at));
        pb.node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)].push_back(idx);
        if (std::abs(at) >= kSameNodeMm) cand.push_back({priority_of(a, c), idx});
      }
    if (fit_reversal && up[static_cast<std::size_t>(a)] && down[static_cast<std::size_t>(a)]) {
      pb.reversal_param[static_cast<std::size_t>(a)] = static_cast<int>(pb.names.size());
      cand.push_back({1, static_cast<int>(pb.names.size())});
      pb.names.push_back(fmt::format("reversal:{}", static_cast<char>('X' + a)));
    }
  }
  return cand;
}

/// Columns in priority order (pb.column_of, pb.param_of, res.candidates); the typical size of each.
Eigen::VectorXd order_columns(Problem& pb, std::vector<Candidate> cand, LaserIdentifyResult& res) {
  std::stable_sort(cand.begin(), cand.end(),
                   [](const Candidate& a, const Candidate& b) { return a.priority < b.priority; });
  pb.column_of.assign(pb.names.size(), -1);
  Eigen::VectorXd typical(static_cast<Eigen::Index>(cand.size()));
  for (const auto& c : cand) {
    pb.column_of[static_cast<std::size_t>(c.layout_index)] = static_cast<int>(pb.param_of.size());
    typical[static_cast<Eigen::Index>(pb.param_of.size())] =
        pb.layout.spec(c.layout_index).is_angle() ? kTypicalAngleRad : kTypicalLengthMm;
    pb.param_of.push_back(c.layout_index);
    res.candidates.push_back(pb.names[static_cast<std::size_t>(c.layout_index)]);
  }
  return typical;
}

/// The fitted values and their standard uncertainties (layout order): the fitting core
/// (fit/damped_least_squares.hpp, Gauss–Newton first) on the columns the rank analysis keeps;
/// sets res.rms/max nominal and fit, res.rank, res.iterations.
struct Fit {
  std::vector<double> values, sigma;
};
Fit fit_tables(const Problem& pb, const Eigen::VectorXd& typical, const LaserIdentifyOptions& o,
               LaserIdentifyResult& res) {
  Fit fit{std::vector<double>(pb.names.size(), 0.0), std::vector<double>(pb.names.size(), 0.0)};
  const Eigen::VectorXd r0 = pb.residual(fit.values);
  stats(r0, res.rms_nominal_um, res.max_nominal_um);
  res.rank = analyse_rank(pb.jacobian(fit.values), o.rank_tolerance, typical);
  const std::vector<int>& kept = res.rank.kept;
  auto full = [&](const Eigen::VectorXd& x) {
    std::vector<double> v(pb.names.size(), 0.0);
    for (std::size_t i = 0; i < kept.size(); ++i)
      v[static_cast<std::size_t>(pb.param_of[static_cast<std::size_t>(kept[i])])] = x[static_cast<Eigen::Index>(i)];
    return v;
  };
  // residual = measured − predicted: its Jacobian is −(d prediction / d value) of the kept columns
  auto kept_jacobian = [&](const Eigen::VectorXd& x) -> Eigen::MatrixXd {
    const Eigen::MatrixXd J = pb.jacobian(full(x));
    Eigen::MatrixXd K(J.rows(), static_cast<Eigen::Index>(kept.size()));
    for (std::size_t i = 0; i < kept.size(); ++i) K.col(static_cast<Eigen::Index>(i)) = -J.col(kept[i]);
    return K;
  };
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> { return pb.residual(full(x)); };
  p.jacobian = kept_jacobian;
  DampedOptions d;
  d.max_iterations = o.max_iterations;
  d.initial_damping = 0.0;
  d.step_tolerance.resize(static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i)
    d.step_tolerance[static_cast<Eigen::Index>(i)] =
        kConvergedUnits *
        (pb.layout.spec(pb.param_of[static_cast<std::size_t>(kept[i])]).is_angle() ? kAngleUnitRad : kLengthUnitMm);
  const DampedSummary sol =
      levenberg_marquardt(p, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(kept.size())), r0, d);
  fit.values = full(sol.x);
  res.iterations = sol.iterations;
  stats(sol.r, res.rms_fit_um, res.max_fit_um);
  // uncertainty of the kept values at the solution: s²·(KᵀK)⁻¹ (fit/scaled_svd.hpp)
  const Eigen::Index dof = sol.r.size() - static_cast<Eigen::Index>(kept.size());
  if (dof > 0) {
    const Eigen::MatrixXd cov = scaled_svd(kept_jacobian(sol.x)).covariance(sol.r.squaredNorm() / double(dof));
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const auto ii = static_cast<Eigen::Index>(i);
      fit.sigma[static_cast<std::size_t>(pb.param_of[static_cast<std::size_t>(kept[i])])] =
          std::sqrt(std::max(0.0, cov(ii, ii)));
    }
  }
  return fit;
}

/// The error functions of every measured axis (straightness to the ISO 230-1 reference line),
/// the squareness from the straightness slopes, and the reversals, into res.
void collect_functions(const Problem& pb, const Fit& fit, const LaserIdentifyOptions& o, LaserIdentifyResult& res) {
  std::vector<bool> seen(pb.names.size(), true);
  for (int c : res.rank.pinned) seen[static_cast<std::size_t>(pb.param_of[static_cast<std::size_t>(c)])] = false;
  std::map<std::string, double> slope;  // "EYX" → s
  std::map<std::string, bool> slope_seen;
  for (int a = 0; a < 3; ++a) {
    const auto& x = pb.nodes[static_cast<std::size_t>(a)];
    if (x.empty()) continue;
    for (int c = 0; c < 6; ++c) {
      LaserFunction f;
      f.component = kComponents[c];
      f.axis = static_cast<char>('X' + a);
      f.nodes_mm = x;
      for (int p : pb.node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)]) {
        f.values.push_back(fit.values[static_cast<std::size_t>(p)]);
        f.sigma.push_back(fit.sigma[static_cast<std::size_t>(p)]);
        f.seen.push_back(seen[static_cast<std::size_t>(p)]);
      }
      if (c < 3 && c != a) {
        double range = 0.0;
        f.iso_slope = least_squares_slope(f.nodes_mm, f.values, range);
        f.iso_straightness_um = 1e3 * range;
        for (std::size_t i = 0; i < x.size(); ++i) f.values[i] -= f.iso_slope * x[i];
        slope[f.name()] = f.iso_slope;
        slope_seen[f.name()] = f.fully_seen();
      }
      std::vector<double> yv = f.values;
      f.polynomial_rms = fit_polynomial_through_home(f.nodes_mm, yv, f.polynomial);
      // the curve between the targets: chosen by cross-validation where every node was seen
      f.curve = o.smooth && f.fully_seen()
                    ? choose_laser_curve(f.nodes_mm, f.values, o.dense_step_mm, o.max_legendre_degree)
                    : LaserCurve{};
      if (f.curve.nodes_mm.empty() || f.curve.basis == LaserBasis::linear) {
        f.curve.nodes_mm = f.nodes_mm;
        f.curve.values = f.values;
      }
      res.functions.push_back(f);
    }
  }
  struct Sq {
    const char* name;
    const char* a;
    const char* b;
    double sign;
  };
  for (const Sq& q : {Sq{"EC0Y", "EYX", "EXY", -1.0}, Sq{"EB0Z", "EZX", "EXZ", 1.0}, Sq{"EA0Z", "EZY", "EYZ", -1.0}}) {
    if (slope.count(q.a) && slope.count(q.b) && slope_seen[q.a] && slope_seen[q.b]) {
      res.squareness.set(q.name, q.sign * (slope[q.a] + slope[q.b]));
    } else {
      res.squareness_unseen.push_back(
          fmt::format("{}: needs the straightness {} and {} (their least-squares slopes, "
                      "ISO 230-1)",
                      q.name, q.a, q.b));
    }
  }
  for (int a = 0; a < 3; ++a)
    if (const int p = pb.reversal_param[static_cast<std::size_t>(a)]; p >= 0) {
      res.reversal.set(pb.names[static_cast<std::size_t>(p)], fit.values[static_cast<std::size_t>(p)]);
      res.reversal_sigma.set(pb.names[static_cast<std::size_t>(p)], fit.sigma[static_cast<std::size_t>(p)]);
    }
}

/// The model as written (functions, squareness, reversal) and the residual it leaves.
void write_model(const Machine& m, const Problem& pb, LaserIdentifyResult& res) {
  for (const auto& f : res.functions)
    for (std::size_t i = 0; i < f.curve.nodes_mm.size(); ++i)
      res.parameters.set(table_parameter_name(f.component, f.axis, f.curve.nodes_mm[i]), f.curve.values[i]);
  for (std::size_t i = 0; i < res.squareness.size(); ++i)
    res.parameters.set(res.squareness.names()[i], res.squareness.values()[i]);
  for (std::size_t i = 0; i < res.reversal.size(); ++i)
    res.parameters.set(res.reversal.names()[i], res.reversal.values()[i]);
  const ModelLayout final_layout(m, res.parameters.names());
  Eigen::VectorXd rf(pb.rows);
  Eigen::Index k = 0;
  for (const auto& s : pb.sets) {
    const std::vector<double> p = predict_laser_set(m, s, final_layout, res.parameters.values().data());
    for (std::size_t i = 0; i < s.rows.size(); ++i) rf[k++] = s.rows[i].value[0] - p[i];
  }
  stats(rf, res.rms_after_um, res.max_after_um);
}

/// What the lines cannot see: nodes not seen per function, squareness without its lines, and the
/// combinations the pinned columns act as.
void describe_unseen(LaserIdentifyResult& res) {
  for (const auto& f : res.functions) {
    int total = 0, unseen = 0;
    for (std::size_t i = 0; i < f.seen.size(); ++i) {
      if (std::abs(f.nodes_mm[i]) < kSameNodeMm) continue;
      ++total;
      unseen += !f.seen[i];
    }
    if (unseen == 0) continue;
    res.unseen.push_back(fmt::format("{} ({} of {}): {} of {} nodes not seen — {}", f.name(), f.kind(), f.axis, unseen,
                                     total, why_unseen(f)));
  }
  for (const auto& s : res.squareness_unseen) res.unseen.push_back(s);
  for (std::size_t i = 0; i < res.rank.pinned.size() && i < kMaxCombinations; ++i) {
    const Eigen::VectorXd& v = res.rank.null_vectors[i];
    const int p = res.rank.pinned[i];
    std::string text = res.candidates[static_cast<std::size_t>(p)] + " acts as";
    int terms = 0;
    std::vector<std::pair<double, int>> w;
    for (Eigen::Index c = 0; c < v.size(); ++c)
      if (c != p && std::abs(v[c]) >= kCombinationWeight) w.emplace_back(-std::abs(v[c]), static_cast<int>(c));
    std::sort(w.begin(), w.end());
    for (const auto& [mag, c] : w) {
      if (terms++ == kCombinationTerms) break;
      text +=
          fmt::format(" {}{:.2f}·{}", terms > 1 ? "+ " : "", -v[c] / v[p], res.candidates[static_cast<std::size_t>(c)]);
    }
    if (terms == 0) text += " nothing: without effect on these readings";
    res.combinations.push_back(text + " (column-scaled)");
  }
}

}  // namespace

std::string LaserIdentifyOptions::validate() const {
  if (!(rank_tolerance > 0.0 && rank_tolerance < 1.0)) return "rank tolerance must be in (0, 1)";
  if (max_iterations < 1) return "at least one iteration";
  if (!(dense_step_mm > 0.0)) return "the dense table step must be > 0 mm";
  return {};
}

bool all_laser(const std::vector<MeasurementSet>& sets) {
  if (sets.empty()) return false;
  return std::all_of(sets.begin(), sets.end(),
                     [](const MeasurementSet& s) { return s.type == MeasurementType::laser; });
}

LaserIdentifyResult identify_laser(const Machine& m, const std::vector<MeasurementSet>& input,
                                   const LaserIdentifyOptions& o) {
  LaserIdentifyResult res;
  if (const std::string why = o.validate(); !why.empty()) {
    res.message = why;
    return res;
  }
  if (!all_laser(input)) {
    res.message = "not all files are laser data";
    return res;
  }
  Problem pb;
  pb.machine = &m;
  std::array<bool, 3> up{}, down{};
  if (const std::string why = gather_sets(pb, input, up, down); !why.empty()) {
    res.message = why;
    return res;
  }
  res.readings = static_cast<std::size_t>(pb.rows);
  std::vector<Candidate> cand = lay_out(pb, o.fit_reversal, up, down);
  try {
    pb.layout = ModelLayout(m, pb.names);
  } catch (const std::invalid_argument& e) {
    res.message = e.what();
    return res;
  }
  const Eigen::VectorXd typical = order_columns(pb, std::move(cand), res);
  const Fit fit = fit_tables(pb, typical, o, res);
  collect_functions(pb, fit, o, res);
  write_model(m, pb, res);
  describe_unseen(res);
  // ISO 230-2 figures of every positioning line
  for (const auto& s : pb.sets)
    if (s.component == static_cast<char>('X' + laser_moving_axis(s))) {
      Iso230Figures f = iso230_2_figures(s);
      if (f.ok) res.iso230.push_back(f);
    }
  res.ok = true;
  res.message = fmt::format("converged in {} Gauss–Newton step(s), rank {} of {}", res.iterations, res.rank.rank,
                            static_cast<int>(res.candidates.size()));
  return res;
}

}  // namespace ncpost::comp
