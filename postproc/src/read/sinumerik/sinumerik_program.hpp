// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Sinumerik file read whole (its blocks jump backwards: GOTOB, loops, subprogram calls) and
// structured: its program units, labels and the blocks that open and close each other.
//
// Program units: the main program runs from the start of the file (or its `%_N_NAME_MPF` line)
// to the next unit. A subprogram in the same file starts with `%_N_NAME_SPF` (as the control's
// archives write it) or `PROC NAME` and ends at the next unit or the end of the file; a call
// names it `NAME`, `CALL "NAME"`, `NAME(arguments)` (with the PROC's parameters) or `L<n>` (the
// unit `L<n>`).
// Labels (`NAME:`) and block numbers are looked for in the unit of the jump.
// IF/ELSE/ENDIF, WHILE/ENDWHILE, FOR/ENDFOR, REPEAT/UNTIL and LOOP/ENDLOOP are matched within
// their unit (an unmatched one is an InputError naming both lines). `IF cond GOTOF label` on one
// line is a conditional jump, no block.
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "read/sinumerik/sinumerik_line.hpp"

namespace ncpost::sinumerik {

struct ProgramLine {
  int number = 0;    ///< 1-based line in the file
  std::string text;  ///< as written (for messages)
  Line block;
  int unit = 0;             ///< index into Program::units
  std::size_t partner = 0;  ///< IF -> ELSE or ENDIF, ELSE -> ENDIF, ENDIF/ENDWHILE/... -> its opener
  std::size_t end = 0;      ///< an opener -> its closer
};

struct Unit {
  std::string name;                     ///< upper case ("" for the main program without a header)
  std::size_t first = 0;                ///< the first line of its body
  std::size_t last = 0;                 ///< one past its last line
  std::vector<std::string> parameters;  ///< PROC NAME(REAL A, INT B): the names
  std::vector<char> parameter_types;    ///< 'R' real, 'I' int, 'B' bool, 'S' string
};

struct Program {
  std::string file;
  std::vector<ProgramLine> lines;
  std::vector<Unit> units;  ///< units[0]: the main program
  std::map<std::string, std::size_t> unit_named;

  /// The line holding `label` (or block number "N<n>") in `unit`, searching forward from `from`
  /// (`forward`) or backward; nullopt when none.
  std::optional<std::size_t> find_label(int unit, const std::string& label, std::size_t from, bool forward) const;
};

/// Reads and structures the whole input; InputError (file:line:column) for a block that does not
/// tokenize or an unmatched control statement.
Program load_program(std::istream& in, const std::string& file);

}  // namespace ncpost::sinumerik
