// SPDX-License-Identifier: Apache-2.0
#pragma once
// The TRR-XY machine (docs/trr-xy.md) as the machine of a post (post_machine.hpp): its commands
// are the words X Y U V W (trr_solver.hpp), its subdivider trr_subdivider.hpp; no RTCP, no tilted
// work plane, and the tool length is the machine file's tool offset.
#include <memory>
#include <optional>

#include "ncpost/kinematics/trr_xy_geometry.hpp"
#include "ncpost/postproc/machine/post_machine.hpp"

namespace ncpost {

/// The machine of a post: `machine` (load_trr_xy_machine), the errors the program compensates
/// (`model`, nullopt: the nominal machine) and those of the machine it is re-executed on (`verify_on`).
std::shared_ptr<const PostMachine> trr_xy_post_machine(trr::Machine machine,
                                                       std::optional<trr::Errors> model = std::nullopt,
                                                       std::optional<trr::Errors> verify_on = std::nullopt);

}  // namespace ncpost
