#include "ncpost/compensation/laser_identify.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/laser_reading.hpp"
#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {
namespace {

constexpr char kComponents[] = "XYZABC";

/// Priority of a component error function in the rank analysis (lower: kept first).
int priority_of(int axis, int component) {
  if (component == axis) return 0;          // positioning
  if (component < 3) return 2;              // straightness
  if (component - 3 == axis) return 4;      // roll
  return 3;                                 // pitch, yaw
}

/// Approach directions from the row order where the file has none (rising: +1; a repeated
/// target reverses; the first row of a run: +1).
void fill_approach(MeasurementSet& set) {
  if (has_approach(set)) return;
  const int j = laser_moving_axis(set);
  for (std::size_t k = 0; k < set.rows.size(); ++k) {
    MeasurementRow& r = set.rows[k];
    const bool first = k == 0 || set.rows[k - 1].run != r.run;
    if (first) r.approach = 1;
    else if (r.command[j] > set.rows[k - 1].command[j] + 1e-9) r.approach = 1;
    else if (r.command[j] < set.rows[k - 1].command[j] - 1e-9) r.approach = -1;
    else r.approach = -set.rows[k - 1].approach;
  }
}

struct Problem {
  const Machine* machine = nullptr;
  std::vector<MeasurementSet> sets;
  std::array<std::vector<double>, 3> nodes;            ///< per axis, ascending, with home (empty: not measured)
  std::array<std::array<std::vector<int>, 6>, 3> node_param;  ///< layout index per axis, component, node
  std::array<int, 3> reversal_param{-1, -1, -1};
  std::vector<std::string> names;  ///< layout order
  ModelLayout layout;
  std::vector<int> column_of;      ///< layout index → Jacobian column (−1: fixed home node)
  std::vector<int> param_of;       ///< column → layout index
  std::vector<int> moving;         ///< per set
  Eigen::Index rows = 0;

  /// Layout indices of the parameters that can change this row's raw reading.
  std::vector<int> support(int set_index, const MeasurementRow& row) const {
    std::vector<int> out;
    for (int a = 0; a < 3; ++a) {
      const auto& x = nodes[static_cast<std::size_t>(a)];
      if (x.empty()) continue;
      const double q = row.command[a];
      std::vector<std::size_t> idx;
      if (q <= x.front()) idx = {0};
      else if (q >= x.back()) idx = {x.size() - 1};
      else {
        std::size_t i = 1;
        while (x[i] < q) ++i;
        idx = {i - 1, i};
      }
      for (int c = 0; c < 6; ++c)
        for (std::size_t i : idx) {
          const int p = node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)][i];
          if (column_of[static_cast<std::size_t>(p)] >= 0) out.push_back(p);
        }
    }
    const int rev = reversal_param[static_cast<std::size_t>(moving[static_cast<std::size_t>(set_index)])];
    if (rev >= 0) out.push_back(rev);
    return out;
  }

  double raw(int set_index, const MeasurementRow& row, const std::vector<double>& values) const {
    const ErrorFunctor<double> f(layout, values.data(),
                                 laser_row_state(layout, values.data(), moving[static_cast<std::size_t>(set_index)], row));
    return laser_raw_reading_um(*machine, sets[static_cast<std::size_t>(set_index)], row, f);
  }

  /// measured − predicted (µm), stacked set by set.
  Eigen::VectorXd residual(const std::vector<double>& values) const {
    Eigen::VectorXd r(rows);
    Eigen::Index k = 0;
    for (const auto& s : sets) {
      const std::vector<double> p = predict_laser_set(*machine, s, layout, values.data());
      for (std::size_t i = 0; i < s.rows.size(); ++i) r[k++] = s.rows[i].value[0] - p[i];
    }
    return r;
  }

  /// d prediction / d parameter (µm per mm or rad), columns = fitted parameters.
  Eigen::MatrixXd jacobian(const std::vector<double>& values) const {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, static_cast<Eigen::Index>(param_of.size()));
    std::vector<double> v = values;
    Eigen::Index k = 0;
    for (std::size_t s = 0; s < sets.size(); ++s) {
      const MeasurementSet& set = sets[s];
      std::map<int, Eigen::Index> first_of_run;
      for (const auto& row : set.rows) {
        for (int p : support(static_cast<int>(s), row)) {
          const double h = layout.spec(p).is_angle() ? 1e-5 : 1e-3;
          const double keep = v[static_cast<std::size_t>(p)];
          v[static_cast<std::size_t>(p)] = keep + h;
          const double up = raw(static_cast<int>(s), row, v);
          v[static_cast<std::size_t>(p)] = keep - h;
          const double down = raw(static_cast<int>(s), row, v);
          v[static_cast<std::size_t>(p)] = keep;
          J(k, column_of[static_cast<std::size_t>(p)]) = (up - down) / (2.0 * h);
        }
        auto it = first_of_run.find(row.run);
        if (it == first_of_run.end()) first_of_run.emplace(row.run, k);
        ++k;
      }
      // zeroed at the first row of each run
      Eigen::Index base = k - static_cast<Eigen::Index>(set.rows.size());
      std::map<int, Eigen::RowVectorXd> zero;
      for (const auto& [run, at] : first_of_run) zero.emplace(run, J.row(at));
      for (std::size_t i = 0; i < set.rows.size(); ++i) J.row(base + static_cast<Eigen::Index>(i)) -= zero.at(set.rows[i].run);
    }
    return J;
  }
};

