// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_candidates.hpp"

#include <fmt/format.h>

#include <algorithm>

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

}  // namespace

std::vector<Candidate> candidate_catalogue(const Machine& m, const std::vector<MeasurementSet>& sets,
                                           const std::vector<std::string>& present) {
  std::vector<Candidate> out;
  auto add = [&](Candidate c) {
    const bool all_in = std::all_of(c.parameters.begin(), c.parameters.end(), [&](const std::string& p) {
      return std::find(present.begin(), present.end(), p) != present.end();
    });
    if (!all_in) out.push_back(std::move(c));
  };
  for (int k = 0; k < m.rotary_count(); ++k) {
    const char a = m.rotary(k).letter;
    for (int order = 1; order <= 4; ++order)
      for (int c = 0; c < 6; ++c) {
        const std::string e = fmt::format("E{}{}:h{}", kComponents[c], a, order);
        add({e, CandidateKind::component, {e + ":cos", e + ":sin"}, {}, false});
      }
  }
  // squareness before the polynomials: EXY:p1 acts as EC0Y, EXZ:p1 as EB0Z, EYZ:p1 as EA0Z, and
  // the ISO name is the one to give
  for (const char* e : {"EC0Y", "EB0Z", "EA0Z"}) add({e, CandidateKind::squareness, {e}, {}, false});
  for (int i = 0; i < 3; ++i) {
    const char a = m.axes[static_cast<std::size_t>(i)].letter;
    for (int order = 1; order <= 3; ++order)
      for (int c = 0; c < 6; ++c) {
        const std::string e = fmt::format("E{}{}:p{}", kComponents[c], a, order);
        add({e, CandidateKind::component, {e}, {}, false});
      }
  }
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    if (axis_falls(sets, static_cast<int>(i))) {
      const std::string e = fmt::format("reversal:{}", m.axes[i].letter);
      add({e, CandidateKind::reversal, {e}, {}, false});
    }
  for (const char c : {'X', 'Y', 'Z'}) {
    const std::string e = fmt::format("drift:{}:t", c);
    Candidate d{e, CandidateKind::drift, {e + ":lin", e + ":exp"}, {}, true};
    d.held.set(e + ":tau", 600.0);  // replaced by the best time constant before it is scored
    add(std::move(d));
  }
  if (has_type(sets, MeasurementType::ballbar))
    add({"ballbar:length", CandidateKind::instrument, {"ballbar:length"}, {}, true});
  if (has_type(sets, MeasurementType::sphere))
    add({"sphere:position", CandidateKind::instrument,
         {"sphere:position:x", "sphere:position:y", "sphere:position:z"}, {}, true});
  return out;
}

}  // namespace ncpost::comp
