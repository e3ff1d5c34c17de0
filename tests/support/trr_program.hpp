// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading back a TRR-XY NC program in tests (trr_post_test, trr_identify_test): the motion blocks
// as modal X Y U V W values after each block that moves.
#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "ncpost/kinematics/trr_xy_forward.hpp"

namespace ncpost::test {

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

}  // namespace ncpost::test
