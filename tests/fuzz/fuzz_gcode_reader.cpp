// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the whole G-code input path (line source, grammar, modal interpreter, arc
// expansion, nominal kinematics) through gcode::GcodeClReader on an AC trunnion with offset
// pivots. Bad input must end in InputError (or Infeasible beyond the axis limits); every motion
// must be finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ac_trunnion_text.hpp"

namespace {

const ncpost::Machine& machine() {
  static const ncpost::Machine m = ncpost::parse_machine(
      ncpost::testing::ac_trunnion_toml("fuzz-ac", "[10, 25, 45]", "[10, 20, 30]"), "fuzz-ac.toml");
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  ncpost::gcode::GcodeReaderOptions options;
  options.arc_chord_tolerance_mm = 0.5;  // few points per arc: the time goes to parsing, not expansion
  try {
    ncpost::gcode::GcodeClReader reader(in, "fuzz.ngc", machine(), ncpost::Setup{}, options);
    for (int records = 0; records < 20000; ++records) {
      auto r = reader.next();
      if (!r) break;
      if (const auto* m = std::get_if<ncpost::cl::Motion>(&*r)) {
        // finite input numbers may still overflow in arithmetic (1e308 + 1e308): then the
        // motion is not finite, which the post must reject; here we only require no UB/crash
        (void)m->point.tip_mm.allFinite();
      }
    }
    (void)reader.take_notices();
  } catch (const ncpost::InputError&) {
  } catch (const ncpost::Infeasible&) {  // beyond the axis limits (A -120 .. 120): exit 3 in the CLI
  }
  return 0;
}
