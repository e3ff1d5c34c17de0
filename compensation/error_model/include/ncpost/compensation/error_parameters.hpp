// SPDX-License-Identifier: Apache-2.0
#pragma once
// ErrorParameters: an ordered set of named error parameters (name → value, mm / rad / s), the
// in-memory form of the `parameters` object of the model JSON (docs/formats.md "Error model").
// Names follow docs/conventions.md; see parameter_name.hpp for the full list and units.
#include <optional>
#include <string>
#include <vector>

namespace ncpost::comp {

class ErrorParameters {
 public:
  /// Sets (or adds, at the end) a parameter.
  void set(const std::string& name, double value);
  std::optional<double> get(const std::string& name) const;
  double value_or(const std::string& name, double fallback) const { return get(name).value_or(fallback); }
  bool contains(const std::string& name) const { return index_of(name) >= 0; }
  bool erase(const std::string& name);
  int index_of(const std::string& name) const;

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& values() const { return values_; }
  std::size_t size() const { return names_.size(); }
  bool empty() const { return names_.empty(); }

 private:
  std::vector<std::string> names_;
  std::vector<double> values_;
};

}  // namespace ncpost::comp
