// SPDX-License-Identifier: Apache-2.0
#pragma once
// Filling the account of a post (PostAccount, post_report.hpp) the same way for every machine
// (post_request.cpp): the names of the job, the figures of the written
// program, and the blocks of the "before" (the plain post executed on the same machine).
#include <optional>
#include <string>

#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost::detail {

/// The names of the job: input (with the files to hash), machine (its file is `r.machine_source`),
/// model and verify-on model (where `r.machine` has them), the machine the program is executed on
/// in words, dialect, method, tolerance.
PostAccount account_of(const PostRequest& r, const std::optional<double>& tolerance_mm);

/// The written program's figures: motions in, blocks out, the re-executed program, the notices.
void add_posted(PostAccount& account, const PostSummary& summary);

/// One block of the "before": its largest error `error_mm`, at CL line `line`.
void add_before(PostAccount& account, int line, double error_mm);
/// Once every block of the "before" is added: the mean from the sum of their errors.
void close_before(PostAccount& account, double sum_mm);

/// The whole "before": the motions of `reader` with the commands of `nominal`, one block per CL
/// motion, executed by `executed` (the job's machine: the model's, or the nominal one); each block's
/// error goes into the figures and, at its CL end point, into the path map of the report.
/// Infeasible where a CL point has no admissible solution.
void measure_before(cl::Reader& reader, const KinematicModel& nominal, const preview::BlockEvaluator& executed,
                    const PostRequest& r, PostAccount& account);

}  // namespace ncpost::detail
