// SPDX-License-Identifier: Apache-2.0
#include "verify/read_back.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncpost::detail {

void add_defect(VerifyReport& report, std::size_t program_line, int cl_line, const std::string& what) {
  constexpr std::size_t kMaxListed = 20;
  if (report.defects.size() < kMaxListed)
    report.defects.push_back(fmt::format("program line {} (CL line {}): {}", program_line, cl_line, what));
  else if (report.defects.size() == kMaxListed)
    report.defects.push_back("... and more (the first 20 are listed)");
}

double rapid_off_line_mm(const ReadBackBlock& rapid, bool at_start, const ExecuteWords& execute) {
  for (std::size_t i = 3; i < rapid.from.values.size(); ++i)
    if (rapid.from.values[i] != rapid.to.values[i]) return 0.0;  // the tool turns: not a straight line
  const ToolPoseT<double> end = execute(rapid.from, rapid.to, at_start ? 0.0 : 1.0);
  const Vec3d u = end.axis.normalized();
  const Vec3d shift = end.tip_mm - (at_start ? rapid.cl_from_mm : rapid.cl_to_mm);  // the execution error there
  const Vec3d a = rapid.cl_from_mm + shift, b = rapid.cl_to_mm + shift;
  constexpr int kSamples = 64;
  double worst = 0.0;
  for (int i = 0; i <= kSamples; ++i) {
    const Vec3d p = execute(rapid.from, rapid.to, static_cast<double>(i) / kSamples).tip_mm;
    const Vec3d d = p - end.tip_mm;
    const double along = d.dot(u);
    const double off_axis = along >= -kRapidLineToleranceMm ? (d - along * u).norm() : d.norm();
    worst = std::max(worst, std::min(off_axis, distance_to_segment(p, a, b)));
  }
  return worst;
}

}  // namespace ncpost::detail
