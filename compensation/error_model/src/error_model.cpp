// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/error_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncpost::comp {

ModelLayout::ModelLayout(const Machine& m, const std::vector<std::string>& names)
    : axis_terms_(m.axes.size()), tables_(m.axes.size()), periodic_(m.axes.size(), false) {
  for (const std::string& n : names) {
    if (index_of(n) >= 0) throw std::invalid_argument(n + ": given twice");
    ParseResult r = parse_parameter_name(n, m);
    if (!r.spec) throw std::invalid_argument(n + ": " + r.error);
    const int i = static_cast<int>(specs_.size());
    specs_.push_back(*r.spec);
    const ParameterSpec& s = specs_.back();
    switch (s.kind) {
      case ParameterKind::location:
      case ParameterKind::squareness:
      case ParameterKind::harmonic:
      case ParameterKind::polynomial:
      case ParameterKind::coupled:
        axis_terms_[static_cast<std::size_t>(s.axis_index)].push_back(i);
        command_dependent_ = command_dependent_ || s.kind == ParameterKind::harmonic ||
                             s.kind == ParameterKind::polynomial || s.kind == ParameterKind::coupled;
        coupled_ = coupled_ || s.kind == ParameterKind::coupled;
        break;
      case ParameterKind::table: {
        TableNodes& nodes = tables_[static_cast<std::size_t>(s.axis_index)][static_cast<std::size_t>(s.component)];
        const double at = s.periodic ? s.at_rad : s.at_mm;  // rotary: rad, round the turn
        for (const auto& node : nodes)
          if (std::abs(node.first - at) < 1e-9)
            throw std::invalid_argument(n + ": a node at this position is given twice (" +
                                        specs_[static_cast<std::size_t>(node.second)].name + ")");
        nodes.emplace_back(at, i);
        if (s.periodic) periodic_[static_cast<std::size_t>(s.axis_index)] = true;
        std::sort(nodes.begin(), nodes.end());
        command_dependent_ = true;
        break;
      }
      case ParameterKind::reversal:
        reversal_[static_cast<std::size_t>(s.axis_index)] = i;
        command_dependent_ = true;
        break;
      case ParameterKind::drift:
        drift_terms_.push_back(i);
        break;
      case ParameterKind::ballbar_length:
        ballbar_length_ = i;
        break;
      case ParameterKind::sphere_position:
        sphere_position_[static_cast<std::size_t>(s.component)] = i;
        break;
    }
  }
  // Drift rides on the linear axis nearest the bed: its translation moves its whole side.
  for (const std::vector<int>* side : {&m.tool_side, &m.workpiece_side}) {
    if (drift_axis_ >= 0) break;
    if (!side->empty() && !m.axes[static_cast<std::size_t>(side->front())].is_rotary()) drift_axis_ = side->front();
  }
  if (!drift_terms_.empty() && drift_axis_ < 0)
    throw std::invalid_argument(specs_[static_cast<std::size_t>(drift_terms_.front())].name +
                                ": no linear axis next to the bed to carry the drift");
  acts_.assign(m.axes.size(), false);
  for (std::size_t a = 0; a < m.axes.size(); ++a) {
    bool any = !axis_terms_[a].empty() || (a < reversal_.size() && reversal_[a] >= 0) ||
               (!drift_terms_.empty() && static_cast<int>(a) == drift_axis_);
    for (const TableNodes& t : tables_[a]) any = any || !t.empty();
    acts_[a] = any;
  }
}

int ModelLayout::index_of(const std::string& name) const {
  auto it = std::find_if(specs_.begin(), specs_.end(), [&](const ParameterSpec& s) { return s.name == name; });
  return it == specs_.end() ? -1 : static_cast<int>(it - specs_.begin());
}

std::vector<std::string> ModelLayout::names() const {
  std::vector<std::string> out;
  for (const auto& s : specs_) out.push_back(s.name);
  return out;
}

bool ModelLayout::has_reversal() const {
  return std::any_of(reversal_.begin(), reversal_.end(), [](int i) { return i >= 0; });
}

}  // namespace ncpost::comp
