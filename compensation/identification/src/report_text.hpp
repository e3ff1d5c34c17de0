// SPDX-License-Identifier: Apache-2.0
#pragma once
// The reports layer (ncpost::report: escape, base_name, page, plots) as seen from the
// identification reports (identify_report, diagnose_report, laser_report): `report::escape`,
// `report::base_name`, `report::page_start`, ... Internal to the compensation library.
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp::report {
using namespace ncpost::report;  // NOLINT: one name for the shared layer inside comp
}  // namespace ncpost::comp::report
