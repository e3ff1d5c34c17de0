// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the APT CL reader (cl::AptReader, postproc/src/apt_*.cpp). Bad input must
// end in InputError; anything else is a finding. The first byte picks the reader's options
// (MSYS applied or not, a coarse or fine curve tolerance, unterminated files allowed or not).
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "ncpost/postproc/read/apt/apt_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncpost::cl::ReaderOptions options;
  if (size > 0) {
    options.msys = (data[0] & 1) ? ncpost::cl::ReaderOptions::Msys::apply : ncpost::cl::ReaderOptions::Msys::ignore;
    options.curve_tolerance_mm = (data[0] & 2) ? 0.001 : 0.01;
    options.allow_unterminated = (data[0] & 4) != 0;
  }
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    ncpost::cl::AptReader reader(in, "fuzz.apt", options);
    for (int records = 0; records < 200000; ++records)
      if (!reader.next()) break;
    (void)reader.take_notices();
    (void)reader.failure_hint();
  } catch (const ncpost::InputError&) {
  }
  return 0;
}
