// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/post_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "ncpost/kinematics/pose.hpp"
#include "ncpost/postproc/preview_svg.hpp"

namespace ncpost {

void MaxSeries::add(double x, double y) {
  if (!buckets_.empty() && buckets_.back().n < per_bucket_) {
    Bucket& b = buckets_.back();
    b.x1 = x;
    b.y = std::max(b.y, y);
    ++b.n;
    return;
  }
  buckets_.push_back({x, x, y, 1});
  if (buckets_.size() > max_points_) merge_pairs();
}

void MaxSeries::merge_pairs() {
  std::vector<Bucket> merged;
  for (std::size_t i = 0; i < buckets_.size(); i += 2) {
    Bucket b = buckets_[i];
    if (i + 1 < buckets_.size()) {
      b.x1 = buckets_[i + 1].x1;
      b.y = std::max(b.y, buckets_[i + 1].y);
      b.n += buckets_[i + 1].n;
    }
    merged.push_back(b);
  }
  buckets_ = std::move(merged);
  per_bucket_ *= 2;
}

std::vector<double> MaxSeries::xs() const {
  std::vector<double> out;
  for (const auto& b : buckets_) out.push_back(0.5 * (b.x0 + b.x1));
  return out;
}

std::vector<double> MaxSeries::ys() const {
  std::vector<double> out;
  for (const auto& b : buckets_) out.push_back(b.y);
  return out;
}

std::string account_text(const PostAccount& a) {
  std::string t;
  t += fmt::format("before (one block per CL motion, nominal commands, on {}): largest contour error {:.4f} mm "
                   "(CL line {}), mean {:.4f} mm over {} blocks\n",
                   a.executed_on, a.before_max_mm,
                   a.before_worst_line, a.before_mean_mm, a.before_blocks);
  if (a.uncompensated_tip_max_mm >= 0.0)
    t += fmt::format("        of which at the CL points (geometric errors, uncompensated): max {:.4f} mm, rms {:.4f} mm\n",
                     a.uncompensated_tip_max_mm, a.uncompensated_tip_rms_mm);
  t += fmt::format("after  (the written program re-executed, {} blocks): largest contour error {:.4f} mm (CL line {}), "
                   "orientation {:.4f} deg, block ends {:.4f} mm\n",
                   a.after.blocks, a.after.max_contour_mm, a.after.worst_line,
                   rad_to_deg(a.after.max_orientation_rad), a.after.max_endpoint_mm);
  return t;
}

std::string render_post_html(const PostAccount& a) {
  using preview::svg::escape;
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>ncpost post report</title>\n";
  h += "<style>body{font-family:sans-serif;margin:24px;color:#222;max-width:1060px}h1{font-size:22px}"
       "h2{font-size:17px;margin-top:28px}table{border-collapse:collapse;font-size:13px}"
       "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f0f0f0;text-align:left}"
       ".note{color:#555;font-size:13px}</style></head><body>\n";
  h += "<h1>ncpost post: error before and after</h1>\n<table>\n";
  auto row = [&](const std::string& k, const std::string& v) { h += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", k, v); };
  row("input", escape(a.input_name));
  row("machine", escape(a.machine_name));
  row("error model", a.model_name.empty() ? "none (nominal machine)" : escape(a.model_name));
  row("nonlinear-error tolerance",
      a.tolerance_mm > 0 ? fmt::format("{} mm ({})", a.tolerance_mm, escape(a.method_name)) : std::string("none"));
  row("dialect", escape(a.dialect_name));
  row("both programs executed on", escape(a.executed_on));
  row("CL motions &rarr; NC blocks", fmt::format("{} &rarr; {}", a.motions_in, a.blocks_out));
  row("before: largest contour error", fmt::format("{:.4f} mm (CL line {})", a.before_max_mm, a.before_worst_line));
  row("before: mean contour error", fmt::format("{:.4f} mm", a.before_mean_mm));
  if (a.uncompensated_tip_max_mm >= 0.0)
    row("before: tip error at the CL points (max / rms)",
        fmt::format("{:.4f} / {:.4f} mm", a.uncompensated_tip_max_mm, a.uncompensated_tip_rms_mm));
  row("after: largest contour error", fmt::format("{:.4f} mm (CL line {})", a.after.max_contour_mm, a.after.worst_line));
  row("after: largest orientation error", fmt::format("{:.4f}&deg;", rad_to_deg(a.after.max_orientation_rad)));
  row("after: largest block-end error", fmt::format("{:.4f} mm", a.after.max_endpoint_mm));
  h += "</table>\n<p class=\"note\">Contour error: distance of the executed tool tip from the straight CL segment of "
       "its block, in the workpiece frame. Before: the program with one block per CL motion and nominal commands; "
       "after: the written program (rounded words), both executed on the same machine.</p>\n";
  preview::svg::Series before{"before", "#c0392b", a.before_series.xs(), a.before_series.ys(), false};
  preview::svg::Series after{"after", "#1f5fa8", a.after_series.xs(), a.after_series.ys(), false};
  preview::svg::ChartFrame f;
  f.title = "Largest contour error along the program";
  f.x_label = "CL line";
  f.y_label = "error (mm)";
  h += "<h2>Along the program</h2>\n" + preview::svg::line_chart(f, {before, after});
  f.title = "After only";
  h += preview::svg::line_chart(f, {after});
  if (!a.notices.empty()) {
    h += "<h2>Notices</h2>\n<ul>\n";
    for (std::size_t i = 0; i < a.notices.size() && i < 200; ++i) h += "<li>" + escape(a.notices[i]) + "</li>\n";
    if (a.notices.size() > 200) h += fmt::format("<li>… {} more</li>\n", a.notices.size() - 200);
    h += "</ul>\n";
  }
  return h + "</body></html>\n";
}

}  // namespace ncpost
