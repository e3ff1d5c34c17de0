// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/preview_csv.hpp"

#include <fmt/format.h>

namespace ncpost::preview {

std::string csv_row(const BlockRow& r) {
  return fmt::format("{},{},{:.6f},{:.5f},{:.6f},{:.6f},{:.5f},{:.6f}\n", r.block, r.line, r.exact.max_error_mm,
                     r.exact.at_t, r.harmonic_mm, rad_to_deg(r.exact.max_orientation_rad), r.exact.orientation_at_t,
                     r.harmonic_residual_mm);
}

CsvWriter::CsvWriter(AtomicFile& out) : out_(out) { out_.write(kCsvHeader); }

void CsvWriter::add(const BlockRow& row) { out_.write(csv_row(row)); }

}  // namespace ncpost::preview
