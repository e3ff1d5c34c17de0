// SPDX-License-Identifier: Apache-2.0
#include <cmath>

#include <nlohmann/json.hpp>

#include "ncpost/compensation/laser_identify.hpp"
#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {

ModelFile laser_model_file(const Machine& m, const LaserIdentifyResult& r) {
  ModelFile f;
  f.machine = m.name;
  f.axes = model_axes(m);
  f.parameters = r.parameters;
  for (const auto& fn : r.functions)
    for (std::size_t i = 0; i < fn.nodes_mm.size(); ++i)
      if (fn.sigma[i] > 0.0)
        f.uncertainty.set(table_parameter_name(fn.component, fn.axis, fn.nodes_mm[i]), fn.sigma[i]);
  for (std::size_t i = 0; i < r.reversal_sigma.size(); ++i)
    f.uncertainty.set(r.reversal_sigma.names()[i], r.reversal_sigma.values()[i]);
  Identifiability id;
  id.rank = r.rank.rank;
  id.parameters = static_cast<int>(r.candidates.size());
  for (std::size_t i = 0; i < r.rank.pinned.size(); ++i) {
    const int p = r.rank.pinned[i];
    id.pinned.push_back(r.candidates[static_cast<std::size_t>(p)]);
    NullDirection d;
    const Eigen::VectorXd& v = r.rank.null_vectors[i];
    for (Eigen::Index c = 0; c < v.size(); ++c)
      if (std::abs(v[c]) >= 0.05) d.emplace_back(r.candidates[static_cast<std::size_t>(c)], v[c]);
    id.null_space.push_back(d);
  }
  id.combinations = r.unseen;
  for (const auto& c : r.combinations) id.combinations.push_back(c);
  f.identifiability = id;
  FitSummary fit;
  fit.rms_nominal_um = r.rms_nominal_um;
  fit.max_nominal_um = r.max_nominal_um;
  fit.rms_before_um = r.rms_after_um;  // no residual analysis on laser data: before = after
  fit.max_before_um = r.max_after_um;
  fit.rms_after_um = r.rms_after_um;
  fit.max_after_um = r.max_after_um;
  f.fit = fit;
  nlohmann::json laser = nlohmann::json::object();
  nlohmann::json poly = nlohmann::json::object();
  nlohmann::json straight = nlohmann::json::object();
  for (const auto& fn : r.functions) {
    for (int k = 0; k < 3; ++k)
      poly[fn.name() + ":p" + std::to_string(k + 1)] = fn.polynomial[static_cast<std::size_t>(k)];
    if (fn.component >= 'X' && fn.component != fn.axis)
      straight[fn.name()] = {{"straightness_um", std::round(fn.iso_straightness_um * 1e4) / 1e4},
                             {"slope_rad", fn.iso_slope}};
  }
  laser["polynomials"] = poly;
  laser["straightness_iso230_1"] = straight;
  nlohmann::json iso = nlohmann::json::array();
  auto r4 = [](double v) { return std::round(v * 1e4) / 1e4; };
  for (const auto& g : r.iso230)
    iso.push_back({{"file", g.file},
                   {"axis", std::string(1, g.axis)},
                   {"A_um", r4(g.accuracy_A_um)},
                   {"R_um", r4(g.repeatability_R_um)},
                   {"B_um", r4(g.reversal_B_um)},
                   {"mean_reversal_um", r4(g.mean_reversal_um)},
                   {"E_um", r4(g.systematic_E_um)},
                   {"M_um", r4(g.mean_bidirectional_M_um)}});
  laser["iso230_2"] = iso;
  laser["rms_fit_um"] = r4(r.rms_fit_um);
  laser["max_fit_um"] = r4(r.max_fit_um);
  f.extra["laser"] = laser.dump();
  return f;
}

}  // namespace ncpost::comp
