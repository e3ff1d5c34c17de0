// SPDX-License-Identifier: Apache-2.0
#pragma once
// The error model as the error hook of the one kinematic chain (kinematics/forward.hpp): named
// parameters (parameter_name.hpp) turned into AxisErrorTerms per axis and command.
//
// `ModelLayout` fixes which parameters exist and what each acts on; `ErrorFunctor<P>` pairs it
// with values of scalar type P (double for posting and simulation, automatic-differentiation
// scalars for identification) and with the state of the current measurement row (reversal
// offsets, time). Its call operator is templated on the command scalar S, so the same model also
// gives exact derivatives with respect to the commands (compensated inverse kinematics).
//
// Frames and units: every term is in M axes at home (mm, rad), docs/conventions.md "Geometric errors":
//   location errors   → location_offset_mm / location_tilt_rad of the rotary axis
//   squareness        → direction_offset: ŷ = (−EC0Y, 1, 0), ẑ = (EB0Z, −EA0Z, 1)
//   component errors  → motion_mm (EX, EY, EZ) / motion_rad (EA, EB, EC) of the axis:
//                       rotary Σ value·cos(kq) or value·sin(kq), linear Σ value·q^k (q in mm);
//                       table nodes (EXX:t:<pos>) of one function interpolated linearly in q,
//                       held at the end values outside the nodes; a rotary axis's table
//                       (ECC:t:<deg>) is periodic, interpolated round the turn
//   coupled location  → location_offset_mm / location_tilt_rad of the carried rotary axis, value ·
//                       q^k with q the command of the axis carrying it (EA0C:A:p1), read from the
//                       whole position the chain passes with each axis (the four-argument hook,
//                       kinematics/forward.hpp error_terms); at home q = 0. The carried axis's terms take
//                       the carrier's command as a constant: their derivative with respect to it
//                       (µm per rad for real sizes) is left out of the command derivatives
//   reversal          → the row's dead-band offset (reversal.hpp), not at home
//   drift             → a translation of the TCP relative to the table in M (added to the error
//                       motion of the linear axis nearest the bed, which moves the whole side),
//                       not at home: the set-up at home is at t = 0 of the drift law
// Instrument terms (ballbar length, sphere position) are read by the measurement predictions.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <stdexcept>
#include <vector>

#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/kinematics/forward.hpp"

namespace ncpost::comp {

/// The plain value of a scalar (double or an automatic-differentiation scalar).
template <class S>
double plain_value(const S& v) {
  if constexpr (std::is_arithmetic_v<S>)
    return static_cast<double>(v);
  else
    return plain_value(v.value());
}

/// The nodes of one tabulated error function: (position mm, parameter index), by position.
using TableNodes = std::vector<std::pair<double, int>>;

class ModelLayout {
 public:
  ModelLayout() = default;
  /// Throws std::invalid_argument("NAME: reason") for a name the machine cannot have.
  ModelLayout(const Machine& machine, const std::vector<std::string>& names);

  std::size_t size() const { return specs_.size(); }
  const ParameterSpec& spec(int i) const { return specs_[static_cast<std::size_t>(i)]; }
  const std::vector<ParameterSpec>& specs() const { return specs_; }
  int index_of(const std::string& name) const;
  std::vector<std::string> names() const;

  /// Parameters acting through the transform of this axis (location, squareness, component).
  const std::vector<int>& terms_of_axis(int axis_index) const {
    return axis_terms_[static_cast<std::size_t>(axis_index)];
  }
  /// Table nodes of component c (0..5) of a linear axis (empty if none).
  const TableNodes& table_of(int axis_index, int component) const {
    static const TableNodes none;
    if (static_cast<std::size_t>(axis_index) >= tables_.size()) return none;
    return tables_[static_cast<std::size_t>(axis_index)][static_cast<std::size_t>(component)];
  }
  /// True when the tables of this axis are periodic (a rotary axis: nodes in rad, round the turn).
  bool table_periodic(int axis_index) const {
    return static_cast<std::size_t>(axis_index) < periodic_.size() && periodic_[static_cast<std::size_t>(axis_index)];
  }
  int reversal_of(int axis_index) const { return reversal_[static_cast<std::size_t>(axis_index)]; }
  /// True when some parameter changes with the command (component error functions, tables,
  /// reversal); false when every term is a constant of the machine (location errors, squareness).
  bool command_dependent() const { return command_dependent_; }
  /// False when no parameter acts on this axis (its transform is the nominal one).
  bool acts_on(int axis_index) const {
    return static_cast<std::size_t>(axis_index) < acts_.size() && acts_[static_cast<std::size_t>(axis_index)];
  }
  bool has_reversal() const;
  /// True when some location error changes with another axis (ParameterKind::coupled).
  bool has_coupled() const { return coupled_; }
  const std::vector<int>& drift_terms() const { return drift_terms_; }
  int drift_axis() const { return drift_axis_; }
  int ballbar_length() const { return ballbar_length_; }
  const std::array<int, 3>& sphere_position() const { return sphere_position_; }

