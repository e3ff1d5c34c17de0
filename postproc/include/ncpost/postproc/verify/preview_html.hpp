// SPDX-License-Identifier: Apache-2.0
#pragma once
// The self-contained HTML report of `ncpost preview --html` (inline SVG, no scripts, no network):
// totals, the error of every block along the program, a histogram, the tool path (XY of W)
// coloured by error, the worst blocks with their source lines, and the harmonic model against the
// exact error curve of the worst block. Units: mm (µm where stated), degrees for orientation.
#include <string>
#include <vector>

#include "ncpost/postproc/verify/preview_summary.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::preview {

struct HtmlReport {
  std::string input_name;
  std::string machine_name;
  std::string model_name;                 ///< empty: nominal machine
  std::vector<report::InputFile> inputs;  ///< named with their SHA-256 (input, machine, model)
  const PreviewSummary* summary = nullptr;
  PreviewStats stats;
  std::vector<std::string> worst_source_lines;  ///< the source text of summary->worst(), same order
  std::vector<double> worst_curve_mm;           ///< |e(t)| of the worst block at t = k / (size − 1)
};

std::string render_html(const HtmlReport& report);

/// The text of the given 1-based lines of a file (empty strings for lines not found), read once.
std::vector<std::string> source_lines(const std::string& path, const std::vector<int>& lines);

}  // namespace ncpost::preview
