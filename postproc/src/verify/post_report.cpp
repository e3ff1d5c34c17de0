// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/post_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "ncpost/kinematics/pose.hpp"
#include "ncpost/postproc/verify/preview_svg.hpp"
#include "ncpost/report/colour_scale.hpp"
#include "ncpost/report/html_page.hpp"
#include "ncpost/report/path_view_3d.hpp"
#include "verify/pairwise_merge.hpp"

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
  detail::merge_pairs(buckets_, [](Bucket& b, const Bucket& next) {
    b.x1 = next.x1;
    b.y = std::max(b.y, next.y);
    b.n += next.n;
  });
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

void PathErrors::add_after(int line, double e) {
  if (!after_.empty() && after_.back().line_last >= line && after_.back().line_first <= line) {
    after_.back().value_mm = std::max(after_.back().value_mm, e);
    return;
  }
  after_.push_back({line, line, e});
  if (after_.size() > 2 * max_points_) {  // merge neighbours: line ranges grow, the largest error stays
    detail::merge_pairs(after_, [](Span& m, const Span& next) {
      m.line_first = std::min(m.line_first, next.line_first);
      m.line_last = std::max(m.line_last, next.line_last);
      m.value_mm = std::max(m.value_mm, next.value_mm);
    });
  }
}

void PathErrors::add_before(int line, const Vec3d& tip, double e) {
  before_.push_back({tip, line, line, e, -1.0});
  if (before_.size() > max_points_) {
    detail::merge_pairs(before_, [](Point& first, const Point& next) {  // the later point stays
      Point m = next;
      m.line_first = std::min(first.line_first, m.line_first);
      m.line_last = std::max(first.line_last, m.line_last);
      m.before_mm = std::max(first.before_mm, m.before_mm);
      first = m;
    });
  }
}

std::vector<PathErrors::Point> PathErrors::points() const {
  std::vector<Point> out = before_;
  // the after spans are in program order, the lines rising: the first span that ends at or after
  // a point's first line, and its successors while they start within the point's lines
  for (Point& p : out) {
    auto it = std::lower_bound(after_.begin(), after_.end(), p.line_first,
                               [](const Span& s, int line) { return s.line_last < line; });
    for (; it != after_.end() && it->line_first <= p.line_last; ++it) p.after_mm = std::max(p.after_mm, it->value_mm);
  }
  return out;
}

std::string account_text(const PostAccount& a) {
  std::string t;
  t += fmt::format(
      "before (one block per CL motion, nominal commands, on {}): largest contour error {:.4f} mm "
      "(CL line {}), mean {:.4f} mm over {} blocks\n",
      a.executed_on, a.before_max_mm, a.before_worst_line, a.before_mean_mm, a.before_blocks);
  if (a.uncompensated_tip_max_mm >= 0.0)
    t += fmt::format(
        "        of which at the CL points (geometric errors, uncompensated): max {:.4f} mm, rms {:.4f} mm\n",
        a.uncompensated_tip_max_mm, a.uncompensated_tip_rms_mm);
  t += fmt::format(
      "after  (the written program re-executed, {} blocks): largest contour error {:.4f} mm (CL line {}), "
      "orientation {:.4f} deg, block ends {:.4f} mm\n",
      a.after.blocks, a.after.max_contour_mm, a.after.worst_line, rad_to_deg(a.after.max_orientation_rad),
      a.after.max_endpoint_mm);
  return t;
}

