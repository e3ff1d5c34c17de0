// SPDX-License-Identifier: Apache-2.0
#pragma once
// The 21 geometric errors of the linear axes from laser interferometer lines (issue 7; seed 003,
// Li et al. 2008; ISO 230-1 for straightness, angular and squareness errors; ISO 230-2 for
// positioning).
//
// Model: each of the 18 component error functions E<c><j> of a measured axis j is a table
// (parameter_name.hpp `E<c><j>:t:<pos>`) with a node at every target of the axis and at home
// (0), linear in between. The home node is 0 by definition (every error acts relative to home,
// docs/conventions.md "Set-up at home"; a constant of a table has no effect). Reversal of each axis
// (`reversal:<j>`) where the data have both approach directions.
//
// Fit: all readings of all lines at once, linear least squares iterated (Gauss–Newton) on the
// laser predictions of laser_reading.hpp — so the angular errors act through the machine's chain
// with the real Abbe offsets (tool length, reflector offset, positions of the other axes),
// including the couplings a per-line formula misses (e.g. the yaw of Y at the line's Y position
// turning the X motion). Jacobian by central differences over the nodes that carry each row.
// Identifiability as identification (fit/rank.hpp): columns scaled, a node whose column
// lies within `rank_tolerance` of the span of the earlier ones is pinned at 0 and reported, in
// priority order positioning, reversal, straightness, pitch/yaw, roll — so that with a single
// straightness line the roll is the one reported as unseen.
//
// ISO 230-1 reference: squareness is not fitted; each straightness table's least-squares slope
// over its nodes is moved into the squareness (x̂ = (1,0,0) and ŷ in the XY plane define M,
// docs/conventions.md):
//   EC0Y = −(s_YX + s_XY),  EB0Z = s_XZ + s_ZX,  EA0Z = −(s_YZ + s_ZY)
// with s_cj the slope of straightness E<c><j> (rad). The slopes of X (s_YX, s_ZX) and of Y in Z
// (s_ZY) beyond that are a turn of the whole machine relative to M, which the straightness
// data of an ISO 230-1 set-up are referred to; it is dropped with them.
// Between the targets (issue 25 item 6): each fully seen function's node values get the curve
// leave-one-out cross-validation picks (laser_smooth.hpp: linear, not-a-knot cubic spline or a
// Legendre polynomial); the model writes it as a dense table (a node every dense_step_mm and at
// every target), held at the end values beyond the outermost targets. The fit itself is on the
// target nodes (the readings are taken there).
// Polynomials p1..p3 (through home) are fitted to every table for the report.
// Units: tables mm / rad, reports µm / µrad.
#include <string>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/fit/rank.hpp"
#include "ncpost/compensation/laser_function.hpp"
#include "ncpost/compensation/laser_iso230_2.hpp"
#include "ncpost/compensation/measurement.hpp"
#include "ncpost/compensation/model_json.hpp"

namespace ncpost::comp {

struct LaserIdentifyOptions {
  double rank_tolerance = 1e-3;  ///< fit/rank.hpp
  int max_iterations = 4;        ///< Gauss–Newton steps
  bool fit_reversal = true;      ///< reversal:<axis> where both approach directions are present
  /// The model between the targets: the curve chosen by cross-validation (laser_smooth.hpp),
  /// written as a table every dense_step_mm; false: the table of the targets, linear between them.
  bool smooth = true;
  double dense_step_mm = 5.0;
  /// Legendre degrees tried beside linear and spline (laser_smooth.hpp). 0 (the default): only
  /// the curves through the nodes — on the unseen sets of bench/laser_unseen_bench.cpp the
  /// least-squares polynomials that won the cross-validation left 1.03 to 3.9x the error of the
  /// spline on the dome (compensation/LASER.md).
  int max_legendre_degree = 0;

  std::string validate() const;
};

struct LaserIdentifyResult {
  bool ok = false;
  std::string message;
  int iterations = 0;
  std::vector<LaserFunction> functions;
  ErrorParameters squareness;                  ///< EC0Y EB0Z EA0Z, those the data determine
  std::vector<std::string> squareness_unseen;  ///< with the reason
  ErrorParameters reversal;                    ///< reversal:<axis> (mm)
  ErrorParameters reversal_sigma;
  ErrorParameters parameters;  ///< the model: tables + squareness + reversal
  std::vector<std::string> candidates;
  RankAnalysis rank;
  std::vector<std::string> unseen;        ///< which errors the lines cannot see, and why
  std::vector<std::string> combinations;  ///< what kept values stand for
  std::vector<Iso230Figures> iso230;
  std::size_t readings = 0;
  double rms_nominal_um = 0.0, max_nominal_um = 0.0;  ///< machine without errors
  double rms_fit_um = 0.0, max_fit_um = 0.0;          ///< fitted tables (before the ISO reference)
  double rms_after_um = 0.0, max_after_um = 0.0;      ///< the model as written
};

/// True if every set is a laser set (the `identify` dispatch).
bool all_laser(const std::vector<MeasurementSet>& sets);

/// Identifies the error functions of the measured axes. Never throws for data it cannot use:
/// `ok = false` with a message.
LaserIdentifyResult identify_laser(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                   const LaserIdentifyOptions& options = {});

/// The model file (docs/formats.md): parameters, uncertainty, identifiability, fit, and an extra key
/// `laser` with the polynomials, ISO 230-1 straightness and ISO 230-2 figures.
ModelFile laser_model_file(const Machine& machine, const LaserIdentifyResult& result);

}  // namespace ncpost::comp
