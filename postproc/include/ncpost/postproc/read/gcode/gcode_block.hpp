// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block (line) of an RS274-family program as written: its words, comments and markers,
// before any meaning is applied (docs/formats.md "NC programs").
//
// Lexical rules (the Spirit X3 grammar is in gcode_block_parser.cpp):
//   block   := [ '/' ] [ name | ':' number ] { comment | keyword | word } [ ';' text ] -- blanks anywhere
//              between; ':' is the ISO program number address, read as the word O (`:1234` = `O1234`)
//   name    := 'O' digits* (letter|'_'|'-') { not blank, '(' or ';' }  -- a program name (NX:
//              Omnf01_vx_0, O2021-11-28_test2setup_1); 'O' digits is a program number word
//   word    := letter number                                           -- letter case-insensitive
//   number  := [ '+' | '-' ] ( digits [ '.' digits? ] | '.' digits )   -- no exponent, NaN, Inf
//   comment := '(' text ')'  -- parentheses inside balanced: `(TEST (NESTED) COMMENT)` is one
//   keyword := TRAORI [ '(' n ')' ] | TRAFOOF                          -- Sinumerik RTCP on/off
// A line holding only '%' (and blanks) is a program delimiter. Blanks may stand between a letter
// and its number (`X  16.339`) but not inside a number (`X1 0` is an error, not X10).
// Parameters (`#1`), expressions (`[...]`) and macro statements are evaluated before this grammar
// reads a line (gcode_macro.hpp); here they are rejected with the exact column, as are O-word
// control flow and a line that starts with a number (a Heidenhain conversational block such as
// `0010 BEGIN PGM 100 MM` is named as such).
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::gcode {

/// A letter word: the letter in upper case, its value as written (no unit conversion).
struct Word {
  char letter = '?';
  double value = 0.0;
  int column = 0;          ///< 1-based column of the letter
  bool has_point = false;  ///< the number was written with a decimal point (P1. vs P1000)
};

/// A `(...)` or `;` comment; `text` views the line buffer (valid until the next line is read).
struct BlockComment {
  std::string_view text;
  int column = 0;  ///< 1-based column of '(' or ';'
};

enum class Keyword { traori, trafoof };

struct BlockKeyword {
  Keyword keyword = Keyword::traori;
  int column = 0;
};

/// One parsed line. Containers are cleared and refilled for every line (capacity is reused).
struct Block {
  bool percent = false;           ///< a '%' program delimiter line
  bool deleted = false;           ///< starts with '/' (block delete)
  std::string_view program_name;  ///< `Oname` (without the O), viewing the line buffer
  int column = 0;                 ///< 1-based column of the first non-blank character (0: blank line)
  std::vector<Word> words;        ///< in the order written
  std::vector<BlockComment> comments;
  std::vector<BlockKeyword> keywords;
  bool computed = false;  ///< its numbers were computed from parameters or expressions (gcode_macro.hpp)

  void clear() {
    percent = deleted = computed = false;
    program_name = {};
    column = 0;
    words.clear();
    comments.clear();
    keywords.clear();
  }
  bool empty() const {
    return !percent && program_name.empty() && words.empty() && comments.empty() && keywords.empty();
  }
};

/// Parses one line (without its line terminator) into `block`. Throws InputError naming
/// `file`, `line_number` and the exact column, with the line for a caret display.
void parse_block(std::string_view line, Block& block, const std::string& file, int line_number);

}  // namespace ncpost::gcode