void stats(const Eigen::VectorXd& r, double& rms, double& max) {
  rms = r.size() ? std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
  max = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
}

/// Least-squares line a + s·x through the points; returns s and sets the max − min about it.
double ls_slope(const std::vector<double>& x, const std::vector<double>& y, double& range_about) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double den = n * sxx - sx * sx;
  const double s = den > 0 ? (n * sxy - sx * sy) / den : 0.0;
  const double a = (sy - s * sx) / n;
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < x.size(); ++i) {
    lo = std::min(lo, y[i] - a - s * x[i]);
    hi = std::max(hi, y[i] - a - s * x[i]);
  }
  range_about = x.empty() ? 0.0 : hi - lo;
  return s;
}

/// p1..p3 through the origin, least squares on the table nodes; returns the rms about it.
double fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, std::array<double, 3>& p) {
  const double scale = std::max(1.0, std::max(std::abs(x.front()), std::abs(x.back())));
  Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double u = x[i] / scale;
    A.row(static_cast<Eigen::Index>(i)) << u, u * u, u * u * u;
    b[static_cast<Eigen::Index>(i)] = y[i];
  }
  const Eigen::Index cols = std::min<Eigen::Index>(3, A.rows() - 1);
  p = {0.0, 0.0, 0.0};
  if (cols < 1) return 0.0;
  const Eigen::VectorXd c = A.leftCols(cols).colPivHouseholderQr().solve(b);
  for (Eigen::Index k = 0; k < cols; ++k) p[static_cast<std::size_t>(k)] = c[k] / std::pow(scale, double(k + 1));
  return std::sqrt((A.leftCols(cols) * c - b).squaredNorm() / double(x.size()));
}

std::string why_unseen(const LaserFunction& f) {
  const std::string k = f.kind();
  if (k == "positioning") return "needs a positioning line of the axis";
  if (k.rfind("straightness", 0) == 0) return fmt::format("needs a straightness line in {}", f.component);
  if (k == "roll") return "roll needs straightness lines at two different offsets (ISO 230-1)";
  return fmt::format("{} needs positioning (or straightness) lines at different Abbe offsets", k);
}

}  // namespace

std::string LaserIdentifyOptions::validate() const {
  if (!(rank_tolerance > 0.0 && rank_tolerance < 1.0)) return "rank tolerance must be in (0, 1)";
  if (max_iterations < 1) return "at least one iteration";
  return {};
}

