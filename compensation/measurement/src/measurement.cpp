// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

const char* to_string(MeasurementType t) {
  switch (t) {
    case MeasurementType::ballbar:
      return "ballbar";
    case MeasurementType::sphere:
      return "sphere";
    case MeasurementType::laser:
      return "laser";
  }
  return "?";
}

std::vector<std::string> MeasurementSet::value_columns() const {
  switch (type) {
    case MeasurementType::ballbar:
      return {"L"};
    case MeasurementType::sphere:
      return {"dx", "dy", "dz"};
    case MeasurementType::laser:
      return {"e_um"};
  }
  return {};
}

std::string MeasurementSet::meta(const std::string& key) const {
  for (const auto& [k, v] : metadata)
    if (k == key) return v;
  return {};
}

void MeasurementSet::set_meta(const std::string& key, const std::string& value) {
  for (auto& [k, v] : metadata)
    if (k == key) {
      v = value;
      return;
    }
  metadata.emplace_back(key, value);
}

}  // namespace ncpost::comp
