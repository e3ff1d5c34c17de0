// SPDX-License-Identifier: Apache-2.0
#pragma once
// The comparison of sessions (compare_sessions.hpp) for people: a text table for stdout, and a
// self-contained HTML page (report/) with the table — each figure per session as v ± U (k = 2) with
// its ISO 14253-1 verdict, the change first → last ± U_Δ and its outcome — and a trend plot (SVG)
// per figure over the session dates (days since the first) or, undated, the session number.
#include <string>

#include "ncpost/compensation/compare_sessions.hpp"

namespace ncpost::comp {

std::string compare_text(const Comparison& comparison);

/// `machine_file`: named with its SHA-256 with the sessions' files.
std::string compare_html(const Comparison& comparison, const std::string& machine_name,
                         const std::string& machine_file);

}  // namespace ncpost::comp
