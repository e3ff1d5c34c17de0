// SPDX-License-Identifier: Apache-2.0
#pragma once
// The post-processor for the TRR-XY machine (docs/trr-xy.md; docs/cli.md `ncpost post`/`preview`):
// CL records in, NC blocks with the words X Y (table) U V W (sliders of chains a, b, c) out.
//
// Every CL motion is solved by the TRR-XY inverse kinematics on `k` (the nominal machine, or
// the machine of an error model for `--model`: the commands then make the actual machine put the
// tool where the CL data say). Blocks are G1 (G0 for rapids) with feeds per minute (G94, the CL
// feed). With a tolerance, every block — rapids included, since the control interpolates them
// in axis space too — whose executed tool tip (linear interpolation of the *rounded* commands,
// forward kinematics on `k`) leaves the straight CL segment by more than 95 % of the tolerance is split
// into ceil(sqrt(error / target)) equal CL pieces (tip interpolated linearly, axis on the great
// circle; the error of a short block grows with its length squared), each checked again.
// CIRCLE records are expanded into points within `arc_tolerance_mm` chord error; drilling cycles
// are not expanded (their GOTOs are plain points, with a notice).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/trr_block_error.hpp"
#include "ncpost/postproc/cl_record.hpp"
#include "ncpost/postproc/nc_writer.hpp"
#include "ncpost/postproc/verify.hpp"

namespace ncpost::trr {

struct PostOptions {
  Vec3d workpiece_origin_mm = Vec3d::Zero();
  std::optional<double> tolerance_mm;     ///< bound of every block's nonlinear error (mm, W)
  double arc_tolerance_mm = 0.001;
  double default_feed_mm_min = 1000.0;
  int max_split_depth = 24;
  /// Blocks are split while their error exceeds this fraction of the tolerance: a margin for a
  /// checker that samples the block differently.
  double split_fraction = 0.95;
  bool verify = false;
  std::string program_name;
  std::vector<std::string> header_comments;
};

struct PostSummary {
  std::size_t motions_in = 0;
  std::size_t blocks_out = 0;
  std::size_t blocks_inserted = 0;     ///< blocks added by the tolerance
  double max_block_error_mm = 0.0;     ///< largest nonlinear error of an output block (as checked)
  std::vector<std::string> notices;
  VerifyReport verify;
};

/// A block of the output as the control executes it (rounded commands) with its CL segment.
struct PostedBlock {
  int line = 0;
  bool rapid = false;
  Block block;
};

/// Posts the whole input. Throws InputError (bad input) or Infeasible (a CL point out of reach;
/// the message names the file and line). `on_block` (optional) sees every written block.
PostSummary post_program(cl::Reader& reader, const std::string& input_name, const Kinematics& k, NcWriter& writer,
                         const PostOptions& options, const std::function<void(const PostedBlock&)>& on_block = {});

}  // namespace ncpost::trr
