// SPDX-License-Identifier: Apache-2.0
#pragma once
// The catalogue of candidate effects of residual analysis (issue 6; docs/conventions.md "Effect
// names"): each candidate is one named physical cause and the error parameters that express it
// (parameter_name.hpp; values mm / rad / s).
//
//   rotary component errors   E<c><axis>:h<k>   k = 1..4, c = X Y Z A B C   {…:cos, …:sin}; for an
//                                               axis the data turn most of a turn, k up to the
//                                               order their sampling resolves (axis_sampling)
//   rotary component tables   E<c><axis>:t      the periodic table (ECC:t:<deg>) on the grid the
//                                               data resolve, node 0° held at 0 (errors act
//                                               relative to home): any shape, for what no
//                                               compact form explains (issue 17)
//   linear component errors   E<c><axis>:p<k>   k = 1..3, c = X Y Z A B C   {E<c><axis>:p<k>}
//   squareness                EC0Y EB0Z EA0Z
//   reversal                  reversal:<axis>   every axis that reverses its motion in the data
//   drift                     drift:<X|Y|Z>:t   {lin, exp}, the time constant tau held at the value
//                                               that explains most (diagnose.cpp chooses it)
//   instruments               ballbar:length (ballbar data), sphere:position (sphere data, x y z)
//   coupled location          E<c>0<axis>:<carrier>:p<k>   k = 1, 2: a location error of a rotary
//                                               axis growing with the rotary axis that carries it
//                                               (EA0C:A:p1, a tilt of C that grows with A)
//
// Effects whose parameters are all already in the model are left out. `measurement_only` effects
// (drift, instruments) are never part of the machine used for posting (machine_model.hpp).
#include <string>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

enum class CandidateKind { component, squareness, reversal, drift, instrument };

/// Highest harmonic order considered for any axis (beyond it, the table).
constexpr int kMaxHarmonicOrder = 24;

/// How the data sample a rotary axis (index into Machine::axes).
struct AxisSampling {
  bool turns = false;             ///< some set turns it most of a turn (≥ 270°, ≥ 9 distinct angles)
  int max_order = 4;              ///< highest harmonic order resolved: per turning set, of its distinct
                                  ///< angles round the turn with largest gap g, floor((360°/g − 1)/2);
                                  ///< the largest over the sets, 4 ≤ order ≤ kMaxHarmonicOrder
  double coarsest_gap_deg = 0.0;  ///< the largest gap g among the turning sets (the table's grid)
  double finest_gap_deg = 0.0;    ///< the smallest such g
};
AxisSampling axis_sampling(const std::vector<MeasurementSet>& sets, int axis_index);

/// The node spacing of a rotary axis's table for these data: the coarsest turning set's largest
/// gap, rounded up to a whole number of degrees that divides 360 (10° for a sphere grid every 10°).
double table_spacing_deg(const AxisSampling& sampling);

struct Candidate {
  std::string effect;  ///< effect name, e.g. "ECC:h2", "drift:Z:t"
  CandidateKind kind = CandidateKind::component;
  std::vector<std::string> parameters;  ///< the parameters fitted for it
  ErrorParameters held;                 ///< parameters held at a value (drift tau, s)
  bool measurement_only = false;        ///< drift and instrument effects
};

/// Every candidate the machine and the data allow, minus those whose parameters are all in
/// `present`. Order: rotary component errors axis by axis, squareness, linear component errors,
/// reversal, drift, instruments, coupled location errors, rotary tables. The order names a class of candidates that act
/// alike on the data (e.g. EC0Y and EXY:p1, the degree-1 straightness that is a squareness): the first is given.
std::vector<Candidate> candidate_catalogue(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                           const std::vector<std::string>& present);

}  // namespace ncpost::comp
