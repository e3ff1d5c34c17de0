// SPDX-License-Identifier: Apache-2.0
#pragma once
// The CSV of `ncpost preview --csv` (docs/cli.md): one row per previewed block,
//   block,line,max_error_mm,at_t,harmonic_mm,orientation_error_deg,orientation_at_t,harmonic_residual_mm
// (exact largest deviation from the straight CL segment in W and where along the block; the
// harmonic model's Emax; the largest orientation error; how far the harmonic curve is from the
// exact one). Written through an AtomicFile (a failed run leaves no partial file).
#include <string>

#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost::preview {

inline constexpr const char* kCsvHeader =
    "block,line,max_error_mm,at_t,harmonic_mm,orientation_error_deg,orientation_at_t,harmonic_residual_mm\n";

/// One CSV row (with its newline).
std::string csv_row(const BlockRow& row);

class CsvWriter {
 public:
  explicit CsvWriter(AtomicFile& out);
  void add(const BlockRow& row);

 private:
  AtomicFile& out_;
};

}  // namespace ncpost::preview
