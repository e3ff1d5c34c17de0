// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text from input files and the command line shown on the terminal: control characters (C0, DEL,
// C1) and bytes that are not UTF-8 are written as escapes (\n, \r, \t, \xNN), so that a file cannot
// move the cursor, clear the screen or retitle the window through an error message.
#include <string>
#include <string_view>

namespace ncpost::cli {

std::string terminal_text(std::string_view text);

/// The column (1-based, in characters) at which byte column `byte_column` (1-based) of `text`
/// appears once `text` is shown through terminal_text().
int terminal_column(std::string_view text, int byte_column);

}  // namespace ncpost::cli
