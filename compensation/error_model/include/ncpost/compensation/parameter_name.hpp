// SPDX-License-Identifier: Apache-2.0
#pragma once
// Error-parameter names (docs/conventions.md "Geometric errors", "Effect names"; docs/formats.md "Error
// model") parsed into what they act on. Units of the values: mm for lengths, rad for angles, s for
// time constants; polynomial terms are value · x^k with x in mm, harmonic terms value · cos/sin(k q).
//
//   EX0C, EY0C, EA0C, EB0C, EC0C    location errors of a rotary axis (offset, tilt, zero)
//   EC0Y, EB0Z, EA0Z                squareness of the linear axes
//   ECC:h2:cos, EXC:h1:sin          component error functions of a rotary axis, harmonic k = 1..99
//                                   (value · cos(k q) / sin(k q), q the command in rad)
//   EXX:p1, EZX:p2, EAY:p3          component error functions of a linear axis, degree k = 1..3
//   EXX:t:-275, ECY:t:50            component error function of a linear axis as a table: the
//                                   value at that position of the axis (mm); all nodes of one
//                                   function (e.g. every EXX:t:*) are interpolated linearly and
//                                   held at the end values outside them (issue 7, LASER.md)
//   ECC:t:30, EAC:t:0               component error function of a rotary axis as a periodic table:
//                                   the value at that angle (degrees, 0 <= angle < 360; rad or mm);
//                                   the nodes of one function are interpolated linearly in the
//                                   angle, round the turn (the last node joins the first +360°)
//                                   (issue 17). As every error acts relative to home, only the
//                                   differences from the value at 0° matter: the diagnosis holds
//                                   the node at 0° at 0.
//   EA0C:A:p1, EX0C:A:p2            location error of a rotary axis that changes with the rotary
//                                   axis carrying it (issue 17: a tilt of C on a cradle that sags
//                                   with A): value · q^k added to the location error EA0C, q the
//                                   command of A in rad, k = 1..2 (rad/rad^k or mm/rad^k). Only
//                                   for an axis carried by the other (the other one between the
//                                   bed and it on the same side of the chain).
//   reversal:A                      dead-band width of axis A (rad or mm)
//   drift:Z:t:lin | :quad | :exp | :tau
//                                   drift of the TCP relative to the table along Z, in M axes:
//                                   lin·t + quad·t² + exp·(1 − e^(−t/tau)) (mm/s, mm/s², mm, s;
//                                   tau defaults to 600 s), t the recorded time stamp in s
//   ballbar:length                  offset added to every ballbar reading (mm)
//   sphere:position:x | :y | :z     offset of the actual sphere centre from the declared one (mm, M)
#include <optional>
#include <string>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

enum class ParameterKind {
  location,        ///< rotary axis: component 0..2 offset (mm), 3..5 tilt/zero (rad)
  squareness,      ///< linear axis: direction offset
  harmonic,        ///< rotary axis error motion, component 0..5, order k, cos or sin
  polynomial,      ///< linear axis error motion, component 0..5, degree k
  table,           ///< axis error motion, component 0..5, value at node at_mm (linear) or at_rad (rotary, periodic)
  coupled,         ///< rotary axis location error (component 0..5) · (command of coupled_axis_index)^order
  reversal,        ///< dead band of an axis
  drift,           ///< TCP drift relative to the table, component 0..2 (X, Y, Z)
  ballbar_length,  ///< instrument: bar length offset
  sphere_position  ///< instrument: sphere centre offset, component 0..2
};

enum class DriftBasis { linear, quadratic, exponential, time_constant };

struct ParameterSpec {
  std::string name;
  ParameterKind kind = ParameterKind::location;
  int axis_index = -1;          ///< index into Machine::axes (-1 for drift and instrument terms)
  int component = 0;            ///< 0..2 = X, Y, Z (translation), 3..5 = A, B, C (rotation)
  int order = 0;                ///< harmonic order or polynomial degree
  bool sine = false;            ///< harmonic: sin term (else cos)
  double at_mm = 0.0;           ///< table of a linear axis: node position on the axis (mm)
  double at_rad = 0.0;          ///< table of a rotary axis: node angle (rad, 0 <= at_rad < 2π)
  bool periodic = false;        ///< table of a rotary axis: interpolated round the turn
  int coupled_axis_index = -1;  ///< coupled: the axis whose command (rad) the location error grows with
  DriftBasis drift = DriftBasis::linear;

  /// True for the effects that act only while measuring (drift, instrument terms): they are not
  /// part of the machine model used for posting.
  bool measurement_only() const {
    return kind == ParameterKind::drift || kind == ParameterKind::ballbar_length ||
           kind == ParameterKind::sphere_position;
  }
  /// True if the value is an angle (rad).
  bool is_angle() const;
};

struct ParseResult {
  std::optional<ParameterSpec> spec;
  std::string error;  ///< why the name was refused, when !spec
};

/// Parses `name` for `machine`; a name of an axis the machine lacks, or an error without effect
/// (e.g. EZ0C, the offset of C along its own line), is refused with a reason.
ParseResult parse_parameter_name(const std::string& name, const Machine& machine);

/// The name of the table node of E<component><axis> at `at_mm` (e.g. "EXX:t:-275", "ECY:t:12.5");
/// for a rotary axis the position is the angle in degrees ("ECC:t:30").
std::string table_parameter_name(char component, char axis, double at_mm);

/// The effect a parameter belongs to (docs/conventions.md "Effect names"): "ECC:h2" for "ECC:h2:cos",
/// "drift:Z:t" for "drift:Z:t:lin", "sphere:position" for "sphere:position:x", else the name.
std::string effect_of(const std::string& name);

}  // namespace ncpost::comp
