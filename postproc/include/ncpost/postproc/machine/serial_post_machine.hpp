// SPDX-License-Identifier: Apache-2.0
#pragma once
// A serial machine (machine.hpp: X Y Z and up to two rotary axes) as the machine of a post
// (post_machine.hpp): the nominal chain, or the actual machine of an identified error model
// (`--model`, ActualSolver), re-executed on the machine of `--verify-on` if given.
#include <memory>
#include <optional>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/machine/post_machine.hpp"

namespace ncpost {

/// The machine of a post: `machine` (load_machine), the errors the program compensates (`model`,
/// nullopt: the nominal machine) and those of the machine it is re-executed on (`verify_on`).
std::shared_ptr<const PostMachine> serial_post_machine(Machine machine,
                                                       std::optional<comp::ErrorParameters> model = std::nullopt,
                                                       std::optional<comp::ErrorParameters> verify_on = std::nullopt);

}  // namespace ncpost
