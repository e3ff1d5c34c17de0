#pragma once
// SPDX-License-Identifier: Apache-2.0
// Paths of the project and of its test data (tests/data/, see tests/data/real/SOURCES.md).
#include <string>

namespace ncpost::test {

inline std::string source(const std::string& rel) { return std::string(NCPOST_SOURCE_DIR) + "/" + rel; }
/// A file under tests/data/ (real CAM files in real/, public scenarios in scenarios/).
inline std::string data(const std::string& rel) { return std::string(NCPOST_SOURCE_DIR) + "/tests/data/" + rel; }
inline const char* const kShippedMachines[] = {"ac-trunnion", "tsutsumi-zxfyac", "gantry-bc-head",     "vmcl600",
                                               "haas-umc750", "bv100",           "linuxcnc-xyzac-trt", "hmc-b-table"};

}  // namespace ncpost::test
