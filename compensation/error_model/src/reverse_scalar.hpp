// SPDX-License-Identifier: Apache-2.0
#pragma once
// A scalar that records its operations on a tape, for reverse-mode differentiation of the
// measurement predictions (prediction_jacobian.cpp). A TapedScalar is a value, the index of the
// tape node that made it and the tape; a constant (a command, a machine dimension, a parameter
// not differentiated) has no node, and an operation on constants only records nothing, so the
// nominal chain costs no more than on double. Each node keeps its one or two parents and the
// partial derivative with respect to each: sweeping the tape backwards from a result gives its
// derivative with respect to every leaf at once, whatever the number of leaves (forward mode
// costs one pass per 16 parameters).
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace ncpost::comp::taped {

/// One operation: parents (−1 for none) and the partial derivative of its value by each.
struct Node {
  int a = -1;
  int b = -1;
  double da = 0.0;
  double db = 0.0;
};

struct Tape {
  std::vector<Node> nodes;
  int push(int a, double da, int b, double db) {
    nodes.push_back({a, b, da, db});
    return static_cast<int>(nodes.size()) - 1;
  }
};

class TapedScalar {
 public:
  TapedScalar() = default;
  TapedScalar(double v) : v_(v) {}  // NOLINT: a constant, implicitly (literals, Eigen's 0 and 1)
  /// A leaf: a differentiated parameter.
  static TapedScalar leaf(double v, Tape& tape) { return {v, tape.push(-1, 0.0, -1, 0.0), &tape}; }

  double value() const { return v_; }
  int node() const { return node_; }

  /// f(x) with f'(x) = d.
  friend TapedScalar unary(const TapedScalar& x, double value, double d) {
    if (x.node_ < 0) return TapedScalar(value);
    return {value, x.tape_->push(x.node_, d, -1, 0.0), x.tape_};
  }
  /// f(x, y) with ∂f/∂x = dx, ∂f/∂y = dy.
  friend TapedScalar binary(const TapedScalar& x, const TapedScalar& y, double value, double dx, double dy) {
    if (x.node_ < 0) return unary(y, value, dy);
    if (y.node_ < 0) return unary(x, value, dx);
    return {value, x.tape_->push(x.node_, dx, y.node_, dy), x.tape_};
  }

  friend TapedScalar operator+(const TapedScalar& x, const TapedScalar& y) {
    return binary(x, y, x.v_ + y.v_, 1.0, 1.0);
  }
  friend TapedScalar operator-(const TapedScalar& x, const TapedScalar& y) {
    return binary(x, y, x.v_ - y.v_, 1.0, -1.0);
  }
  friend TapedScalar operator*(const TapedScalar& x, const TapedScalar& y) {
    return binary(x, y, x.v_ * y.v_, y.v_, x.v_);
  }
  friend TapedScalar operator/(const TapedScalar& x, const TapedScalar& y) {
    const double q = x.v_ / y.v_;
    return binary(x, y, q, 1.0 / y.v_, -q / y.v_);
  }
  friend TapedScalar operator-(const TapedScalar& x) { return unary(x, -x.v_, -1.0); }
  friend TapedScalar operator+(const TapedScalar& x) { return x; }
  TapedScalar& operator+=(const TapedScalar& y) { return *this = *this + y; }
  TapedScalar& operator-=(const TapedScalar& y) { return *this = *this - y; }
  TapedScalar& operator*=(const TapedScalar& y) { return *this = *this * y; }
  TapedScalar& operator/=(const TapedScalar& y) { return *this = *this / y; }

  friend bool operator<(const TapedScalar& x, const TapedScalar& y) { return x.v_ < y.v_; }
  friend bool operator>(const TapedScalar& x, const TapedScalar& y) { return x.v_ > y.v_; }
  friend bool operator<=(const TapedScalar& x, const TapedScalar& y) { return x.v_ <= y.v_; }
  friend bool operator>=(const TapedScalar& x, const TapedScalar& y) { return x.v_ >= y.v_; }
  friend bool operator==(const TapedScalar& x, const TapedScalar& y) { return x.v_ == y.v_; }
  friend bool operator!=(const TapedScalar& x, const TapedScalar& y) { return x.v_ != y.v_; }

  friend TapedScalar sin(const TapedScalar& x) { return unary(x, std::sin(x.v_), std::cos(x.v_)); }
  friend TapedScalar cos(const TapedScalar& x) { return unary(x, std::cos(x.v_), -std::sin(x.v_)); }
  friend TapedScalar exp(const TapedScalar& x) {
    const double e = std::exp(x.v_);
    return unary(x, e, e);
  }
  friend TapedScalar sqrt(const TapedScalar& x) {
    const double s = std::sqrt(x.v_);
    return unary(x, s, 0.5 / s);
  }
  friend TapedScalar abs(const TapedScalar& x) { return unary(x, std::abs(x.v_), x.v_ < 0.0 ? -1.0 : 1.0); }

 private:
  TapedScalar(double v, int node, Tape* tape) : v_(v), node_(node), tape_(tape) {}
  double v_ = 0.0;
  int node_ = -1;
  Tape* tape_ = nullptr;
};

}  // namespace ncpost::comp::taped

namespace Eigen {
template <>
struct NumTraits<ncpost::comp::taped::TapedScalar> : NumTraits<double> {
  using Real = ncpost::comp::taped::TapedScalar;
  using NonInteger = ncpost::comp::taped::TapedScalar;
  using Nested = ncpost::comp::taped::TapedScalar;
  using Literal = ncpost::comp::taped::TapedScalar;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 2,
    MulCost = 3
  };
};
}  // namespace Eigen
