// SPDX-License-Identifier: Apache-2.0
#pragma once
// The meaning of an APT `CYCLE/` statement (cl::Cycle): the cycle vocabularies of NX and CATIA
// (`CYCLE/DRILL,DEEP,RAPTO,3,FEDTO,-20,STEP,2,MMPM,250`, `RTRCTO,AUTO`), Creo
// (`CYCLE / TAP, DEPTH, d, TPI, 20, CLEAR, c`) and SOLIDWORKS CAM (`CYCLE/DEEP2,FEDTO,..,1STPECK,..,
// SUBPECK,..,MMPM,..,RAPTO,..,RTRCTO,..`, `CYCLE/INIT`, `CYCLE/CLEAR`). A kind or a word it does not
// know is an InputError naming the line: a hole drilled with a guessed meaning is a wrong part.
#include <optional>
#include <string>

#include "ncpost/postproc/read/apt/apt_reader.hpp"

namespace ncpost::cl {

struct AptCycleContext {
  const std::string& file;
  double mm_per_unit = 1.0;  ///< the file's length unit (UNITS/...)
  /// NX writes FEDTO signed along the tool axis (the bottom at GOTO + FEDTO·axis, negative);
  /// SOLIDWORKS CAM and Creo write the depth below the GOTO point as a positive number.
  bool signed_fedto = false;
};

/// The cycle record of a CYCLE statement, or none for the statements that only open or clear a
/// cycle definition (SOLIDWORKS CAM's `CYCLE/INIT` and `CYCLE/CLEAR`). Throws InputError.
std::optional<Cycle> read_apt_cycle(const AptStatement& st, const AptCycleContext& context);

}  // namespace ncpost::cl
