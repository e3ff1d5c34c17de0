// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

MachineModel::MachineModel(const Machine& machine, const ErrorParameters& parameters)
    : machine_(machine), layout_(machine, parameters.names()), values_(parameters.values()) {}

}  // namespace ncpost::comp
