#pragma once
// Paths of the project and of the shared data, for tests.
#include <string>

namespace ncpost::test {

inline std::string source(const std::string& rel) { return std::string(NCPOST_SOURCE_DIR) + "/" + rel; }
inline std::string shared(const std::string& rel) { return std::string(NCPOST_SHARED_DIR) + "/" + rel; }
inline const char* const kShippedMachines[] = {"ac-trunnion", "tsutsumi-zxfyac", "gantry-bc-head", "vmcl600",
                                               "haas-umc750", "bv100", "linuxcnc-xyzac-trt"};

}  // namespace ncpost::test
