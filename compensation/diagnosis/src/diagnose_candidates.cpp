// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_candidates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {
namespace {

constexpr const char* kComponents = "XYZABC";

bool has_type(const std::vector<MeasurementSet>& sets, MeasurementType t) {
  return std::any_of(sets.begin(), sets.end(), [t](const MeasurementSet& s) { return s.type == t; });
}

/// True if the command of axis `index` changes direction somewhere in a set (or, the first row
/// counting as approached from below, ever falls): only then can a dead band show.
bool axis_falls(const std::vector<MeasurementSet>& sets, int index) {
  for (const auto& s : sets)
    for (std::size_t k = 1; k < s.rows.size(); ++k)
      if (s.rows[k].command[index] < s.rows[k - 1].command[index] - 1e-12) return true;
  return false;
}

/// True if the command of axis `index` takes more than one value in the data.
bool moves(const std::vector<MeasurementSet>& sets, int index) {
  double lo = 1e300, hi = -1e300;
  for (const auto& s : sets)
    for (const auto& row : s.rows) lo = std::min(lo, row.command[index]), hi = std::max(hi, row.command[index]);
  return hi - lo > 1e-6;
}

}  // namespace

AxisSampling axis_sampling(const std::vector<MeasurementSet>& sets, int index) {
  AxisSampling out;
  for (const auto& s : sets) {
    std::set<long long> distinct;  // angles round the turn, in 1e-4 degrees
    double lo = 1e300, hi = -1e300;
    for (const auto& row : s.rows) {
      const double q = row.command[index];
      lo = std::min(lo, q);
      hi = std::max(hi, q);
      double deg = std::fmod(q * 180.0 / kPi, 360.0);
      if (deg < 0) deg += 360.0;
      distinct.insert(std::llround(deg * 1e4) % 3600000);
    }
    if (distinct.size() < 9 || hi - lo < 1.5 * kPi) continue;
    double gap = 0.0;
    long long previous = *distinct.rbegin() - 3600000;
    for (long long d : distinct) gap = std::max(gap, double(d - previous) * 1e-4), previous = d;
    const int order = static_cast<int>(std::floor((360.0 / gap - 1.0) / 2.0 + 1e-9));
    out.max_order = std::max(out.max_order, std::min(order, kMaxHarmonicOrder));
    out.coarsest_gap_deg = out.turns ? std::max(out.coarsest_gap_deg, gap) : gap;
    out.finest_gap_deg = out.turns ? std::min(out.finest_gap_deg, gap) : gap;
    out.turns = true;
  }
  return out;
}

double table_spacing_deg(const AxisSampling& sampling) {
  for (int d = 1; d <= 120; ++d)
    if (360 % d == 0 && double(d) >= sampling.coarsest_gap_deg - 1e-6) return double(d);
  return 120.0;
}

