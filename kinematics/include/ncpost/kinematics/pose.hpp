// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rigid transforms and small rotation helpers, templated on the scalar so that the same code
// runs on double (posting) and on automatic-differentiation scalars (identification).
//
// Naming rule, used throughout ncpost: `a_T_b` maps the coordinates of a point given in frame b
// to frame a, so that `a_T_b * b_T_c == a_T_c` and `a_T_b.apply(p_b) == p_a`.
// Frames (docs/conventions.md): M = machine program frame (bed), W = workpiece frame (fixed to the
// table). Lengths in mm, angles in radians.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <type_traits>

#include "ncpost/kinematics/units.hpp"

namespace ncpost {

template <class S>
using Vec3 = Eigen::Matrix<S, 3, 1>;
template <class S>
using Mat3 = Eigen::Matrix<S, 3, 3>;

/// Skew-symmetric matrix [w]x with [w]x v = w x v.
template <class S>
Mat3<S> skew(const Vec3<S>& w) {
  // (element by element: Eigen's comma initializer is not inlined, and this is in every chain)
  Mat3<S> m;
  m(0, 0) = S(0);
  m(0, 1) = -w.z();
  m(0, 2) = w.y();
  m(1, 0) = w.z();
  m(1, 1) = S(0);
  m(1, 2) = -w.x();
  m(2, 0) = -w.y();
  m(2, 1) = w.x();
  m(2, 2) = S(0);
  return m;
}

/// Rotation by `angle` (rad) right-handed about the unit vector `d` (Rodrigues).
template <class S>
Mat3<S> rotation_about(const Vec3<S>& d, const S& angle) {
  using std::cos;
  using std::sin;
  if constexpr (std::is_same_v<S, double>) {
    // the expression below element by element, in Eigen's order of operations (its product takes
    // the scalar into the left factor): the same bits, a fifth faster in every chain
    const double s = sin(angle), c1 = 1.0 - cos(angle);
    const double k[3][3] = {{0.0, -d.z(), d.y()}, {d.z(), 0.0, -d.x()}, {-d.y(), d.x(), 0.0}};
    Mat3<S> r;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double kk = ((c1 * k[i][0]) * k[0][j] + (c1 * k[i][1]) * k[1][j]) + (c1 * k[i][2]) * k[2][j];
        r(i, j) = ((i == j ? 1.0 : 0.0) + s * k[i][j]) + kk;
      }
    return r;
  } else {
    const Mat3<S> k = skew(d);
    return Mat3<S>::Identity() + sin(angle) * k + (S(1) - cos(angle)) * (k * k);
  }
}

/// Rotation of the rotation vector w (axis * angle, rad). Exact for finite angles; near zero a
/// series keeps automatic derivatives well defined (error < 2e-13 for |w| < 1e-4 rad).
template <class S>
Mat3<S> rotation_vector(const Vec3<S>& w) {
  using std::sqrt;
  const S theta2 = w.squaredNorm();
  const Mat3<S> k = skew(w);
  if (theta2 < S(1e-8)) return Mat3<S>::Identity() + k + S(0.5) * (k * k);
  const S theta = sqrt(theta2);
  return rotation_about<S>(w / theta, theta);
}

/// Hot in every chain evaluation: kept inline (GCC otherwise emits out-of-line calls for the
/// 3x3 products on double).
#if defined(__GNUC__)
#define NCPOST_INLINE inline __attribute__((always_inline))
#else
#define NCPOST_INLINE inline
#endif

/// A rigid transform a_T_b: p_a = R * p_b + t.
template <class S>
struct Rigid {
  Mat3<S> R = Mat3<S>::Identity();
  Vec3<S> t = Vec3<S>::Zero();

  static Rigid translation(const Vec3<S>& v) {
    Rigid r;
    r.t = v;
    return r;
  }
  static Rigid rotation(const Mat3<S>& m) {
    Rigid r;
    r.R = m;
    return r;
  }
  /// Rotation `m` about the point `c`: Trans(c) * Rot(m) * Trans(-c).
  static Rigid rotation_about_point(const Mat3<S>& m, const Vec3<S>& c) {
    Rigid r;
    r.R = m;
    r.t = c - m * c;
    return r;
  }

  NCPOST_INLINE Vec3<S> apply(const Vec3<S>& p) const { return R * p + t; }
  NCPOST_INLINE Vec3<S> rotate(const Vec3<S>& v) const { return R * v; }
  NCPOST_INLINE Rigid inverse() const {
    Rigid r;
    r.R = R.transpose();
    r.t = -(r.R * t);
    return r;
  }
  NCPOST_INLINE Rigid operator*(const Rigid& o) const {
    Rigid r;
    r.R = R * o.R;
    r.t = R * o.t + t;
    return r;
  }

  template <class T>
  Rigid<T> cast() const {
    Rigid<T> r;
    r.R = R.template cast<T>();
    r.t = t.template cast<T>();
    return r;
  }
};

using Rigidd = Rigid<double>;
using Vec3d = Vec3<double>;
using Mat3d = Mat3<double>;

}  // namespace ncpost
