// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/apt/apt_nurbs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncpost::cl {
namespace {

using Vec4d = Eigen::Matrix<double, 4, 1>;

/// The knot span index k with knots[k] <= u < knots[k+1] (the last non-empty span at u_end).
std::size_t span_of(const NurbsCurve& c, double u) {
  const std::size_t n = c.points_mm.size();
  const std::size_t p = static_cast<std::size_t>(c.degree);
  if (u >= c.knots[n]) {
    std::size_t k = n - 1;
    while (k > p && c.knots[k] >= c.knots[n]) --k;
    return k;
  }
  const auto it = std::upper_bound(c.knots.begin() + static_cast<std::ptrdiff_t>(p),
                                   c.knots.begin() + static_cast<std::ptrdiff_t>(n) + 1, u);
  return static_cast<std::size_t>(it - c.knots.begin()) - 1;
}

/// De Boor's algorithm on homogeneous points (w x, w y, w z, w).
template <class Get>
Vec4d de_boor(const NurbsCurve& c, double u, Get homogeneous) {
  const std::size_t p = static_cast<std::size_t>(c.degree);
  const std::size_t k = span_of(c, u);
  Vec4d d[32];
  for (std::size_t j = 0; j <= p; ++j) d[j] = homogeneous(k - p + j);
  for (std::size_t r = 1; r <= p; ++r)
    for (std::size_t j = p; j >= r; --j) {
      const double lo = c.knots[k - p + j], hi = c.knots[k + 1 + j - r];
      const double a = hi > lo ? (u - lo) / (hi - lo) : 0.0;
      d[j] = (1.0 - a) * d[j - 1] + a * d[j];
    }
  return d[p];
}

double distance_to_chord(const Vec3d& x, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 < 1e-24) return (x - a).norm();
  const double t = std::clamp((x - a).dot(ab) / len2, 0.0, 1.0);
  return (x - (a + t * ab)).norm();
}

}  // namespace

std::string NurbsCurve::defect() const {
  const std::size_t n = points_mm.size();
  if (degree < 1 || degree > 30) return fmt::format("degree {} (expected 1 to 30)", degree);
  if (n < static_cast<std::size_t>(degree) + 1)
    return fmt::format("{} control points for degree {} (expected at least {})", n, degree, degree + 1);
  if (knots.size() != n + static_cast<std::size_t>(degree) + 1)
    return fmt::format("{} knots for {} control points of degree {} (expected {})", knots.size(), n, degree,
                       n + static_cast<std::size_t>(degree) + 1);
  if (weights.size() != n) return "a weight per control point expected";
  if (!axes.empty() && axes.size() != n) return "a tool axis for every control point or for none expected";
  for (std::size_t i = 1; i < knots.size(); ++i)
    if (!(knots[i] >= knots[i - 1])) return fmt::format("knot {} ({:g}) is less than the one before", i + 1, knots[i]);
  for (std::size_t i = 0; i < n; ++i)
    if (!(weights[i] > 0.0) || !std::isfinite(weights[i]))
      return fmt::format("weight {} of control point {} (expected a positive number)", weights[i], i + 1);
  if (!(u_end() > u_begin())) return "the knots leave no parameter range (all interior knots equal)";
  return {};
}

Vec3d NurbsCurve::point_at(double u) const {
  const Vec4d h = de_boor(*this, u, [&](std::size_t i) {
    Vec4d v;
    v << weights[i] * points_mm[i], weights[i];
    return v;
  });
  return h.head<3>() / h[3];
}

std::optional<Vec3d> NurbsCurve::axis_at(double u) const {
  if (axes.empty()) return std::nullopt;
  const Vec4d h = de_boor(*this, u, [&](std::size_t i) {
    Vec4d v;
    v << weights[i] * axes[i], weights[i];
    return v;
  });
  const Vec3d a = h.head<3>();
  if (a.norm() < 1e-12) return std::nullopt;
  return Vec3d(a.normalized());
}

std::vector<double> linearize(const NurbsCurve& c, double tolerance_mm, std::size_t max_chords) {
  std::vector<double> out{c.u_begin()};
  struct Piece {
    double u0, u1;
    Vec3d p0, p1;
    int depth;
  };
  // every non-empty knot span on its own, halved once for curves (a span's ends and middle can
  // lie on one line while the curve swings between them)
  const std::size_t p = static_cast<std::size_t>(c.degree);
  std::vector<double> breaks;
  for (std::size_t k = p; k <= c.points_mm.size(); ++k)
    if (breaks.empty() || c.knots[k] > breaks.back()) breaks.push_back(c.knots[k]);
  std::vector<Piece> stack;
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1];
    const int halves = c.degree >= 2 ? 2 : 1;
    // pushed in reverse so that the pieces come off the stack in order
    for (int h = halves; h-- > 0;) {
      const double u0 = a + (b - a) * h / halves, u1 = h + 1 == halves ? b : a + (b - a) * (h + 1) / halves;
      stack.push_back({u0, u1, c.point_at(u0), c.point_at(u1), 0});
    }
    while (!stack.empty()) {
      const Piece piece = stack.back();
      stack.pop_back();
      double worst = 0.0;
      for (const double f : {0.25, 0.5, 0.75})
        worst =
            std::max(worst, distance_to_chord(c.point_at(piece.u0 + f * (piece.u1 - piece.u0)), piece.p0, piece.p1));
      if (out.size() + stack.size() > max_chords) return {};
      if (worst > tolerance_mm && piece.depth < 40) {
        const double um = 0.5 * (piece.u0 + piece.u1);
        const Vec3d pm = c.point_at(um);
        stack.push_back({um, piece.u1, pm, piece.p1, piece.depth + 1});
        stack.push_back({piece.u0, um, piece.p0, pm, piece.depth + 1});
        continue;
      }
      out.push_back(piece.u1);
    }
  }
  return out;
}

}  // namespace ncpost::cl
