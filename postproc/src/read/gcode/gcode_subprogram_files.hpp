// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a subprogram the program's file does not hold is found (docs/formats.md "Subprograms in
// other files"). The directories are searched in order: --subprogram-dir, then the program's own.
//   Fanuc/Haas  M98 P<n>      a file whose name before its first '.' is O<n> or <n>, the number
//                             with any zero padding and the O of either case (O1234.nc, o01234.NC,
//                             1234.tap, O1234); two such files in one directory are ambiguous
//   LinuxCNC    o<name> call  the file <name>.ngc, the name in lower case as LinuxCNC looks it up
//                             (its SUBROUTINE_PATH)
// The file must then hold the program (O<n>, `o<name> sub`); the reader checks that.
#include <string>
#include <vector>

namespace ncpost::gcode {

struct SubprogramFile {
  std::string path;        ///< the file found ("" none)
  std::string error;       ///< why none was taken: not found (where it looked), or ambiguous
  bool ambiguous = false;  ///< two files could hold it
};

/// The file of Fanuc program O<number> in `dirs` (the first directory that has one).
SubprogramFile find_program_file(long number, const std::vector<std::string>& dirs);

/// The file of LinuxCNC `o<name>` (`name` without the brackets, lower case) in `dirs`.
SubprogramFile find_sub_file(const std::string& name, const std::vector<std::string>& dirs);

}  // namespace ncpost::gcode
