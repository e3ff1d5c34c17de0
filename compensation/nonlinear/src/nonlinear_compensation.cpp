// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/nonlinear_compensation.hpp"

namespace ncpost::nonlinear {

std::optional<Method> method_named(const std::string& name) {
  if (name == "adaptive") return Method::adaptive;
  if (name == "harmonic") return Method::harmonic;
  return std::nullopt;
}

}  // namespace ncpost::nonlinear
