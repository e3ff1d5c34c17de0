// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the Sinumerik reader notes, passes on or refuses, by name (sinumerik_translator.hpp): one
// table per kind, one sentence each.
#include <optional>
#include <string>

namespace ncpost::sinumerik {

enum class GAction { pass, note, dwell, refuse };

/// Whether `name` is a drilling or boring cycle the reader runs (CYCLE81 82 83 85 86), also under MCALL.
bool is_hole_cycle(const std::string& name);

/// What a G code does in the reader (G0-G3, G90/G91, G500 are the translator's own).
GAction kept_g(int g);
/// What a noted G code is, for the notice.
const char* g_meaning(int g);
/// The message for a refused G code.
std::string refused_g(int g);
/// The message for an M function that is refused (M code with a meaning the reader cannot keep).
std::optional<std::string> refused_m(double m);
/// What a name that is noted and not posted is (SOFT, FFWON, CYCLE832 ...), or null.
const char* noted_name(const std::string& name);
/// The message for a name or call that is not read.
std::string refused_name(const std::string& name);
/// The message for an address that is not read (H, P, E, AR=, TURN= ...).
std::string refused_address(const std::string& name, bool number);

}  // namespace ncpost::sinumerik
