// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text written into an NC program (comments, the program name): file names, the machine's name,
// PARTNO and PPRINT text come from users and CAM files, so every such text passes through the
// sanitiser of the program's dialect before it is written. Whatever the input, the result is one
// line of printable ASCII that cannot end the comment, the block or the tape (README "Output
// text"): control characters (newlines included) become spaces, non-ASCII characters '?', the
// dialect's comment terminators and '%' are replaced, and the text is cut to the dialect's length
// (the rules: Dialect::comment_rules, from the dialect file's [comments]).
#include <cstddef>
#include <string>
#include <string_view>

#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost {

/// `text` made safe as the text of one comment in `dialect`.
std::string nc_comment_text(std::string_view text, const Dialect& dialect);

/// `name` made safe as a program name: letters, digits and '_' only (upper case), at most the
/// dialect's length; "NCPOST" if nothing is left.
std::string nc_program_name(std::string_view name, const Dialect& dialect);

}  // namespace ncpost
