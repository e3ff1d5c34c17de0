// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block (line) of a Sinumerik 840D sl part program as written, before any meaning is applied
// (docs/formats.md "Sinumerik input"). A hand-written tokenizer.
//
// Lexical rules (SINUMERIK 840D sl Programming Manual "Fundamentals" and "Job planning"):
//   block     := [ '/' ] [ 'N' digits | ':' digits ] [ label ':' ] ( statement rest | { item } ) [ ';' text ]
//   statement := DEF | IF | ELSE | ENDIF | WHILE | ENDWHILE | FOR | ENDFOR | REPEAT | UNTIL | LOOP | ENDLOOP
//              | GOTOF | GOTOB | GOTO | GOTOC | PROC | RET | CASE | ...   -- `rest` is the text after it
//   item      := address [ sign ] number         -- X10.5, G1, M3, R12? no: R12=... (assignment)
//              | name '=' expression             -- X=R1+5, R12=3, _CAM=0.01, CR=5, A3=0.7, T="MILL"
//              | name '(' arguments ')'          -- CYCLE800(...), MSG("..."), IC(5) after '='
//              | name                            -- TRAORI, SOFT, G-group words written as names
//   address   := letters, then digits before '=' or '(' make them part of the name (A3=, CYCLE81()
//   expression:= operand { operator operand }   -- blanks allowed around operators
// Names are upper case in the result; input is case-insensitive; strings keep their case. ';'
// inside a string does not start a comment.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncpost::sinumerik {

struct Item {
  enum class Kind { word, assign, call, name };
  Kind kind = Kind::name;
  std::string name;             ///< upper case: "X", "G", "R12", "CYCLE800", "_X_HOME", "TRAORI"
  std::string text;             ///< word: the number as written; assign: the expression; call: inside ( )
  std::optional<double> value;  ///< word: the signed number
  int column = 0;               ///< 1-based column of the name
};

struct Line {
  bool skip = false;                 ///< starts with '/'
  std::optional<long> block_number;  ///< N...
  std::string label;                 ///< upper case, without ':'
  std::string statement;             ///< a control statement (upper case), "" when the block holds items
  std::string rest;                  ///< after the statement, comment removed, blanks trimmed
  int statement_column = 0;
  int rest_column = 0;
  std::vector<Item> items;
  std::string comment;  ///< after ';', trimmed
  int comment_column = 0;
  std::string header;  ///< "%_N_NAME_MPF" / "%_N_NAME_SPF" (a program unit's first line)

  bool empty() const { return statement.empty() && items.empty() && header.empty(); }
};

/// A Sinumerik tokenizing error at a 0-based offset of the line.
struct LexError {
  std::size_t offset;
  std::string what;
};

/// Parses one physical line; throws LexError.
Line lex_line(std::string_view text);

/// Where the expression starting at `at` ends (0-based offset one past it): operands joined by
/// operators, blanks around operators allowed (`R1 + 2*R3`), ending at a blank before something
/// that is not an operator, or at ';'. Throws LexError on unbalanced parentheses or quotes.
std::size_t expression_end(std::string_view text, std::size_t at);

/// The top-level comma-separated arguments of a call (`CYCLE800(0,"TC",,57)`), trimmed; an empty
/// argument is "".
std::vector<std::string> split_arguments(std::string_view inside);

/// A call's arguments (split_arguments) and which of them are given.
struct Arguments {
  std::vector<std::string> text;
  bool given(std::size_t i) const { return i < text.size() && !text[i].empty(); }
};

/// Upper case of ASCII letters.
std::string upper(std::string_view s);

}  // namespace ncpost::sinumerik
