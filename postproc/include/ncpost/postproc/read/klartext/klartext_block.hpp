// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block (line) of a Heidenhain conversational ("Klartext", plain-language) program as
// written (TNC 426 ... 640), before any meaning is applied (docs/formats.md "Heidenhain Klartext
// input"). A hand-written tokenizer, as small as the language.
//
// Lexical rules:
//   block     := [ '/' ] [ number ] [ statement { word } ] [ ';' text ]  -- blanks between
//   statement := '*' text                      -- a structure block ("* - ROUGHING"): a comment
//              | keyword [ keyword2 ]          -- BEGIN PGM, TOOL CALL, L, CC, CYCL DEF, PLANE ...
//              | (a block that starts with an M word: the statement "M", its words follow)
//   word      := name [ sign ] [ value ]       -- X+10, IX-5, R0, RL, DR+, FMAX, F MAX, M3, S5000
//              | '"' text '"'                  -- a tool name
//              | value                         -- a number without a name (TOOL CALL 5)
//   name      := letters (upper case in Block; input is case-insensitive)
//   value     := digits [ '.' digits ] | '.' digits  (the sign is part of the word)
// A word whose value is a Q parameter (`X+Q1`, `FQ5`) is kept with `q_parameter` set: the reader
// refuses it by name. A line ending in '~' continues on the next (cycle parameters): `continued`.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::klartext {

struct Word {
  std::string name;             ///< "X", "IX", "R", "RL", "DR", "FMAX", "M", "" (a bare number), "\"" (a string)
  char sign = 0;                ///< '+', '-' or 0 as written before the value (DR+ has a sign and no value)
  std::optional<double> value;  ///< signed
  std::string text;             ///< the string of a "..." word; the Q parameter of a q_parameter word ("Q1")
  bool q_parameter = false;     ///< the value is a Q parameter, not a number
  int column = 0;               ///< 1-based column of the word's first character
};

struct Block {
  bool deleted = false;        ///< starts with '/' (block skip)
  std::optional<long> number;  ///< the block number
  std::string statement;       ///< upper case, single blanks: "L", "TOOL CALL", "BEGIN PGM", "*" ...; "" when none
  int column = 0;              ///< 1-based column of the statement (0: none)
  std::vector<Word> words;     ///< after the statement, in the order written
  std::string text;            ///< what follows the statement as written, blanks trimmed (BEGIN PGM name MM)
  std::string comment;         ///< the text after ';' (or after '*'), blanks trimmed
  int comment_column = 0;      ///< 1-based column of ';' or '*' (0: none)
  bool continued = false;      ///< the line ends with '~' (the block goes on on the next line)

  bool empty() const { return statement.empty() && comment_column == 0; }
  /// The first word called `name`, or null.
  const Word* find(std::string_view name) const;
};

/// Parses `line` (one physical line, without its terminator). InputError (file:line:column) when a
/// character cannot start a word.
Block parse_block(std::string_view line, const std::string& file, int line_number);

/// True when the first block of `head` (the start of a file) is `BEGIN PGM` (with or without a
/// block number), blank lines and ';' comments before it allowed.
bool looks_like_klartext(std::string_view head);

}  // namespace ncpost::klartext
