// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Heidenhain conversational (Klartext) program (TNC 426 ... 640) read into CL records, streaming:
// the records the G-code reader gives for the same motions (gcode_cl_reader.hpp), so that the post,
// compensation, tolerance, --verify and reports work unchanged (docs/formats.md "Heidenhain
// Klartext input").
//
// Frames (docs/conventions.md): without M128 / FUNCTION TCPM, X Y Z and the rotary words are
// machine commands (the TNC applies the tool length along Z): each motion is mapped through the
// NOMINAL forward kinematics of the machine and job set-up to the tool tip and axis in W. Under
// M128 or FUNCTION TCPM (AXIS POS) X Y Z are the tool tip in W and the rotary words machine angles
// (as G43.4 in the G-code reader). cl::Motion::rotary_rad carries the programmed angles.
//
// Read: BEGIN PGM name MM / END PGM, block numbers, ';' comments and '*' structure blocks
// (cl::Comment), block skip '/', BLK FORM and TOOL DEF (noted), TOOL CALL n|"name" Z S F DL DR (tool
// change, by number or by name: cl::ToolChange::name; spindle speed, the FAUTO feed), L with X Y Z and the machine's
// rotary words (I...: incremental), R0 / RL / RR (cl::CutterComp: the post writes it or refuses), F / FMAX / F MAX /
// FAUTO (FMAX only for its block, as the TNC), M3 M4 M5 M8 M9 M13 M14 M0 M1 M2 M30, M126 (shortest
// rotary path) / M127, M128 / M129, FUNCTION TCPM / FUNCTION RESET TCPM, M140 MB MAX|n (a rapid
// along the tool axis: the machine Z, on a machine without a tilting head), M91 / M92 beside X Y Z
// (machine coordinates from the machine file's reference / reference2), STOP, and the paths
// CC, C, CR, CT, CP (klartext_arc.hpp): a cl::Circle and its end motion for a single-turn arc,
// else points within `arc_chord_tolerance_mm`; CYCL DEF 7 (datum shift), 32 (noted), 200 (drilling)
// and 207 (rigid tapping) as cl::Cycle (klartext_drilling.hpp), 203 (universal drilling), 208 (bore
// milling) and 241 (single-lip deep-hole drilling) expanded into motions (klartext_hole_path.hpp),
// called by CYCL CALL or M99; PLANE RESET STAY (noted).
// Refused by name with file:line:column and what to do: everything else (other cycles, PLANE, RND, CHF,
// LP, APPR/DEP, Q parameters, FN, LBL / CALL, M91 / M92 without the machine file's reference data,
// M89, M114, M116, M94, DL, INCH programs, FUNCTION TCPM with AXIS SPAT / F CONT / REFPNT other than
// TIP-TIP / PATHCTRL VECTOR).
// Start: rapids before X, Y and Z are all programmed are held and take those axes' first
// programmed values; a cutting motion before that is refused (where the tool starts is not known).
// Rotary axes not programmed yet stand at 0 (notice). Limits: a motion whose machine commands lie
// beyond an axis limit is Infeasible (exit 3), as in the G-code reader.
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::klartext {

struct ReaderOptions {
  bool allow_unterminated = false;       ///< a program without END PGM / M2 / M30 is posted (notice), not refused
  bool block_skip = true;                ///< blocks that start with '/' are left out
  double arc_chord_tolerance_mm = 1e-3;  ///< chord error bound of arcs expanded into points
  bool check_limits = true;              ///< the machine's axis limits (Infeasible beyond)
  std::shared_ptr<const ToolTable> tool_table;  ///< the tools' diameters (CYCL DEF 208); null: none
};

class KlartextReader final : public cl::Reader {
 public:
  /// Reads `in` (which must outlive the reader).
  KlartextReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                 ReaderOptions options = {});
  ~KlartextReader() override;

  std::optional<cl::Record> next() override;
  std::vector<std::string> take_notices() override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ncpost::klartext
