// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/trr_sensitivity_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "ncpost/postproc/verify/preview_svg.hpp"
#include "ncpost/report/colour_scale.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::trr {
namespace {

/// v rounded to `decimals` decimals (printed as the shortest decimal that reads back).
double rounded(double v, int decimals) {
  const double p = std::pow(10.0, decimals);
  return std::round(v * p) / p;
}

using report::diverging_colour;

int point_index(const SensitivityOptions& o, int ring, int sector) {
  const int sectors = static_cast<int>(std::lround(360.0 / o.azimuth_step_deg));
  return ring == 0 ? 0 : 1 + (ring - 1) * sectors + sector;
}

std::string map_svg(const SensitivityResult& r, const SensitivityOptions& o, const ParameterMap& m) {
  constexpr double R = 110.0, cx = 130.0, cy = 125.0;
  const int rings = static_cast<int>(std::lround(o.max_polar_deg / o.polar_step_deg));
  const int sectors = static_cast<int>(std::lround(360.0 / o.azimuth_step_deg));
  // display cells of about 2° polar × 8° azimuth, each coloured by the sample at its centre
  const int ring_stride = std::max(1, static_cast<int>(std::lround(2.0 / o.polar_step_deg)));
  const int sector_stride = std::max(1, static_cast<int>(std::lround(8.0 / o.azimuth_step_deg)));
  // each map on its own symmetric scale; a map without effect (rounding noise only) is drawn as zero
  const double largest = std::max(std::abs(m.max_um), std::abs(m.min_um));
  const bool no_effect = !(largest >= report::kNoEffectUm);
  const double scale = no_effect ? 1.0 : largest;
  std::string s = fmt::format("<svg width='260' height='265' viewBox='0 0 260 265'>");
  const auto xy = [&](double polar_deg, double az) {
    const double rho = R * polar_deg / o.max_polar_deg;
    return std::pair{cx + rho * std::cos(az), cy - rho * std::sin(az)};
  };
  for (int i = 0; i <= rings; i += ring_stride) {
    const double p0 = std::max(0.0, (i - 0.5 * ring_stride) * o.polar_step_deg);
    const double p1 = std::min(o.max_polar_deg, (i + 0.5 * ring_stride) * o.polar_step_deg);
    if (i == 0) {
      const double v = r.maps.empty() ? 0 : m.deviation_um[0];
      s += fmt::format("<circle cx='{:.1f}' cy='{:.1f}' r='{:.1f}' fill='{}'/>", cx, cy, R * p1 / o.max_polar_deg,
                       diverging_colour(v / scale));
      continue;
    }
    for (int j = 0; j < sectors; j += sector_stride) {
      const double a0 = deg_to_rad((j - 0.5 * sector_stride) * o.azimuth_step_deg);
      const double a1 = deg_to_rad((j + 0.5 * sector_stride) * o.azimuth_step_deg);
      const double v = m.deviation_um[static_cast<std::size_t>(point_index(o, i, j))];
      const auto [x0, y0] = xy(p0, a0);
      const auto [x1, y1] = xy(p1, a0);
      const auto [x2, y2] = xy(p1, a1);
      const auto [x3, y3] = xy(p0, a1);
      s += fmt::format("<path d='M{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}Z' fill='{}'/>", x0, y0, x1,
                       y1, x2, y2, x3, y3, diverging_colour(v / scale));
    }
  }
  s += fmt::format("<circle cx='{:.1f}' cy='{:.1f}' r='{:.1f}' fill='none' stroke='#444'/>", cx, cy, R);
  for (int c = 0; c < 3; ++c) {  // screw lines of chains a, b, c
    const auto [x, y] = xy(o.max_polar_deg * 1.08, deg_to_rad(120.0 * c));
    s += fmt::format(
        "<text x='{:.1f}' y='{:.1f}' font-size='12' text-anchor='middle' dominant-baseline='middle'>{}</text>", x, y,
        "abc"[c]);
  }
  const auto mark = [&](int idx, const char* label) {
    const SurfacePoint& p = r.points[static_cast<std::size_t>(idx)];
    const auto [x, y] = xy(rad_to_deg(p.polar_rad), p.azimuth_rad);
    s += fmt::format(
        "<text x='{:.1f}' y='{:.1f}' font-size='11' text-anchor='middle' dominant-baseline='middle'>{}</text>", x, y,
        label);
  };
  if (!no_effect) {
    mark(m.max_at, "+");
    mark(m.min_at, "&#8722;");
  }
  s +=
      fmt::format("<text x='130' y='258' font-size='11' text-anchor='middle'>max {:.3f} µm, min {:.3f} µm</text></svg>",
                  m.max_um, m.min_um);
  return s + "<br>" + report::diverging_bar_svg(largest, "µm", 260, no_effect);
}

}  // namespace

