// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sphere-probing data of the TRR-XY machine in CSV (docs/formats.md "Measurement data", an ncpost
// variant for this machine, documented in kinematics/TRR-XY.md):
//   # type: sphere
//   # machine: trr-xy
//   t,X,Y,U,V,W,stylus,dx,dy,dz
// X Y U V W: commanded positions (mm); stylus: the probe's extra length L beyond the tool (mm; the
// probed point is fixed to the tool at (0, 0, −L) from the TCP at home); dx dy dz: the sphere
// centre deviation (mm, M). A plan has no dx dy dz (or they are ignored). Unknown `# key:` lines
// are kept; a bad row is an InputError with file and line.
#include <map>
#include <string>
#include <vector>

#include "ncpost/compensation/trr_identify.hpp"

namespace ncpost::trr {

struct ProbingRow {
  double t_s = 0.0;
  Command command;
  double stylus_mm = 0.0;
  Vec3d deviation_mm = Vec3d::Zero();
};

struct ProbingData {
  std::map<std::string, std::string> metadata;
  std::vector<ProbingRow> rows;
};

/// Reads a file; with `plan`, the dx dy dz columns may be absent.
ProbingData read_probing_csv(const std::string& path, bool plan);
std::string format_probing_csv(const ProbingData& d, bool plan);

/// The rows as identification input.
std::vector<ProbeMeasurement> measurements(const ProbingData& d);

}  // namespace ncpost::trr
