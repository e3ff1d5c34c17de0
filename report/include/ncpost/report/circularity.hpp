// SPDX-License-Identifier: Apache-2.0
#pragma once
// ISO 230-4 (2022) figures of a circular test from the radial deviation r(θ) (µm) of the path
// at angles θ (rad), as a ballbar reads them (ΔL = L − nominal bar length):
//   circular deviation G: the least separation of two concentric circles enclosing the path,
//     about the least-squares circle (LSC) centre (r ≈ a + b cos θ + c sin θ, small deviations);
//   radial deviation F: the largest and smallest r (about the instrument's centre);
//   circular hysteresis H: the largest radial difference between the clockwise and the
//     counter-clockwise paths at the same angle (only when both directions were run).
#include <string>
#include <vector>

namespace ncpost::report {

struct CircularityFigures {
  bool ok = false;
  std::string message;  ///< why not ok (too few points, arc too short)
  double G_um = 0.0;    ///< circular deviation about the LSC centre
  double F_max_um = 0.0, F_min_um = 0.0;
  double H_um = -1.0;                           ///< < 0: one direction only
  double centre_x_um = 0.0, centre_y_um = 0.0;  ///< LSC centre offset (in the plane of θ)
  double arc_deg = 0.0;                         ///< angle covered (at most 360)
  int direction = 0;                            ///< +1 counter-clockwise (θ rising), −1 clockwise, 0 both
};

CircularityFigures iso230_4_circularity(const std::vector<double>& angle_rad, const std::vector<double>& radial_um);

/// Circular hysteresis H (µm) of two runs of one test in opposite directions, e.g. one file each:
/// the largest |r_ccw(θ) − r_cw(θ)| at the angles of the counter-clockwise points where the
/// clockwise run has points less than ~11° away on both sides (linear between them). A centre
/// offset adds the same at one angle to both runs, so none is removed. < 0: no angle in common.
double circular_hysteresis_um(const std::vector<double>& ccw_angle_rad, const std::vector<double>& ccw_um,
                              const std::vector<double>& cw_angle_rad, const std::vector<double>& cw_um);

/// ISO 230-4 asks for the figures of each direction of travel: `both` of the whole path (with H),
/// `ccw` of the points reached with θ rising, `cw` of those reached with θ falling (the first point
/// takes the direction of the move that leaves it), each with its own LSC centre and G. A direction
/// the path does not run has ok = false and says so.
struct CircularityByDirection {
  CircularityFigures both, ccw, cw;
};
CircularityByDirection iso230_4_by_direction(const std::vector<double>& angle_rad,
                                             const std::vector<double>& radial_um);

}  // namespace ncpost::report