bool LaserFunction::fully_seen() const { return std::all_of(seen.begin(), seen.end(), [](bool b) { return b; }); }

bool LaserFunction::partly_seen() const {
  int n = 0;
  for (std::size_t i = 0; i < seen.size(); ++i) n += seen[i] && std::abs(nodes_mm[i]) > 1e-9;
  return n > 0;
}

std::string LaserFunction::kind() const {
  if (component == axis) return "positioning";
  if (component >= 'X') return fmt::format("straightness in {}", component);
  const int rot = component - 'A', ax = axis - 'X';
  if (rot == ax) return "roll";
  // ISO 230-1 words on a machine with Z vertical: rotation about the vertical is yaw for X and Y
  if (ax < 2) return rot == 2 ? "yaw" : "pitch";
  return rot == 0 ? "pitch" : "yaw";  // Z: about X pitch, about Y yaw (a common usage)
}

double LaserFunction::at(double x) const {
  if (nodes_mm.empty()) return 0.0;
  if (x <= nodes_mm.front()) return values.front();
  if (x >= nodes_mm.back()) return values.back();
  std::size_t i = 1;
  while (nodes_mm[i] < x) ++i;
  const double w = (x - nodes_mm[i - 1]) / (nodes_mm[i] - nodes_mm[i - 1]);
  return values[i - 1] + w * (values[i] - values[i - 1]);
}