namespace {

/// Adds a candidate to the catalogue unless every one of its parameters is in the model already.
struct Catalogue {
  const std::vector<std::string>& present;
  std::vector<Candidate> out;
  void add(Candidate c) {
    const bool all_in = std::all_of(c.parameters.begin(), c.parameters.end(), [&](const std::string& p) {
      return std::find(present.begin(), present.end(), p) != present.end();
    });
    if (!all_in) out.push_back(std::move(c));
  }
};

/// The harmonics of every component of rotary axis `a`, orders `first` to `last`.
void add_harmonics(Catalogue& cat, char a, int first, int last) {
  for (int order = first; order <= last; ++order)
    for (int c = 0; c < 6; ++c) {
      const std::string e = fmt::format("E{}{}:h{}", kComponents[c], a, order);
      cat.add({e, CandidateKind::component, {e + ":cos", e + ":sin"}, {}, false});
    }
}

/// Squareness, then the polynomials (degree 1 to 3) of every component of the linear axes.
void add_linear_terms(Catalogue& cat, const Machine& m) {
  // squareness before the polynomials: EXY:p1 acts as EC0Y, EXZ:p1 as EB0Z, EYZ:p1 as EA0Z, and
  // the ISO name is the one to give
  for (const char* e : {"EC0Y", "EB0Z", "EA0Z"}) cat.add({e, CandidateKind::squareness, {e}, {}, false});
  for (int i = 0; i < 3; ++i) {
    const char a = m.axes[static_cast<std::size_t>(i)].letter;
    for (int order = 1; order <= 3; ++order)
      for (int c = 0; c < 6; ++c) {
        const std::string e = fmt::format("E{}{}:p{}", kComponents[c], a, order);
        cat.add({e, CandidateKind::component, {e}, {}, false});
      }
  }
}

/// Reversal of the axes whose command falls, drift in time, and the instruments of the data.
void add_reversal_drift_instruments(Catalogue& cat, const Machine& m, const std::vector<MeasurementSet>& sets) {
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    if (axis_falls(sets, static_cast<int>(i))) {
      const std::string e = fmt::format("reversal:{}", m.axes[i].letter);
      cat.add({e, CandidateKind::reversal, {e}, {}, false});
    }
  for (const char c : {'X', 'Y', 'Z'}) {
    const std::string e = fmt::format("drift:{}:t", c);
    Candidate d{e, CandidateKind::drift, {e + ":lin", e + ":exp"}, {}, true};
    d.held.set(e + ":tau", 600.0);  // replaced by the best time constant before it is scored
    cat.add(std::move(d));
  }
  if (has_type(sets, MeasurementType::ballbar))
    cat.add({"ballbar:length", CandidateKind::instrument, {"ballbar:length"}, {}, true});
  if (has_type(sets, MeasurementType::sphere))
    cat.add({"sphere:position",
             CandidateKind::instrument,
             {"sphere:position:x", "sphere:position:y", "sphere:position:z"},
             {},
             true});
}

/// Location errors of a rotary axis that change with the rotary axis carrying it (a tilt of C on
/// a cradle that sags with A, issue 17): degree 1 and 2 in the carrier's command, where the data
/// move the carrier.
void add_carried_terms(Catalogue& cat, const Machine& m, const std::vector<MeasurementSet>& sets) {
  for (int k = 0; k < m.rotary_count(); ++k)
    for (int j = 0; j < m.rotary_count(); ++j) {
      const char carrier = m.rotary(k).letter, carried = m.rotary(j).letter;
      if (j == k || !moves(sets, m.index_of(carrier))) continue;
      for (int order = 1; order <= 2; ++order)
        for (int c = 0; c < 6; ++c) {
          const std::string e = fmt::format("E{}0{}:{}:p{}", kComponents[c], carried, carrier, order);
          if (!parse_parameter_name(e, m).spec) continue;  // not carried, or an offset along its own line
          cat.add({e, CandidateKind::component, {e}, {}, false});
        }
    }
}

/// The non-parametric form: a periodic table of every component of an axis the data turn, on the
/// grid they resolve; the node at home is held at 0 (only differences from home act).
void add_tables(Catalogue& cat, const Machine& m, const std::vector<AxisSampling>& sampling) {
  for (int k = 0; k < m.rotary_count(); ++k) {
    const AxisSampling& sm = sampling[static_cast<std::size_t>(k)];
    if (!sm.turns) continue;
    const char a = m.rotary(k).letter;
    const double d = table_spacing_deg(sm);
    const int nodes = static_cast<int>(std::lround(360.0 / d));
    if (nodes < 4) continue;
    for (int c = 0; c < 6; ++c) {
      Candidate t{fmt::format("E{}{}:t", kComponents[c], a), CandidateKind::component, {}, {}, false};
      for (int i = 1; i < nodes; ++i) t.parameters.push_back(table_parameter_name(kComponents[c], a, i * d));
      t.held.set(table_parameter_name(kComponents[c], a, 0.0), 0.0);
      cat.add(std::move(t));
    }
  }
}

}  // namespace

std::vector<Candidate> candidate_catalogue(const Machine& m, const std::vector<MeasurementSet>& sets,
                                           const std::vector<std::string>& present) {
  Catalogue cat{present, {}};
  std::vector<AxisSampling> sampling;
  for (int k = 0; k < m.rotary_count(); ++k) sampling.push_back(axis_sampling(sets, 3 + k));
  for (int k = 0; k < m.rotary_count(); ++k) add_harmonics(cat, m.rotary(k).letter, 1, 4);
  // orders beyond 4 where the data resolve them (an axis they turn): the order the data show
  for (int k = 0; k < m.rotary_count(); ++k)
    if (sampling[static_cast<std::size_t>(k)].turns)
      add_harmonics(cat, m.rotary(k).letter, 5, sampling[static_cast<std::size_t>(k)].max_order);
  add_linear_terms(cat, m);
  add_reversal_drift_instruments(cat, m, sets);
  add_carried_terms(cat, m, sets);
  add_tables(cat, m, sampling);  // last
  return cat.out;
}

}  // namespace ncpost::comp
