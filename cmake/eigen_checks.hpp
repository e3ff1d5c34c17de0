// SPDX-License-Identifier: Apache-2.0
#pragma once
// Included before every translation unit of ncpost (CMakeLists.txt, -include): Eigen's index and
// size checks stay on in release builds. A position sized for another model, or a wrong index,
// stops the job as an internal error (exit 4, the check and where it failed; the output file is
// not written: it is only renamed into place when complete), never reads past a vector
// silently. The model's axis count is a run-time size (AxisPosition::rotary_rad), so this is the
// check that sizes agree. A check that fails where no exception may pass ends the program.
#include <stdexcept>
#include <string>

/// A failed Eigen check: an internal error naming the check and where it failed.
[[noreturn]] inline void ncpost_eigen_check_failed(const char* check, const char* file, int line) {
  throw std::logic_error(std::string("Eigen check '") + check + "' failed at " + file + ":" + std::to_string(line));
}

#define eigen_assert(x) ((x) ? static_cast<void>(0) : ncpost_eigen_check_failed(#x, __FILE__, __LINE__))
