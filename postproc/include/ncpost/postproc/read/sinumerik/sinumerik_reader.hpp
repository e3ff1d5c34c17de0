// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Siemens SINUMERIK 840D sl part program read into CL records (docs/formats.md "Sinumerik
// input"): the records the G-code reader gives for the same motions (gcode_cl_reader.hpp), so
// that the post, compensation, tolerance, --verify and reports work unchanged.
//
// How: the program is read whole (its jumps go backwards), run block by block as the control
// does — variables, expressions, program flow, subprograms, frames, CYCLE800, drilling cycles,
// orientation vectors (src/read/sinumerik/sinumerik_translator.hpp) — into plain ISO blocks that
// the G-code reader reads; every record, message and notice names the Sinumerik file and line
// the motion comes from. Without TRAORI or CYCLE800, X Y Z and the rotary words are machine
// commands (mapped through the nominal forward kinematics); under TRAORI, and after CYCLE800,
// X Y Z are the tool tip in W (as G43.4 in the G-code reader).
// What is read and what is refused by name: docs/formats.md "Sinumerik input".
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

namespace ncpost::sinumerik {

struct ReaderOptions {
  gcode::GcodeReaderOptions gcode;       ///< for the ISO blocks (units, dwell, circles, limits)
  double arc_chord_tolerance_mm = 1e-3;  ///< arcs in a tilted frame become points within this
  int max_call_depth = 16;               ///< subprogram levels
  long max_blocks = 50'000'000;          ///< blocks executed before the program is taken as an endless loop
};

class SinumerikReader final : public cl::Reader {
 public:
  /// Reads the whole of `in` (InputError for a block that does not tokenize).
  SinumerikReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                  ReaderOptions options = {});
  ~SinumerikReader() override;

  std::optional<cl::Record> next() override;
  std::vector<std::string> take_notices() override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// True when `head` (the start of a file) holds a construct of the Sinumerik language that plain
/// ISO G-code lacks: a `%_N_..._MPF/SPF` line, `DEF REAL|INT|BOOL|STRING`, `PROC`, a CYCLE8..
/// call, MCALL, GOTOF/GOTOB, SUPA, `T="..."`, a `name=value` assignment of an R parameter, an
/// axis, an orientation or a `_NAME` (`R1=`, `X=`, `A3=`, `CR=`, `_CAMTOL=`), TRANS/ROT/ATRANS/AROT. Comments do not
/// count.
bool looks_like_sinumerik(std::string_view head);

}  // namespace ncpost::sinumerik
