// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_sensitivity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ncpost::trr {

std::vector<SurfacePoint> hemisphere_points(const SensitivityOptions& o) {
  std::vector<SurfacePoint> pts;
  const int rings = static_cast<int>(std::lround(o.max_polar_deg / o.polar_step_deg));
  const int sectors = static_cast<int>(std::lround(360.0 / o.azimuth_step_deg));
  for (int i = 0; i <= rings; ++i) {
    const double phi = deg_to_rad(i * o.polar_step_deg);
    for (int j = 0; j < (i == 0 ? 1 : sectors); ++j) {
      SurfacePoint p;
      p.polar_rad = phi;
      p.azimuth_rad = deg_to_rad(j * o.azimuth_step_deg);
      const Vec3d n(std::sin(phi) * std::cos(p.azimuth_rad), std::sin(phi) * std::sin(p.azimuth_rad), std::cos(phi));
      p.cl.axis = n;
      p.cl.tip_mm = o.sphere_radius_mm * n;
      pts.push_back(p);
    }
  }
  return pts;
}

SensitivityResult sensitivity(const Machine& m, const SensitivityOptions& o) {
  SensitivityResult r;
  r.points = hemisphere_points(o);
  const Kinematics nominal(m);
  std::vector<Command> program;
  std::vector<Rigidd> plates;
  for (const SurfacePoint& p : r.points) {
    const InverseOutcome ik = inverse(nominal, p.cl, o.workpiece_origin_mm);
    if (!ik.ok())
      throw std::runtime_error(
          fmt::format("sensitivity: the hemisphere point at polar {:.1f} deg, azimuth {:.1f} deg "
                      "is out of reach: {}",
                      rad_to_deg(p.polar_rad), rad_to_deg(p.azimuth_rad), ik.failure));
    program.push_back(*ik.command);
    plates.push_back(ik.machine_T_plate);
  }
  for (int k = 0; k < kParameterCount; ++k) {
    Errors e;
    e[k] = Errors::is_angle(k) ? deg_to_rad(o.angle_step_deg) : o.length_step_mm;
    const Kinematics actual(m, e);
    ParameterMap map;
    map.name = Errors::name(k);
    map.value = e[k];
    map.max_um = -1e300;
    map.min_um = 1e300;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      std::string why;
      const auto tp = actual.tool(program[i].slider_mm, plates[i], &why);
      if (!tp) throw std::runtime_error("sensitivity: " + map.name + ": " + why);
      const Vec3d tip = Kinematics::tip_in_workpiece(*tp, program[i], o.workpiece_origin_mm);
      const double dev_um = 1000.0 * (tip - r.points[i].cl.tip_mm).dot(r.points[i].cl.axis);
      map.deviation_um.push_back(dev_um);
      if (dev_um > map.max_um) {
        map.max_um = dev_um;
        map.max_at = static_cast<int>(i);
      }
      if (dev_um < map.min_um) {
        map.min_um = dev_um;
        map.min_at = static_cast<int>(i);
      }
    }
    r.maps.push_back(std::move(map));
  }
  return r;
}

}  // namespace ncpost::trr