bool all_laser(const std::vector<MeasurementSet>& sets) {
  if (sets.empty()) return false;
  return std::all_of(sets.begin(), sets.end(), [](const MeasurementSet& s) { return s.type == MeasurementType::laser; });
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
  pb.sets = input;
  std::array<bool, 3> up{}, down{};
  for (auto& s : pb.sets) {
    if (!s.has_values) {
      res.message = s.file + ": a plan without values";
      return res;
    }
    fill_approach(s);
    const int j = laser_moving_axis(s);
    pb.moving.push_back(j);
    for (const auto& r : s.rows) {
      auto& x = pb.nodes[static_cast<std::size_t>(j)];
      if (std::none_of(x.begin(), x.end(), [&](double v) { return std::abs(v - r.command[j]) < 1e-4; }))
        x.push_back(r.command[j]);
      (r.approach > 0 ? up : down)[static_cast<std::size_t>(j)] = true;
    }
    pb.rows += static_cast<Eigen::Index>(s.rows.size());
  }
  res.readings = static_cast<std::size_t>(pb.rows);
  // the layout: every node (home included, fixed at 0), reversal; columns by priority
  struct Candidate {
    int priority;
    int layout_index;
  };
  std::vector<Candidate> cand;
  for (int a = 0; a < 3; ++a) {
    auto& x = pb.nodes[static_cast<std::size_t>(a)];
    if (x.empty()) continue;
    if (std::none_of(x.begin(), x.end(), [](double v) { return std::abs(v) < 1e-4; })) x.push_back(0.0);
    std::sort(x.begin(), x.end());
    for (int c = 0; c < 6; ++c)
      for (double at : x) {
        const int idx = static_cast<int>(pb.names.size());
        pb.names.push_back(table_parameter_name(kComponents[c], static_cast<char>('X' + a), at));
        pb.node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)].push_back(idx);
        if (std::abs(at) >= 1e-4) cand.push_back({priority_of(a, c), idx});
      }
    if (o.fit_reversal && up[static_cast<std::size_t>(a)] && down[static_cast<std::size_t>(a)]) {
      pb.reversal_param[static_cast<std::size_t>(a)] = static_cast<int>(pb.names.size());
      cand.push_back({1, static_cast<int>(pb.names.size())});
      pb.names.push_back(fmt::format("reversal:{}", static_cast<char>('X' + a)));
    }
  }
  try {
    pb.layout = ModelLayout(m, pb.names);
  } catch (const std::invalid_argument& e) {
    res.message = e.what();
    return res;
  }
  std::stable_sort(cand.begin(), cand.end(), [](const Candidate& a, const Candidate& b) { return a.priority < b.priority; });
  pb.column_of.assign(pb.names.size(), -1);
  Eigen::VectorXd typical(static_cast<Eigen::Index>(cand.size()));
  for (const auto& c : cand) {
    pb.column_of[static_cast<std::size_t>(c.layout_index)] = static_cast<int>(pb.param_of.size());
    typical[static_cast<Eigen::Index>(pb.param_of.size())] = pb.layout.spec(c.layout_index).is_angle() ? 5e-5 : 0.01;
    pb.param_of.push_back(c.layout_index);
    res.candidates.push_back(pb.names[static_cast<std::size_t>(c.layout_index)]);
  }

  // Gauss–Newton on the kept columns
  std::vector<double> values(pb.names.size(), 0.0);
  Eigen::VectorXd r = pb.residual(values);
  stats(r, res.rms_nominal_um, res.max_nominal_um);
  Eigen::MatrixXd J = pb.jacobian(values);
  res.rank = analyse_rank(J, o.rank_tolerance, typical);
  const auto& kept = res.rank.kept;
  auto kept_matrix = [&](const Eigen::MatrixXd& full, Eigen::VectorXd& scale) {
    Eigen::MatrixXd K(full.rows(), static_cast<Eigen::Index>(kept.size()));
    scale.resize(static_cast<Eigen::Index>(kept.size()));
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const double n = full.col(kept[i]).norm();
      scale[static_cast<Eigen::Index>(i)] = n > 0 ? n : 1.0;
      K.col(static_cast<Eigen::Index>(i)) = full.col(kept[i]) / scale[static_cast<Eigen::Index>(i)];
    }
    return K;
  };
  Eigen::VectorXd scale;
  for (res.iterations = 1; res.iterations <= o.max_iterations; ++res.iterations) {
    const Eigen::MatrixXd K = kept_matrix(J, scale);
    const Eigen::VectorXd step = K.colPivHouseholderQr().solve(r).cwiseQuotient(scale);
    double largest = 0.0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const int p = pb.param_of[static_cast<std::size_t>(kept[i])];
      values[static_cast<std::size_t>(p)] += step[static_cast<Eigen::Index>(i)];
      const double unit = pb.layout.spec(p).is_angle() ? 1e-6 : 1e-4;  // 1 µrad, 0.1 µm
      largest = std::max(largest, std::abs(step[static_cast<Eigen::Index>(i)]) / unit);
    }
    r = pb.residual(values);
    if (largest < 1e-3) break;
    J = pb.jacobian(values);
  }
  res.iterations = std::min(res.iterations, o.max_iterations);
  stats(r, res.rms_fit_um, res.max_fit_um);
  // uncertainty of the kept values: s²·(KᵀK)⁻¹ in scaled space
  std::vector<double> sigma(pb.names.size(), 0.0);
  {
    const Eigen::MatrixXd K = kept_matrix(J, scale);
    const double dof = double(K.rows() - K.cols());
    if (dof > 0) {
      const double s2 = r.squaredNorm() / dof;
      const Eigen::MatrixXd cov = (K.transpose() * K).ldlt().solve(Eigen::MatrixXd::Identity(K.cols(), K.cols()));
      for (std::size_t i = 0; i < kept.size(); ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        sigma[static_cast<std::size_t>(pb.param_of[static_cast<std::size_t>(kept[i])])] =
            std::sqrt(std::max(0.0, s2 * cov(ii, ii))) / scale[ii];
      }
    }
  }
  std::vector<bool> seen(pb.names.size(), true);
  for (int c : res.rank.pinned) seen[static_cast<std::size_t>(pb.param_of[static_cast<std::size_t>(c)])] = false;

  // functions, ISO 230-1 reference for straightness
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
        f.values.push_back(values[static_cast<std::size_t>(p)]);
        f.sigma.push_back(sigma[static_cast<std::size_t>(p)]);
        f.seen.push_back(seen[static_cast<std::size_t>(p)]);
      }
      if (c < 3 && c != a) {
        double range = 0.0;
        f.iso_slope = ls_slope(f.nodes_mm, f.values, range);
        f.iso_straightness_um = 1e3 * range;
        for (std::size_t i = 0; i < x.size(); ++i) f.values[i] -= f.iso_slope * x[i];
        slope[f.name()] = f.iso_slope;
        slope_seen[f.name()] = f.fully_seen();
      }
      std::vector<double> yv = f.values;
      f.polynomial_rms = fit_polynomial(f.nodes_mm, yv, f.polynomial);
      res.functions.push_back(f);
    }
  }
  // squareness from the slopes
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
      res.squareness_unseen.push_back(fmt::format("{}: needs the straightness {} and {} (their least-squares slopes, "
                                                  "ISO 230-1)", q.name, q.a, q.b));
    }
  }
  for (int a = 0; a < 3; ++a)
    if (const int p = pb.reversal_param[static_cast<std::size_t>(a)]; p >= 0) {
      res.reversal.set(pb.names[static_cast<std::size_t>(p)], values[static_cast<std::size_t>(p)]);
      res.reversal_sigma.set(pb.names[static_cast<std::size_t>(p)], sigma[static_cast<std::size_t>(p)]);
    }
  // the model as written
  for (const auto& f : res.functions)
    for (std::size_t i = 0; i < f.nodes_mm.size(); ++i)
      res.parameters.set(table_parameter_name(f.component, f.axis, f.nodes_mm[i]), f.values[i]);
  for (std::size_t i = 0; i < res.squareness.size(); ++i) res.parameters.set(res.squareness.names()[i], res.squareness.values()[i]);
  for (std::size_t i = 0; i < res.reversal.size(); ++i) res.parameters.set(res.reversal.names()[i], res.reversal.values()[i]);
  {
    const ModelLayout final_layout(m, res.parameters.names());
    Eigen::VectorXd rf(pb.rows);
    Eigen::Index k = 0;
    for (const auto& s : pb.sets) {
      const std::vector<double> p = predict_laser_set(m, s, final_layout, res.parameters.values().data());
      for (std::size_t i = 0; i < s.rows.size(); ++i) rf[k++] = s.rows[i].value[0] - p[i];
    }
    stats(rf, res.rms_after_um, res.max_after_um);
  }
  // what the lines cannot see
  for (const auto& f : res.functions) {
    int total = 0, unseen = 0;
    for (std::size_t i = 0; i < f.seen.size(); ++i) {
      if (std::abs(f.nodes_mm[i]) < 1e-4) continue;
      ++total;
      unseen += !f.seen[i];
    }
    if (unseen == 0) continue;
    res.unseen.push_back(fmt::format("{} ({} of {}): {} of {} nodes not seen — {}", f.name(), f.kind(), f.axis,
                                     unseen, total, why_unseen(f)));
  }
  for (const auto& s : res.squareness_unseen) res.unseen.push_back(s);
  for (std::size_t i = 0; i < res.rank.pinned.size() && i < 12; ++i) {
    const Eigen::VectorXd& v = res.rank.null_vectors[i];
    const int p = res.rank.pinned[i];
    std::string text = res.candidates[static_cast<std::size_t>(p)] + " acts as";
    int terms = 0;
    std::vector<std::pair<double, int>> w;
    for (Eigen::Index c = 0; c < v.size(); ++c)
      if (c != p && std::abs(v[c]) >= 0.05) w.emplace_back(-std::abs(v[c]), static_cast<int>(c));
    std::sort(w.begin(), w.end());
    for (const auto& [mag, c] : w) {
      if (terms++ == 3) break;
      text += fmt::format(" {}{:.2f}·{}", terms > 1 ? "+ " : "", -v[c] / v[p], res.candidates[static_cast<std::size_t>(c)]);
    }
    if (terms == 0) text += " nothing: without effect on these readings";
    res.combinations.push_back(text + " (column-scaled)");
  }
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
