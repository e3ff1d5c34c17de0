// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "ncpost/report/html_page.hpp"
// The HTML report of `ncpost preview --html` on the TRR-XY machine: self-contained (inline SVG,
// no scripts): summary, the nonlinear error of every feed block (exact and the harmonic model's
// midpoint estimate), the tool path seen from above coloured by that error, the worst blocks.
#include <string>
#include <vector>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::trr {

struct PreviewRow {
  std::size_t block = 0;
  int line = 0;
  double max_mm = 0.0, at_t = 0.0, harmonic_mm = 0.0, orientation_rad = 0.0;
  Vec3d from_mm = Vec3d::Zero(), to_mm = Vec3d::Zero();  ///< CL end points in W
};

struct PreviewReport {
  std::string input_name, machine_name, model_name;
  std::vector<report::InputFile> inputs;  ///< named with their SHA-256
  std::size_t motions = 0;
  std::vector<PreviewRow> rows;
};

std::string preview_html(const PreviewReport& r);

}  // namespace ncpost::trr
