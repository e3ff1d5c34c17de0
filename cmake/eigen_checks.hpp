// SPDX-License-Identifier: Apache-2.0
#pragma once
// Included before every translation unit of ncpost (CMakeLists.txt, -include): Eigen's index and
// size checks stay on in release builds. A position sized for another model, or a wrong index,
// stops the program with the check that failed (no NC program is written: the output file is
// only renamed into place at the end), never reads past a vector silently. The model's axis
// count is a run-time size (AxisPosition::rotary_rad), so this is the check that sizes agree.
#include <cstdio>
#include <cstdlib>

/// A failed Eigen check: says which and where, then stops (abort: no output file is completed).
[[noreturn]] inline void ncpost_eigen_check_failed(const char* check, const char* file, int line) {
  std::fprintf(stderr, "ncpost: internal error: Eigen check '%s' failed at %s:%d; no program was written\n", check,
               file, line);
  std::abort();
}

#define eigen_assert(x) ((x) ? static_cast<void>(0) : ncpost_eigen_check_failed(#x, __FILE__, __LINE__))
