// SPDX-License-Identifier: Apache-2.0
#include "read/sinumerik/sinumerik_frame.hpp"

#include <cmath>

namespace ncpost::sinumerik {

Eigen::Matrix3d about_axis(int axis, double deg) {
  const Eigen::Vector3d unit = Eigen::Vector3d::Unit(axis);
  return Eigen::AngleAxisd(deg * M_PI / 180.0, unit).toRotationMatrix();
}

Frame rotation_rpy_deg(double a_deg, double b_deg, double c_deg) {
  Frame f;
  f.rotation = about_axis(2, c_deg) * about_axis(1, b_deg) * about_axis(0, a_deg);
  return f;
}

}  // namespace ncpost::sinumerik
