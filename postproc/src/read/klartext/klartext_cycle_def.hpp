// SPDX-License-Identifier: Apache-2.0
#pragma once
// The number and words of an old-style Klartext cycle block, `CYCL DEF 7.1 IX+10`,
// `CYCL DEF 32.1 T0.02` (the TNC writes such a cycle as blocks n.0, n.1, ...).
#include <string>
#include <vector>

#include "ncpost/postproc/read/klartext/klartext_block.hpp"

namespace ncpost::klartext {

struct CycleDef {
  int number = -1;          ///< 7 (datum shift), 32 (tolerance), 200 ...; -1: not a number
  int part = -1;            ///< the digit after the point (7.1: 1); -1 when none (200-series)
  std::vector<Word> words;  ///< after the number, tokenized as a block's words (columns in the line)
  std::string rest;         ///< after the number as written
};

/// Reads the cycle number and the words of `b` (a CYCL DEF block); words that do not tokenize
/// leave `words` empty and `rest` as written.
CycleDef cycle_def_of(const Block& b, const std::string& file, int line_number);

}  // namespace ncpost::klartext