std::string sensitivity_json(const SensitivityResult& r, const SensitivityOptions& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < r.maps.size(); ++k) {
    const ParameterMap& m = r.maps[k];
    const bool angle = Errors::is_angle(static_cast<int>(k));
    const SurfacePoint& pmax = r.points[static_cast<std::size_t>(m.max_at)];
    const SurfacePoint& pmin = r.points[static_cast<std::size_t>(m.min_at)];
    j[m.name] = {{"max_um", rounded(m.max_um, 6)},
                 {"min_um", rounded(m.min_um, 6)},
                 {"range_um", rounded(m.range_um(), 6)},
                 {"step", angle ? o.angle_step_deg : o.length_step_mm},
                 {"unit", angle ? "deg" : "mm"},
                 {"max_at_deg", {rounded(rad_to_deg(pmax.polar_rad), 6), rounded(rad_to_deg(pmax.azimuth_rad), 6)}},
                 {"min_at_deg", {rounded(rad_to_deg(pmin.polar_rad), 6), rounded(rad_to_deg(pmin.azimuth_rad), 6)}}};
  }
  return j.dump(1) + "\n";
}

std::string sensitivity_table(const SensitivityResult& r) {
  std::string s = fmt::format("{:<6} {:>10} {:>10} {:>10} {:>10}\n", "param", "step", "max_um", "min_um", "range_um");
  for (std::size_t k = 0; k < r.maps.size(); ++k) {
    const ParameterMap& m = r.maps[k];
    const bool angle = Errors::is_angle(static_cast<int>(k));
    s += fmt::format("{:<6} {:>10} {:>10.3f} {:>10.3f} {:>10.3f}\n", m.name, angle ? "0.01 deg" : "0.01 mm", m.max_um,
                     m.min_um, m.range_um());
  }
  // largest |deviation| by kind, over the three chains
  const char* kinds[] = {"dr", "dt", "ar", "at", "ds", "gp", "dl", "drs", "dts", "dzs"};
  s += "\nlargest |deviation| per kind (chains a / b / c, µm):\n";
  for (int f = 0; f < kPerChain; ++f) {
    s += fmt::format("  {:<4}", kinds[f]);
    for (int c = 0; c < 3; ++c) {
      const ParameterMap& m = r.maps[static_cast<std::size_t>(c * kPerChain + f)];
      s += fmt::format(" {:>9.3f}", std::max(std::abs(m.max_um), std::abs(m.min_um)));
    }
    s += "\n";
  }
  return s;
}

std::string sensitivity_html(const SensitivityResult& r, const SensitivityOptions& o, const std::string& machine_name,
                             const std::string& machine_file) {
  report::Provenance p;
  p.title = "Sensitivity maps — " + machine_name;
  p.machine = machine_name;
  p.model = "one error parameter at a time (no model file)";
  if (!machine_file.empty()) p.inputs.push_back({"machine file", machine_file});
  std::string s = report::page_start(p);
  s += "<style>.maps{display:flex;flex-wrap:wrap}.map{margin:4px;text-align:center}</style>";
  s += fmt::format(
      "<p>Hemisphere of radius {} mm (centre = workpiece origin at {:.1f}, {:.1f}, {:.1f} mm in M), tool "
      "normal to the surface, polar angle 0–{}°; {} CL points. One error parameter at a time ({} mm, or {}° for "
      "ar, at, gp); deviation of the executed tool tip from the CL point along the surface normal "
      "(positive: material left). Maps seen from above (+X right, +Y up), colour scaled to each map's largest "
      "|deviation| (red positive, blue negative; a map whose largest |deviation| is below 0.001 µm has no effect and "
      "is drawn white); "
      "a, b, c mark the screw lines, + and − the extremes.</p>",
      o.sphere_radius_mm, o.workpiece_origin_mm.x(), o.workpiece_origin_mm.y(), o.workpiece_origin_mm.z(),
      o.max_polar_deg, r.points.size(), o.length_step_mm, o.angle_step_deg);
  s += "<table><tr><th>parameter</th><th>step</th><th>max µm</th><th>min µm</th><th>range µm</th></tr>";
  for (std::size_t k = 0; k < r.maps.size(); ++k) {
    const ParameterMap& m = r.maps[k];
    s += fmt::format("<tr><td>{}</td><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>", m.name,
                     Errors::is_angle(static_cast<int>(k)) ? "0.01°" : "0.01 mm", m.max_um, m.min_um, m.range_um());
  }
  s += "</table>";
  for (int c = 0; c < 3; ++c) {
    s += fmt::format("<h2>Chain {}</h2><div class='maps'>", "abc"[c]);
    for (int f = 0; f < kPerChain; ++f) {
      const ParameterMap& m = r.maps[static_cast<std::size_t>(c * kPerChain + f)];
      s += fmt::format("<div class='map'><b>{}</b><br>{}</div>", m.name, map_svg(r, o, m));
    }
    s += "</div>";
  }
  return s + report::page_end();
}

}  // namespace ncpost::trr
