// SPDX-License-Identifier: Apache-2.0
#pragma once
// The reader of a post's input: APT CL data, G-code (machine axes or tool tip under RTCP) or a
// Heidenhain Klartext or Sinumerik program read back into CL records (docs/cli.md `--input-kind`). With `automatic` the
// kind is detected from the first 4 KiB of the stream, which is then put back where it was: the stream must be
// seekable.
#include <istream>
#include <memory>
#include <string>

#include <functional>
#include <optional>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost {

enum class InputKind {
  automatic,  ///< CL data if the text looks like APT, else G-code of either kind (detected)
  cl,         ///< APT CL data
  machine,    ///< G-code with machine axis positions
  rtcp,       ///< G-code with the tool tip in W and rotary angles (RTCP)
  klartext,   ///< a Heidenhain conversational program (klartext_reader.hpp); detected by its BEGIN PGM
  sinumerik,  ///< a Sinumerik 840D sl program (sinumerik_reader.hpp); detected by DEF, CYCLE800, %_N_ ...
};

/// "auto", "cl", "machine", "rtcp", "klartext", "sinumerik" (the CLI words); std::invalid_argument otherwise.
InputKind input_kind_named(const std::string& name);

/// Opens the reader of `in` for its kind. InputError (naming `name`) when `automatic` finds an
/// empty input. `machine` and `setup` read G-code back into CL points; they must outlive the reader.
std::unique_ptr<cl::Reader> open_cl_reader(std::istream& in, const std::string& name, InputKind kind,
                                           const cl::ReaderOptions& options, const Machine& machine,
                                           const Setup& setup);

/// The same for a machine whose words are not a serial chain's (the TRR-XY machine): G-code is read
/// through `word_forward` (gcode_cl_reader.hpp GcodeReaderOptions::word_forward), `machine` lists
/// its words. `InputKind::rtcp` is a usage error of the caller (std::invalid_argument).
std::unique_ptr<cl::Reader> open_cl_reader(
    std::istream& in, const std::string& name, InputKind kind, const cl::ReaderOptions& options, const Machine& machine,
    const Setup& setup,
    const std::function<std::optional<ToolPoseT<double>>(const AxisPosition&, std::string*)>& word_forward);

/// The NC axis words of the machine in chain order, e.g. "XYZAC".
std::string axis_letters(const Machine& machine);

}  // namespace ncpost
