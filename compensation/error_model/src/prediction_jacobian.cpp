// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/prediction_jacobian.hpp"

#include "ncpost/compensation/prediction.hpp"
#include "reverse_scalar.hpp"

namespace ncpost::comp {
namespace {

using taped::Node;
using taped::Tape;
using taped::TapedScalar;
using NodeGradients = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The visitor of predict_rows that differentiates each row's values. What comes before row 0
/// (the leaves, the home pose, the row states) stays on the tape: the derivative of each of its
/// nodes by every leaf is computed once, forwards. Each row is recorded after it and swept back
/// from each value down to the row's start; what reaches the shared part is finished with those
/// derivatives. The row's record is then dropped.
class RowSweep {
 public:
  RowSweep(Tape& tape, int leaves, Eigen::MatrixXd& by_leaf) : tape_(tape), leaves_(leaves), by_leaf_(by_leaf) {}

  void begin_row(std::size_t) {
    if (shared_ < 0) differentiate_shared();
    tape_.nodes.resize(static_cast<std::size_t>(shared_));
  }
  void row(std::size_t k, const TapedScalar* v, int n) {
    for (int i = 0; i < n; ++i) by_leaf_.row(static_cast<Eigen::Index>(k) * n + i) = gradient(v[i]);
  }

 private:
  void differentiate_shared() {
    shared_ = static_cast<int>(tape_.nodes.size());
    shared_gradient_ = NodeGradients::Zero(shared_, leaves_);
    for (int i = 0; i < shared_; ++i) {
      const Node& n = tape_.nodes[static_cast<std::size_t>(i)];
      if (n.a < 0) {
        shared_gradient_(i, i) = 1.0;  // a leaf: the leaves are the first nodes
        continue;
      }
      shared_gradient_.row(i) = n.da * shared_gradient_.row(n.a);
      if (n.b >= 0) shared_gradient_.row(i) += n.db * shared_gradient_.row(n.b);
    }
    reaching_.assign(static_cast<std::size_t>(shared_), 0.0);
  }

  /// Adds weight w to the adjoint of node p.
  void pass(int p, double w) {
    if (p < 0) return;
    if (p >= shared_) {
      adjoint_[static_cast<std::size_t>(p - shared_)] += w;
      return;
    }
    double& r = reaching_[static_cast<std::size_t>(p)];
    if (r == 0.0) touched_.push_back(p);
    r += w;
  }

  Eigen::RowVectorXd gradient(const TapedScalar& y) {
    if (y.node() < 0) return Eigen::RowVectorXd::Zero(leaves_);
    if (y.node() < shared_) return shared_gradient_.row(y.node());
    adjoint_.assign(static_cast<std::size_t>(y.node() - shared_ + 1), 0.0);
    adjoint_.back() = 1.0;
    for (int i = y.node(); i >= shared_; --i) {
      const double a = adjoint_[static_cast<std::size_t>(i - shared_)];
      if (a == 0.0) continue;
      const Node& n = tape_.nodes[static_cast<std::size_t>(i)];
      pass(n.a, n.da * a);
      pass(n.b, n.db * a);
    }
    Eigen::RowVectorXd g = Eigen::RowVectorXd::Zero(leaves_);
    for (int p : touched_) {
      double& r = reaching_[static_cast<std::size_t>(p)];
      if (r != 0.0) g += r * shared_gradient_.row(p);
      r = 0.0;
    }
    touched_.clear();
    return g;
  }

  Tape& tape_;
  int leaves_;
  Eigen::MatrixXd& by_leaf_;
  int shared_ = -1;                ///< nodes before row 0
  NodeGradients shared_gradient_;  ///< d node / d leaf for those
  std::vector<double> adjoint_;    ///< the row's nodes
  std::vector<double> reaching_;   ///< what reaches the shared nodes
  std::vector<int> touched_;
};

}  // namespace

Eigen::MatrixXd prediction_jacobian_mm(const Machine& m, const std::vector<MeasurementSet>& sets,
                                       const ModelLayout& layout, const std::vector<double>& values,
                                       const std::vector<int>& columns) {
  Eigen::Index count = 0;
  for (const auto& s : sets) count += static_cast<Eigen::Index>(s.rows.size()) * s.values_per_row();
  Eigen::MatrixXd J(count, static_cast<Eigen::Index>(columns.size()));
  Tape tape;
  Eigen::Index at = 0;
  for (const auto& s : sets) {
    tape.nodes.clear();
    std::vector<TapedScalar> x(values.begin(), values.end());
    std::vector<int> leaf_of(columns.size());
    int leaves = 0;
    for (std::size_t j = 0; j < columns.size(); ++j) {
      TapedScalar& v = x[static_cast<std::size_t>(columns[j])];
      if (v.node() < 0) v = TapedScalar::leaf(values[static_cast<std::size_t>(columns[j])], tape), ++leaves;
      leaf_of[j] = v.node();
    }
    const Eigen::Index len = static_cast<Eigen::Index>(s.rows.size()) * s.values_per_row();
    Eigen::MatrixXd by_leaf(len, leaves);
    RowSweep sweep(tape, leaves, by_leaf);
    predict_rows<TapedScalar>(m, s, layout, x.data(), sweep);
    const std::vector<std::size_t> zero_row = run_zero_rows(s);
    if (!zero_row.empty()) {
      const Eigen::MatrixXd reading = by_leaf;
      for (std::size_t k = 0; k < zero_row.size(); ++k)
        by_leaf.row(static_cast<Eigen::Index>(k)) =
            reading.row(static_cast<Eigen::Index>(k)) - reading.row(static_cast<Eigen::Index>(zero_row[k]));
    }
    const double unit = value_unit_mm(s);
    for (std::size_t j = 0; j < columns.size(); ++j)
      J.block(at, static_cast<Eigen::Index>(j), len, 1) = unit * by_leaf.col(leaf_of[j]);
    at += len;
  }
  return J;
}

}  // namespace ncpost::comp
