// SPDX-License-Identifier: Apache-2.0
#pragma once
// Human reports of a laser identification (issue 7): text for stdout, self-contained HTML with a
// plot per error function (SVG). Values in µm and µrad; ISO 230-2 figures per positioning line;
// squareness from the straightness slopes (ISO 230-1); what the lines cannot see.
#include <string>

#include "ncpost/compensation/laser_identify.hpp"

namespace ncpost::comp {

std::string laser_text_report(const Machine& machine, const LaserIdentifyResult& result);
std::string laser_html_report(const Machine& machine, const LaserIdentifyResult& result);

}  // namespace ncpost::comp