namespace {

std::string path_3d(const PostAccount& a) {
  const std::vector<PathErrors::Point> pts = a.path.points();
  if (pts.size() < 2) return "<p class=\"note\">No path to show (nothing re-executed).</p>\n";
  report::PathView3d before{"path-before", "before: one block per CL motion, nominal commands", {}, {}};
  report::PathView3d after{"path-after", "after: the written program re-executed", {}, {}};
  double largest = 0.0;
  for (const auto& p : pts) {
    const report::PathPoint3 q{p.tip_mm.x(), p.tip_mm.y(), p.tip_mm.z()};
    before.points.push_back(q);
    before.values.push_back(1e3 * p.before_mm);
    after.points.push_back(q);
    after.values.push_back(p.after_mm >= 0 ? 1e3 * p.after_mm : 0.0);
    largest = std::max({largest, 1e3 * p.before_mm, p.after_mm >= 0 ? 1e3 * p.after_mm : 0.0});
  }
  report::PathView3d after_own = after;
  after_own.id = "path-after-own";
  after_own.title = "after, on its own scale";
  double after_largest = 0.0;
  for (double v : after.values) after_largest = std::max(after_largest, v);
  return "<p class=\"note\">Both programs on one colour scale:</p>\n" +
         report::path_view_3d({before, after}, report::colour_scale_for(largest, "µm"), "contour error") +
         "<p class=\"note\">The written program on its own colour scale (magnified):</p>\n" +
         report::path_view_3d({after_own}, report::colour_scale_for(after_largest, "µm"), "contour error, after");
}

}  // namespace

std::string render_post_html(const PostAccount& a) {
  using report::escape;
  report::Provenance p;
  p.title = "ncpost post: contour error before and after";
  p.machine = a.machine_name;
  p.model = a.model_name;
  p.inputs = a.inputs;
  std::string h = report::page_start(p);
  h += "<h2>Figures</h2><table>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    h += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", k, v);
  };
  row("nonlinear-error tolerance", a.tolerance_mm > 0
                                       ? fmt::format("{:g} µm ({})", a.tolerance_mm * 1e3, escape(a.method_name))
                                       : std::string("none"));
  row("dialect", escape(a.dialect_name));
  row("both programs executed on", escape(a.executed_on));
  row("CL motions &rarr; NC blocks", fmt::format("{} &rarr; {}", a.motions_in, a.blocks_out));
  row("before: largest contour error",
      fmt::format("{:.2f} µm (CL line {})", 1e3 * a.before_max_mm, a.before_worst_line));
  row("before: mean contour error", fmt::format("{:.2f} µm", 1e3 * a.before_mean_mm));
  if (a.uncompensated_tip_max_mm >= 0.0)
    row("before: tip error at the CL points (max / rms)",
        fmt::format("{:.2f} / {:.2f} µm", 1e3 * a.uncompensated_tip_max_mm, 1e3 * a.uncompensated_tip_rms_mm));
  row("after: largest contour error",
      fmt::format("{:.2f} µm (CL line {})", 1e3 * a.after.max_contour_mm, a.after.worst_line));
  row("after: largest orientation error", fmt::format("{:.1f} µrad", 1e6 * a.after.max_orientation_rad));
  row("after: largest block-end error", fmt::format("{:.2f} µm", 1e3 * a.after.max_endpoint_mm));
  h += "</table>\n<p class=\"note\">Contour error: distance of the executed tool tip from the straight CL segment of "
       "its block, in the workpiece frame. Before: the program with one block per CL motion and nominal commands; "
       "after: the written program (rounded words), both executed on the same machine.</p>\n";
  h += "<h2 id=\"path3d\">Tool path in 3D</h2>\n" + path_3d(a);
  auto um = [](std::vector<double> v) {
    for (double& x : v) x *= 1e3;
    return v;
  };
  preview::svg::Series before{"before", "#c0392b", a.before_series.xs(), um(a.before_series.ys()), false};
  preview::svg::Series after{"after", "#1f5fa8", a.after_series.xs(), um(a.after_series.ys()), false};
  preview::svg::ChartFrame f;
  f.title = "Largest contour error along the program";
  f.x_label = "CL line";
  f.y_label = "error (µm)";
  h += "<h2>Along the program</h2>\n" + preview::svg::line_chart(f, {before, after});
  f.title = "After only";
  h += preview::svg::line_chart(f, {after});
  if (!a.notices.empty()) {
    h += "<h2>Notices</h2>\n<ul>\n";
    for (std::size_t i = 0; i < a.notices.size() && i < 200; ++i) h += "<li>" + escape(a.notices[i]) + "</li>\n";
    if (a.notices.size() > 200) h += fmt::format("<li>… {} more</li>\n", a.notices.size() - 200);
    h += "</ul>\n";
  }
  return h + report::page_end();
}

}  // namespace ncpost
