// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the Klartext reader does not read, by name, with what to do instead (klartext_reader.hpp).
#include <optional>
#include <string>

#include "ncpost/postproc/read/klartext/klartext_block.hpp"

namespace ncpost::klartext {

/// True for the hole cycles the reader reads (CYCL DEF 200, 201, 203, 206, 207, 208, 209, 240, 241).
bool is_hole_cycle(int number);

/// Those cycles' numbers for a message, "200, 201, ... `last_word` 241".
std::string hole_cycles_listed(const char* last_word);

/// The message for a statement the reader does not read (CYCL DEF 200, PLANE SPATIAL, RND ...).
std::string refused_statement(const Block& b);

/// The message for an M function that changes what the program's words mean (M114, M116, M94 ...)
/// or calls something the reader does not read (M99, M89); nullopt for the others.
std::optional<std::string> refused_m(int code);

}  // namespace ncpost::klartext
