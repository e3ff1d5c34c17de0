// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/error_parameters.hpp"

#include <algorithm>

namespace ncpost::comp {

int ErrorParameters::index_of(const std::string& name) const {
  auto it = std::find(names_.begin(), names_.end(), name);
  return it == names_.end() ? -1 : static_cast<int>(it - names_.begin());
}

void ErrorParameters::set(const std::string& name, double value) {
  const int i = index_of(name);
  if (i >= 0) {
    values_[static_cast<std::size_t>(i)] = value;
    return;
  }
  names_.push_back(name);
  values_.push_back(value);
}

std::optional<double> ErrorParameters::get(const std::string& name) const {
  const int i = index_of(name);
  if (i < 0) return std::nullopt;
  return values_[static_cast<std::size_t>(i)];
}

bool ErrorParameters::erase(const std::string& name) {
  const int i = index_of(name);
  if (i < 0) return false;
  names_.erase(names_.begin() + i);
  values_.erase(values_.begin() + i);
  return true;
}

}  // namespace ncpost::comp
