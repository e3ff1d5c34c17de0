// SPDX-License-Identifier: Apache-2.0
#pragma once
// post() (post_request.hpp) for a TRR-XY job: the solver, subdivider, header and "before" account of
// that machine around the common post_program.
#include "ncpost/postproc/post_request.hpp"

namespace ncpost::detail {

/// post() with `r.trr` set.
PostResult post_trr(std::istream& input, std::ostream& program, const PostRequest& r);

}  // namespace ncpost::detail
