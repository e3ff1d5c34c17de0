// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading back a TRR-XY NC program in tests (trr_post_test, trr_identify_test): the motion blocks
// as modal X Y U V W values after each block that moves; how far the program, executed (every block
// interpolated linearly in X Y U V W, forward kinematics), strays from a CL path.
#include <algorithm>
#include <cmath>
#include <optional>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "ncpost/kinematics/trr_xy_forward.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "polyline_distance.hpp"
#include "test_paths.hpp"

namespace ncpost::test {

/// The TRR-XY machine file and the hemisphere sample the TRR-XY tests post on it.
inline std::string trr_machine_path() { return source("machines/trr-xy.toml"); }
inline std::string hemisphere_sample_path() { return source("samples/hemisphere_5axis.cls"); }

/// The tool tips (W, mm) of the motions of the APT file at `path`: the path the executed tip must follow.
inline std::vector<Vec3d> read_cl_tips(const std::string& path) {
  std::ifstream in(path);
  cl::AptReader reader(in, path);
  std::vector<Vec3d> pts;
  while (auto r = reader.next())
    if (const auto* m = std::get_if<cl::Motion>(&*r)) pts.push_back(m->point.tip_mm);
  return pts;
}

/// The commands of every motion block of the program at `path` (empty if it cannot be read).
inline std::vector<trr::Command> read_trr_program(const std::string& path) {
  std::ifstream in(path);
  std::vector<trr::Command> out;
  Eigen::Matrix<double, 5, 1> w = Eigen::Matrix<double, 5, 1>::Constant(std::nan(""));
  const std::string letters = "XYUVW";
  const std::regex word("([XYUVW])(-?[0-9]+\\.?[0-9]*)");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '(' || line[0] == '%') continue;
    bool moved = false;
    for (std::sregex_iterator it(line.begin(), line.end(), word), end; it != end; ++it) {
      w[static_cast<Eigen::Index>(letters.find((*it)[1].str()[0]))] = std::stod((*it)[2].str());
      moved = true;
    }
    if (moved && w.allFinite()) out.push_back(trr::Command::from_words(w));
  }
  return out;
}

/// Distance (mm) from `p` to the polyline `path`, measuring every segment (PolylineDistance gives
/// the same for many points, faster).
inline double distance_to_path(const Vec3d& p, const std::vector<Vec3d>& path) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) best = std::min(best, segment_distance_mm(p, path[i], path[i + 1]));
  return best;
}

/// Largest distance (mm) of the executed tool tip from `path` (W) over every block of `program`,
/// `samples` points per block, on the machine `k` with the workpiece origin `origin_mm`; nullopt
/// if the forward kinematics fails somewhere.
inline std::optional<double> trr_executed_deviation(const trr::Kinematics& k, const std::vector<trr::Command>& program,
                                                    const std::vector<Vec3d>& path, const Vec3d& origin_mm,
                                                    int samples = 100) {
  double worst = 0.0;
  std::optional<Rigidd> warm;
  const PolylineDistance distance_to_cl(path);
  for (std::size_t b = 0; b + 1 < program.size(); ++b)
    for (int j = (b == 0 ? 0 : 1); j <= samples; ++j) {
      const double t = static_cast<double>(j) / samples;
      const trr::Command c = trr::Command::from_words((1 - t) * program[b].words() + t * program[b + 1].words());
      const auto tp = k.tool(c.slider_mm, warm);
      if (!tp) return std::nullopt;
      warm = tp->machine_T_plate;
      worst = std::max(worst, distance_to_cl(trr::Kinematics::tip_in_workpiece(*tp, c, origin_mm)));
    }
  return worst;
}

}  // namespace ncpost::test