 private:
  std::vector<ParameterSpec> specs_;
  std::vector<std::vector<int>> axis_terms_;
  std::vector<std::array<TableNodes, 6>> tables_;
  std::vector<bool> periodic_;  ///< per axis: its tables are periodic (rotary)
  PerAxis<int> reversal_ = per_axis_filled(-1);
  std::vector<int> drift_terms_;
  int drift_axis_ = -1;
  std::vector<bool> acts_;  ///< per axis: any parameter acts on it
  bool command_dependent_ = false;
  bool coupled_ = false;
  int ballbar_length_ = -1;
  std::array<int, 3> sphere_position_{-1, -1, -1};
};

/// What the model needs to know about the measurement row being evaluated.
template <class P>
struct RowState {
  PerAxis<P> reversal = per_axis_filled(P(0));  ///< actual − command per axis (mm / rad)
  double time_s = 0.0;                          ///< time stamp for the drift law
  /// Where the axes stood before the current move (mm / rad). When set, the reversal offset of
  /// each command q is that of the dead band from there, clamp(previous, q, q + b) − q, instead of
  /// the fixed `reversal` above: a block that starts on a reversal first crosses the band standing
  /// still (posting: the commands of a block vary along it).
  std::optional<PerAxis<double>> previous_actual;
};

template <class P>
class ErrorFunctor {
 public:
  /// `values` has layout.size() entries and must outlive the functor. With `machine_only`, the
  /// effects that act only while measuring (drift, instruments) are left out (posting).
  ErrorFunctor(const ModelLayout& layout, const P* values, RowState<P> state = {}, bool machine_only = false)
      : layout_(&layout),
        values_(values),
        state_(state),
        machine_only_(machine_only),
        constant_(!layout.command_dependent() && (machine_only || layout.drift_terms().empty())) {}

  void set_state(const RowState<P>& s) { state_ = s; }
  /// The same functor carrying its home inverse (home_inverse() of this model; posting).
  ErrorFunctor with_home(const HomeInverse* home) const {
    ErrorFunctor f = *this;
    f.home_ = home;
    return f;
  }
  /// True when the machine this hook describes is a rigid chain like the nominal one with its axis
  /// lines moved: every term a constant (no component error functions, tables, reversal, and no
  /// drift unless measurement effects are left out).
  bool constant_in_command() const { return constant_; }
  /// The carried home inverse when it was computed for this tool length, else nullptr.
  const HomeInverse* cached_home(double tool_length_mm) const {
    return home_ && home_->tool_length_mm == tool_length_mm ? home_ : nullptr;
  }
  const RowState<P>& state() const { return state_; }
  const ModelLayout& layout() const { return *layout_; }
  /// Value of parameter i, or 0 for i < 0.
  P value(int i) const { return i < 0 ? P(0) : values_[i]; }

  /// The error terms of axis `axis_index` at its command q. A model with coupled terms
  /// (has_coupled()) needs the other axes' commands: the chain passes them all (the four-argument
  /// form, kinematics/forward.hpp); this form is for home and for models without coupled terms.
  template <class S>
  AxisErrorTerms<S> operator()(int axis_index, const S& q, bool at_home) const {
    if (!at_home && layout_->has_coupled())
      throw std::logic_error("error model: a coupled term needs every axis's command (call with the whole position)");
    return terms(axis_index, q, at_home, static_cast<const AxisPositionT<S>*>(nullptr));
  }
  /// The error terms of axis `axis_index` at its command q, the whole position being `all`.
  template <class S>
  AxisErrorTerms<S> operator()(int axis_index, const S& q, bool at_home, const AxisPositionT<S>& all) const {
    return terms(axis_index, q, at_home, &all);
  }

