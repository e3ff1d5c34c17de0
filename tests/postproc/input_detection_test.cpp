// SPDX-License-Identifier: Apache-2.0
// Input kind detection (APT or G-code) from the head of a file: every real file, and G-code whose
// comments contain APT major words (ncpost's own headers: "(ncpost 0.1.0 from part.cls)").
#include <catch2/catch.hpp>

#include <fstream>

#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "test_paths.hpp"

namespace {
std::string head_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}
}  // namespace

TEST_CASE("every real file is detected as what it is") {
  for (const char* f :
       {"nx_APT_Project2.txt", "nx_APT_SimpleMillPlane.txt", "nx_APT_Variable_Axis.txt", "nx_APT_Zig_Zag_Smoothed.txt",
        "catia_peening.aptsource", "creo_bohren_1.ncl", "creo_schruppen_1.ncl"}) {
    INFO(f);
    CHECK(ncpost::cl::looks_like_apt(head_of(ncpost::test::data(std::string("real/") + f))));
  }
  for (const char* f :
       {"nx_PostProcessed_SimpleMillPlane.txt", "nx_PostProcessed_Variable_Axis.txt",
        "nx_PostProcessed_Zig_Zag_Smoothed.txt", "linuxcnc_boat-xyzbc.ngc", "linuxcnc_impeller-7bl-xyzac.ngc"}) {
    INFO(f);
    CHECK_FALSE(ncpost::cl::looks_like_apt(head_of(ncpost::test::data(std::string("real/") + f))));
  }
}

TEST_CASE("APT words inside G-code comments do not make it APT") {
  CHECK_FALSE(
      ncpost::cl::looks_like_apt("%\nO0001 (NCPOST)\n(ncpost 0.1.0 from part.cls)\n(RAPID FROM GOTO)\nG0 X1\n"));
  CHECK_FALSE(ncpost::cl::looks_like_apt("Tool Path Listing has 80 lines.\nG1 X1\n"));
  CHECK(ncpost::cl::looks_like_apt("PARTNO TEST\nGOTO / 1, 2, 3\n"));
  CHECK(ncpost::cl::looks_like_apt("  goto/1,2,3\n"));
  CHECK(ncpost::cl::looks_like_apt("$$ comment\nRAPID\n"));
}
