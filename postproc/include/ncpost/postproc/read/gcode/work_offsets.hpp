// SPDX-License-Identifier: Apache-2.0
#pragma once
// The values of a control's work offsets (`post --work-offsets FILE`, docs/formats.md "Work
// offsets"): for each offset G54-G59, G59.1-G59.3 and G54.1 P1..P300, where its zero lies in
// machine coordinates, per axis X Y Z (mm) and A B C (rad; degrees in the file). An axis the file
// does not give is unknown (not 0).
//
// Two file formats, told apart by their first line that is neither blank nor a comment:
//   TOML:      units = "mm" | "inch" (optional, mm), then per offset a table of axis values:
//                [G54]             X = 0.0  Y = 0.0  Z = -350.0
//                ["G54.1 P3"]      X = 120.5  B = 90.0
//   var file:  LinuxCNC's parameter file, lines "number value": 5221..5229 G54 (X Y Z A B C U V W),
//              5241.. G55, ... every 20 up to 5381.. G59.3; other numbers are skipped. Values in
//              mm and degrees (a machine configured in inches: write the TOML form with units).
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace ncpost::gcode {

/// One offset's zero in machine coordinates: X Y Z (mm), A B C (rad); nullopt: not known.
using OffsetValues = std::array<std::optional<double>, 6>;

struct WorkOffsetTable {
  std::string file;                             ///< where it was read (for messages)
  std::map<std::string, OffsetValues> offsets;  ///< by canonical name: "G54", "G59.1", "G54.1 P3"
};

/// The canonical name of an offset as a program or a file writes it ("g54.1 p03" -> "G54.1 P3",
/// "G55" -> "G55"), or nullopt when it is none of G54-G59, G59.1-G59.3, G54.1 P1..P300.
std::optional<std::string> work_offset_name(std::string_view text);

/// The offset that a `G10 L2 P<n>` (and LinuxCNC's `G10 L20 P<n>`) names for n = 1..9 (G54 ..
/// G59.3), or nullopt.
std::optional<std::string> work_offset_of_register(int n);

/// Reads either format from `text`; InputError at file:line:column when malformed.
WorkOffsetTable parse_work_offsets(const std::string& text, const std::string& file);

/// Reads a file; InputError (exit 2) when it cannot be opened or is malformed.
WorkOffsetTable load_work_offsets(const std::string& path);

}  // namespace ncpost::gcode
