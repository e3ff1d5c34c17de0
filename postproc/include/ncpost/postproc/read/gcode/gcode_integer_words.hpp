// SPDX-License-Identifier: Apache-2.0
#pragma once
// Coordinates written without a decimal point (`X20`): whole units (LinuxCNC, grbl, Haas, a Fanuc
// with parameter DPI = 1) or least input increments (a Fanuc with DPI = 0: `X20` is 0.020 mm),
// as cl::IntegerWords says (--integer-words; docs/choices.md "G-code input").
//
// The letters read so: X Y Z, U V W, A B C, I J K, R (and the Q of a canned cycle, read where the
// cycle reads it). Not in a G4 block (X is the dwell's time there: --dwell-p). The least input
// increment is IS-B's: 0.001 mm, 0.0001 in, 0.001 deg.
//
// IntegerWords::automatic reads units, and watches the program's own evidence: a writer that puts
// a decimal point on a whole number (`X20.`, `Z0.0`) knows that its control needs one, so a
// coordinate without one in the same program (`X20`) is a slip or another control's convention.
// Both seen (zero without a point counts for neither: it is 0 either way; lines whose numbers were
// computed by expressions give no evidence of a point): refused, naming both words and lines.
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"

namespace ncpost::gcode {

/// The letters whose words are lengths or angles written in the program's units.
inline constexpr std::string_view kIntegerWordLetters = "XYZUVWABCIJKR";

/// The value of `units_value` (a whole number written without a decimal point) read as IS-B least
/// input increments of `letter`'s word under G20 (`inch`) or G21: 0.0001 in, 0.001 mm or 0.001 deg.
double in_least_increments(double units_value, char letter, bool inch);

/// The word as written at its column of `line` ("X20.", "Y-5"), for messages.
std::string written_word(std::string_view line, const Word& word);

/// IntegerWords::automatic's watch over a program (see above).
class IntegerWordEvidence {
 public:
  /// A refusal: the column in the block and its text.
  struct Refusal {
    int column = 0;
    std::string text;
  };
  /// Notes the coordinate words of a block (`dwell`: a G4 block, whose X is a time; `computed`: its
  /// numbers come from expressions). Returns the refusal where the block completes a mixture.
  std::optional<Refusal> note(const Block& block, std::string_view line, const std::string& file, int line_number,
                              bool dwell);

 private:
  struct Seen {
    std::string word, file;
    int line = 0;  ///< 0: not seen
  };
  Seen with_point_, without_point_;
};

}  // namespace ncpost::gcode
