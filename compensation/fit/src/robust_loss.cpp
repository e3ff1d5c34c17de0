// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/fit/robust_loss.hpp"

#include <cmath>

namespace ncpost::comp {

double RobustLoss::rho(double r) const {
  const double a = std::abs(r), k = scale;
  switch (loss) {
    case Loss::squared:
      return 0.5 * r * r;
    case Loss::huber:
      return a <= k ? 0.5 * r * r : k * a - 0.5 * k * k;
    case Loss::cauchy:
      return 0.5 * k * k * std::log1p((r / k) * (r / k));
  }
  return 0.5 * r * r;
}

double RobustLoss::weight(double r) const {
  const double a = std::abs(r), k = scale;
  switch (loss) {
    case Loss::squared:
      return 1.0;
    case Loss::huber:
      return a <= k ? 1.0 : k / a;
    case Loss::cauchy:
      return 1.0 / (1.0 + (r / k) * (r / k));
  }
  return 1.0;
}

double RobustLoss::cost(const Eigen::VectorXd& r) const {
  double c = 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i) c += rho(r[i]);
  return c;
}

Eigen::VectorXd RobustLoss::weights(const Eigen::VectorXd& r) const {
  Eigen::VectorXd w(r.size());
  for (Eigen::Index i = 0; i < r.size(); ++i) w[i] = weight(r[i]);
  return w;
}

}  // namespace ncpost::comp
