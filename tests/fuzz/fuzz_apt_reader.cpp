// libFuzzer target: the APT CL reader (cl::AptReader, postproc/src/apt_*.cpp). Bad input must
// end in InputError; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "ncpost/postproc/apt_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    ncpost::cl::AptReader reader(in, "fuzz.apt");
    for (int records = 0; records < 200000; ++records)
      if (!reader.next()) break;
    (void)reader.take_notices();
  } catch (const ncpost::InputError&) {
  }
  return 0;
}
