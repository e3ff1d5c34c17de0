// SPDX-License-Identifier: Apache-2.0
#pragma once
// `preview --model` uses the post's actual-machine solver (actual_solver.hpp).
#include "ncpost/postproc/solve/actual_solver.hpp"

namespace ncpost::preview {

using ModelMotionSolver = ActualSolver;

}  // namespace ncpost::preview
