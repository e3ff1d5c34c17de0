// SPDX-License-Identifier: Apache-2.0
#pragma once
// The actual machine for posting and simulated execution: the nominal machine plus the machine
// errors of a model file. Effects that act only while measuring (drift, instrument terms) are
// left out (parameter_name.hpp `measurement_only`). Frames and units as forward.hpp: commands in
// mm / rad, tool pose in W.
#include <string>
#include <vector>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/error_parameters.hpp"

namespace ncpost::comp {

class MachineModel {
 public:
  /// Throws std::invalid_argument for a name the machine cannot have.
  MachineModel(const Machine& machine, const ErrorParameters& parameters);
  MachineModel(const MachineModel&) = delete;  // functors point into it
  MachineModel& operator=(const MachineModel&) = delete;

  const Machine& machine() const { return machine_; }
  const ModelLayout& layout() const { return layout_; }
  const std::vector<double>& values() const { return values_; }
  bool has_reversal() const { return layout_.has_reversal(); }

  /// The error hook for forward.hpp; `state` carries reversal offsets (reversal.hpp).
  ErrorFunctor<double> errors(const RowState<double>& state = {}) const {
    return ErrorFunctor<double>(layout_, values_.data(), state, true);
  }
  /// Actual tool tip and axis in W at command q.
  ToolPoseT<double> tool_pose(const AxisPosition& q, const Setup& setup, const RowState<double>& state = {},
                              const HomeInverse* home = nullptr) const {
    return ncpost::tool_pose<double>(machine_, q, setup, errors(state).with_home(home));
  }
  /// The home inverse of this model for a tool length (pass it to the calls above and to
  /// ErrorFunctor::with_home so that they skip recomputing it).
  /// The direction of a rotary axis whose location changes with another axis (EA0C:A:p1) is not
  /// a constant: it is left out of the cache (the chain computes it at each command).
  HomeInverse home_inverse(double tool_length_mm) const {
    HomeInverse h = ncpost::home_inverse(machine_, tool_length_mm, errors());
    for (const ParameterSpec& s : layout_.specs())
      if (s.kind == ParameterKind::coupled && static_cast<std::size_t>(s.axis_index) < h.rotary_direction.size())
        h.rotary_direction[static_cast<std::size_t>(s.axis_index)].reset();
    return h;
  }

 private:
  Machine machine_;
  ModelLayout layout_;
  std::vector<double> values_;
};

}  // namespace ncpost::comp