 private:
  template <class S>
  AxisErrorTerms<S> terms(int axis_index, const S& q, bool at_home, const AxisPositionT<S>* all) const {
    using std::cos;
    using std::sin;
    if constexpr (std::is_same_v<S, double> && std::is_same_v<P, double>) {
      // every term a constant: the terms computed once with the home pose (posting's hot path)
      if (home_ && constant_ && static_cast<std::size_t>(axis_index) < home_->terms_at_home.size())
        return home_->terms_at_home[static_cast<std::size_t>(axis_index)];
    }
    AxisErrorTerms<S> e;
    if (!layout_->acts_on(axis_index)) return e;
    for (int i : layout_->terms_of_axis(axis_index)) {
      const ParameterSpec& s = layout_->spec(i);
      const S v = S(values_[i]);
      const int c = s.component;
      switch (s.kind) {
        case ParameterKind::location:
          if (c < 3)
            e.location_offset_mm[c] += v;
          else
            e.location_tilt_rad[c - 3] += v;
          break;
        case ParameterKind::squareness:
          if (s.name == "EC0Y")
            e.direction_offset.x() -= v;
          else if (s.name == "EB0Z")
            e.direction_offset.x() += v;
          else
            e.direction_offset.y() -= v;  // EA0Z
          break;
        case ParameterKind::harmonic: {
          const S kq = S(double(s.order)) * q;
          const S f = s.sine ? S(sin(kq)) : S(cos(kq));
          add_motion<S>(e, c, S(v * f));
          break;
        }
        case ParameterKind::polynomial: {
          S power = q;
          for (int k = 1; k < s.order; ++k) power = power * q;
          add_motion<S>(e, c, S(v * power));
          break;
        }
        case ParameterKind::coupled: {
          // the carrier's command as a constant: its derivative is left out (µm per rad)
          const double by = at_home || all == nullptr ? 0.0 : plain_value((*all)[s.coupled_axis_index]);
          const S term = v * S(std::pow(by, s.order));
          if (c < 3)
            e.location_offset_mm[c] += term;
          else
            e.location_tilt_rad[c - 3] += term;
          break;
        }
        default:
          break;
      }
    }
    for (int c = 0; c < 6; ++c) {
      const TableNodes& nodes = layout_->table_of(axis_index, c);
      if (!nodes.empty())
        add_motion<S>(
            e, c, layout_->table_periodic(axis_index) ? interpolate_periodic<S>(nodes, q) : interpolate<S>(nodes, q));
    }
    if (at_home) return e;
    if (const int r = layout_->reversal_of(axis_index); r >= 0) {
      if (state_.previous_actual) {
        const double previous = (*state_.previous_actual)[static_cast<std::size_t>(axis_index)];
        S lo = q, hi = q + S(values_[r]);
        if (hi < lo) std::swap(lo, hi);
        const S actual = S(previous) < lo ? lo : (S(previous) > hi ? hi : S(previous));
        e.reversal = actual - q;
      } else {
        e.reversal = S(state_.reversal[static_cast<std::size_t>(axis_index)]);
      }
    }
    if (!machine_only_ && axis_index == layout_->drift_axis()) e.motion_mm += drift<S>();
    return e;
  }

 public:
  /// Drift of the TCP relative to the table at the row's time (mm, M axes).
  template <class S>
  Vec3<S> drift() const {
    using std::exp;
    Vec3<S> d = Vec3<S>::Zero();
    const double t = state_.time_s;
    std::array<S, 3> tau{S(600.0), S(600.0), S(600.0)};
    for (int i : layout_->drift_terms())
      if (layout_->spec(i).drift == DriftBasis::time_constant) tau[layout_->spec(i).component] = S(values_[i]);
    for (int i : layout_->drift_terms()) {
      const ParameterSpec& s = layout_->spec(i);
      const S v = S(values_[i]);
      switch (s.drift) {
        case DriftBasis::linear:
          d[s.component] += v * t;
          break;
        case DriftBasis::quadratic:
          d[s.component] += v * (t * t);
          break;
        case DriftBasis::exponential:
          d[s.component] += v * (S(1.0) - exp(-S(t) / tau[s.component]));
          break;
        case DriftBasis::time_constant:
          break;
      }
    }
    return d;
  }

 private:
  /// Linear interpolation of table nodes at q, held at the end values outside them.
  template <class S>
  S interpolate(const TableNodes& nodes, const S& q) const {
    const double x = plain_value(q);
    if (x <= nodes.front().first) return S(values_[nodes.front().second]);
    if (x >= nodes.back().first) return S(values_[nodes.back().second]);
    std::size_t i = 1;
    while (nodes[i].first < x) ++i;
    const auto& [x0, i0] = nodes[i - 1];
    const auto& [x1, i1] = nodes[i];
    const S w = (q - S(x0)) / S(x1 - x0);
    return S(values_[i0]) + w * (S(values_[i1]) - S(values_[i0]));
  }

  /// Linear interpolation of the nodes of a rotary axis's table (rad) at q, round the turn: the
  /// last node joins the first one turn on.
  template <class S>
  S interpolate_periodic(const TableNodes& nodes, const S& q) const {
    constexpr double turn = 2.0 * kPi;
    if (nodes.size() == 1) return S(values_[nodes.front().second]);
    const double x = plain_value(q);
    const double wraps = std::floor((x - nodes.front().first) / turn);
    const S u = q - S(wraps * turn);  // first <= u < first + turn
    const double ux = x - wraps * turn;
    std::size_t i = 1;
    while (i < nodes.size() && nodes[i].first <= ux) ++i;
    const auto& [x0, i0] = nodes[i - 1];
    const double x1 = i < nodes.size() ? nodes[i].first : nodes.front().first + turn;
    const int i1 = i < nodes.size() ? nodes[i].second : nodes.front().second;
    const S w = (u - S(x0)) / S(x1 - x0);
    return S(values_[i0]) + w * (S(values_[i1]) - S(values_[i0]));
  }

  template <class S>
  static void add_motion(AxisErrorTerms<S>& e, int c, const S& v) {
    if (c < 3)
      e.motion_mm[c] += v;
    else
      e.motion_rad[c - 3] += v;
  }

  const ModelLayout* layout_;
  const P* values_;
  RowState<P> state_;
  bool machine_only_;
  bool constant_;  ///< constant_in_command()
  const HomeInverse* home_ = nullptr;
};

}  // namespace ncpost::comp
