// SPDX-License-Identifier: Apache-2.0
#pragma once
// One LinuxCNC (RS274NGC) o-word statement as written: `o100 sub`, `O<name> call [1] [2]`,
// `o101 if [#1 GT 0]`, ..., with an optional block number or '/' before it and a comment after.
//   label   := 'o' digits | 'o<' name '>'     -- names compare without case and blanks
//   keyword := sub endsub return call if elseif else endif while endwhile do repeat endrepeat
//              break continue
// `argument_at` is where the text after the keyword starts (a condition, a count, call arguments).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace ncpost::gcode {

struct OWord {
  enum class Keyword {
    sub,
    endsub,
    return_,
    call,
    if_,
    elseif,
    else_,
    endif,
    while_,
    endwhile,
    do_,
    repeat,
    endrepeat,
    break_,
    continue_
  };
  std::string label;  ///< "o100", "o<name>" (normalized: lower case, no blanks)
  Keyword keyword = Keyword::sub;
  int column = 0;               ///< 1-based column of the 'o'
  std::size_t argument_at = 0;  ///< 0-based offset after the keyword
};

/// The o-word statement of `line`, or nullopt when the line is none (a program number `O1000`,
/// an ordinary block).
std::optional<OWord> read_o_word(std::string_view line);

/// The keyword as written in messages ("sub", "endwhile").
std::string_view keyword_name(OWord::Keyword k);

}  // namespace ncpost::gcode
