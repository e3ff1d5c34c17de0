// SPDX-License-Identifier: Apache-2.0
#pragma once
// PLANE (tilted working plane) of Klartext: the plane's frame in W and the rotary angles the
// control computes for it from the machine's kinematics (Heidenhain TNC 640 user's manual,
// "Tilting the working plane").
//
// Frames (W_R_plane maps plane coordinates to W; the plane's origin is the datum shift's):
//   PLANE SPATIAL SPA SPB SPC:   Rz(SPC) · Ry(SPB) · Rx(SPA)  (about the fixed X, then Y, then Z)
//   PLANE EULER EULPR EULNU EULROT: Rz(EULPR) · Rx(EULNU) · Rz(EULROT)
//   PLANE VECTOR BX BY BZ NX NY NZ: Z along N, X along B made normal to N, Y = Z × X
//   PLANE AXIAL A.. B.. C..:     the machine's rotary axes at those angles: R_w(q)ᵀ · R_t(q)
//   PLANE POINTS P1.. P2.. P3..: X along P1 -> P2, Z = X × (P3 - P1)
//   PLANE PROJECTED PROPR PROMIN ROT (PROROT): the plane's trace in the principal plane ZX runs along
//     Ry(PROPR)·e_x, its trace in the minor plane YZ along Rx(PROMIN)·e_y (each angle turning as the
//     spatial angle about that axis does: PROPR alone is SPB, PROMIN alone SPA); X along the first
//     trace, Z = first × second, then turned by ROT about Z: Rz'(ROT) · [x y z]. The manual's planes
//     Z/X and Y/Z (angles positive from the first axis to the second) give these signs.
// Angles in degrees in the program, radians here. PLANE RELATIV is refused by name.
//
// Rotary angles (Q120 .. Q122 after STAY): the two solutions of the tool axis W_R_plane · e_z
// (rotary_solutions), within the limits. SEQ+ / SEQ- pick the one whose master axis is >= 0 / <= 0;
// the master axis is the first rotary axis from the tool on a machine with a head axis, the second
// from the table on a table-table machine (the one nearer the bed). Without SEQ the admissible
// solution nearest the current angles. At the singular orientation (tool axis along the free
// axis) the free axis keeps its current angle. TABLE ROT and COORD ROT give the same plane in W
// (the control turns the table or the coordinates); they differ only in the free axis at the
// singular orientation, where TABLE ROT is refused.
#include <optional>
#include <string>
#include <variant>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/klartext/klartext_block.hpp"

namespace ncpost::klartext {

/// The tilted plane in effect: plane coordinates p are at origin_W + W_R_plane · p in W.
struct PlaneFrame {
  Mat3d W_R_plane = Mat3d::Identity();
  Vec3d origin_W = Vec3d::Zero();
};

struct PlaneRequest {
  enum class Motion { stay, move, turn };
  Mat3d W_R_plane = Mat3d::Identity();
  std::optional<RotaryAngles> axial_rad;  ///< PLANE AXIAL: the angles (missing axes: 0)
  Motion motion = Motion::stay;
  int seq = 0;  ///< +1, -1, 0 (none)
  bool table_rot = false;
  bool retract = false;  ///< MB given
  bool rapid = false;    ///< FMAX
  std::optional<double> feed;
  bool reset = false;  ///< PLANE RESET
};

/// The words of a PLANE block (Q parameters resolved); a message naming the statement otherwise.
std::variant<PlaneRequest, std::string> plane_request(const Block& b, const Machine& m);

/// The rotary angles for the plane (see above); a message otherwise. `current_rad`: the
/// rotary axes now.
std::variant<RotaryAngles, std::string> plane_rotary(const Machine& m, const PlaneRequest& r,
                                                     const RotaryAngles& current_rad);

/// The orientation the rotary axes give the tool frame in W: R_w(q)ᵀ · R_t(q).
Mat3d tool_frame_W(const Machine& m, const RotaryAngles& rotary_rad);

}  // namespace ncpost::klartext
