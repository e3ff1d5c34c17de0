// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/post_hooks.hpp"

namespace ncpost {

const PostHooks& post_hooks_of(const KinematicModel& model) {
  static const PostHooks kNone;
  const auto* own = dynamic_cast<const PostHooks*>(&model);
  return own ? *own : kNone;
}

}  // namespace ncpost
