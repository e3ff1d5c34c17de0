// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/trr_preview_html.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "ncpost/postproc/preview_svg.hpp"

namespace ncpost::trr {

std::string preview_html(const PreviewReport& r) {
  namespace svg = preview::svg;
  double worst = 0.0, sum = 0.0;
  std::size_t over = 0;
  for (const PreviewRow& row : r.rows) {
    worst = std::max(worst, row.max_mm);
    sum += row.max_mm;
    if (row.max_mm > 0.005) ++over;
  }
  report::Provenance p;
  p.title = "Nonlinear error preview (TRR-XY): " + r.input_name;
  p.machine = r.machine_name;
  p.model = r.model_name;
  p.inputs = r.inputs;
  std::string s = report::page_start(p);
  s += fmt::format("<p>Input {}; machine {}, model {}. {} CL motions, {} feed blocks "
                   "(one per CL motion, X Y U V W interpolated linearly); largest error {:.4f} mm, mean {:.4f} mm, "
                   "{} blocks over 5 µm.</p>",
                   svg::escape(r.input_name), svg::escape(r.machine_name),
                   r.model_name.empty() ? std::string("none (nominal machine)") : svg::escape(r.model_name), r.motions,
                   r.rows.size(), worst, r.rows.empty() ? 0.0 : sum / static_cast<double>(r.rows.size()), over);
  if (!r.rows.empty()) {
    svg::Series exact{"exact", "#b2182b", {}, {}, false}, harmonic{"harmonic model (midpoint)", "#2166ac", {}, {}, true};
    for (const PreviewRow& row : r.rows) {
      exact.x.push_back(static_cast<double>(row.block));
      exact.y.push_back(row.max_mm);
      harmonic.x.push_back(static_cast<double>(row.block));
      harmonic.y.push_back(row.harmonic_mm);
    }
    svg::ChartFrame f;
    f.title = "Largest deviation of the executed tip from the CL segment, per block";
    f.x_label = "block";
    f.y_label = "mm";
    s += svg::line_chart(f, {exact, harmonic});
    std::vector<svg::PathSegment> segs;
    for (const PreviewRow& row : r.rows)
      segs.push_back({row.from_mm.x(), row.from_mm.y(), row.to_mm.x(), row.to_mm.y(), row.max_mm});
    svg::ChartFrame p;
    p.width = 700;
    p.height = 560;
    p.title = "Tool path in W seen from above, coloured by the block's error";
    p.x_label = "X mm";
    p.y_label = "Y mm";
    s += svg::path_plot(p, segs, std::max(worst, 1e-9), "mm");
    std::vector<PreviewRow> sorted = r.rows;
    std::sort(sorted.begin(), sorted.end(), [](const PreviewRow& a, const PreviewRow& b) { return a.max_mm > b.max_mm; });
    s += "<h2>Worst blocks</h2><table><tr><th>block</th><th>CL line</th><th>error mm</th><th>at t</th>"
         "<th>harmonic mm</th><th>orientation deg</th></tr>";
    for (std::size_t i = 0; i < std::min<std::size_t>(20, sorted.size()); ++i)
      s += fmt::format("<tr><td>{}</td><td>{}</td><td>{:.4f}</td><td>{:.3f}</td><td>{:.4f}</td><td>{:.4f}</td></tr>",
                       sorted[i].block, sorted[i].line, sorted[i].max_mm, sorted[i].at_t, sorted[i].harmonic_mm,
                       rad_to_deg(sorted[i].orientation_rad));
    s += "</table>";
  }
  return s + report::page_end();
}

}  // namespace ncpost::trr
