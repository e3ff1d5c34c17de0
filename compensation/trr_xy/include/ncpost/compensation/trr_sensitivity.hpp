// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sensitivity maps of the TRR-XY machine (docs/trr-xy.md "Sensitivity map", seed 004 section 5).
//
// Test surface: a hemisphere of radius 120 mm whose centre is the workpiece origin, at (0, 0, −300)
// in M, finished with the tool normal to the surface for polar angles 0–30°. CL points on a grid
// of polar angle φ (0..30°, `polar_step_deg`) and azimuth α (0..360°, `azimuth_step_deg`, one
// point at the pole): tip R·(sin φ cos α, sin φ sin α, cos φ) in W, tool axis the same unit normal.
// The nominal program (nominal inverse kinematics, exact commands) runs on a machine with one
// error parameter set (0.01 mm for lengths, 0.01° for the angles ar, at, gp); the deviation at each
// CL point is (executed tip − CL tip)·normal (µm; positive: the tool stays outside the surface,
// material is left). Per parameter: max, min and range of that deviation.
#include <string>
#include <vector>

#include "ncpost/kinematics/trr_xy_inverse.hpp"

namespace ncpost::trr {

struct SensitivityOptions {
  double sphere_radius_mm = 120.0;
  Vec3d workpiece_origin_mm = Vec3d(0.0, 0.0, -300.0);
  double max_polar_deg = 30.0;
  double polar_step_deg = 1.0;
  double azimuth_step_deg = 1.0;
  double length_step_mm = 0.01;
  double angle_step_deg = 0.01;
};

struct SurfacePoint {
  double polar_rad = 0.0;
  double azimuth_rad = 0.0;
  ClPoint cl;
};

struct ParameterMap {
  std::string name;
  double value = 0.0;                ///< the error set (mm or rad)
  std::vector<double> deviation_um;  ///< per surface point
  double max_um = 0.0, min_um = 0.0;
  int max_at = 0, min_at = 0;  ///< indices into the points
  double range_um() const { return max_um - min_um; }
};

struct SensitivityResult {
  std::vector<SurfacePoint> points;
  std::vector<ParameterMap> maps;  ///< the 30 parameters in Errors order
};

/// The test surface's CL points.
std::vector<SurfacePoint> hemisphere_points(const SensitivityOptions& o);

/// Runs the analysis. Throws std::runtime_error naming the point if the
/// nominal program cannot be solved on this machine (axis limits, reach).
SensitivityResult sensitivity(const Machine& m, const SensitivityOptions& o = {});

}  // namespace ncpost::trr
