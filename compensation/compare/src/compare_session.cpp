// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/compare_session.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "identify_report_sections.hpp"
#include "ncpost/compensation/laser_iso230_2.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/formatters.hpp"

namespace ncpost::comp {
namespace {

/// The axes whose command changes over the set, in the machine's order ("XYC").
std::string axes_moved(const Machine& m, const MeasurementSet& s) {
  std::string moved;
  for (std::size_t j = 0; j < m.axes.size(); ++j) {
    double lo = 1e300, hi = -1e300;
    for (const MeasurementRow& r : s.rows) lo = std::min(lo, r.command[j]), hi = std::max(hi, r.command[j]);
    if (hi - lo > 1e-6) moved += m.axes[j].letter;
  }
  return moved;
}

void add_circular(Session& out, const std::string& name, const report::CircularityFigures& f,
                  const UncertaintyBudget& b) {
  if (f.ok) out.figures.push_back({name, "G", "µm", f.G_um, b});
}

Session ballbar_session(const Machine& m, const MeasurementSet& s) {
  Session out{s.file, s.conditions.date, "", {}};
  out.test = fmt::format("ballbar: bar {:.3f} mm, table ball ({:.3f}) mm, tool ball ({:.3f}) mm, axes moved {}",
                         s.bar_length_mm, s.table_ball_mm, s.tool_ball_mm, axes_moved(m, s));
  const sections::BallbarFigures f = sections::ballbar_figures(m, s);
  if (!f.both.ok)
    throw InputError({s.file, 0, 0},
                     "no ISO 230-4 figures: " + (f.both.message.empty() ? "fewer than 8 rows" : f.both.message));
  const UncertaintyBudget budget = circularity_budget(s, {});
  add_circular(out, "G", f.both, budget);
  if (f.both.direction == 0) {  // both directions in the file: each direction's G and the hysteresis
    add_circular(out, "G ccw", f.ccw, budget);
    add_circular(out, "G cw", f.cw, budget);
    if (f.both.H_um >= 0) out.figures.push_back({"H", "", "µm", f.both.H_um, budget});
  }
  return out;
}

Session laser_session(const MeasurementSet& s) {
  const Iso230Figures g = iso230_2_figures(s);
  if (!g.ok)
    throw InputError({s.file, 0, 0}, "no ISO 230-2 figures (" + g.message +
                                         "): compare takes bidirectional positioning lines, ballbar files or models");
  Session out{s.file, s.conditions.date, "", {}};
  const int moving = g.axis - 'X';
  std::string line;  // where the other two axes stood at the first row (with `# line:` every row agrees)
  for (int j = 0; j < 3; ++j)
    if (j != moving)
      line += fmt::format("{}{} {:.3f}", line.empty() ? "" : ", ", char('X' + j), s.rows.front().command[j]);
  out.test = fmt::format(
      "laser positioning of {}: line at {} mm, tool point ({:.3f}) mm, {} targets {:.3f} … {:.3f} mm", g.axis, line,
      s.tool_point_mm, g.targets.size(), g.targets.front().target_mm, g.targets.back().target_mm);
  const std::pair<char, double> figures[] = {{'A', g.accuracy_A_um},
                                             {'B', g.reversal_B_um},
                                             {'E', g.systematic_E_um},
                                             {'M', g.mean_bidirectional_M_um},
                                             {'R', g.repeatability_R_um}};
  for (const auto& [kind, value] : figures)
    out.figures.push_back({std::string(1, kind), std::string(1, kind), "µm", value, iso230_2_budget(s, g, kind)});
  return out;
}

}  // namespace

Session session_from_set(const Machine& m, const MeasurementSet& s) {
  if (!s.has_values) throw InputError({s.file, 0, 0}, "a plan without values: nothing measured to compare");
  if (s.type == MeasurementType::ballbar) return ballbar_session(m, s);
  if (s.type == MeasurementType::laser) return laser_session(s);
  throw InputError({s.file, 0, 0},
                   "sphere probing has no ISO figure to compare; compare the models identified from it "
                   "(MODEL.json) instead");
}

Session session_from_model(const Machine& m, const ModelFile& model, const std::string& file) {
  Session out{file, "", fmt::format("identification of '{}'", model.machine.empty() ? m.name : model.machine), {}};
  for (std::size_t i = 0; i < model.parameters.size(); ++i) {
    const std::string& name = model.parameters.names()[i];
    const ParseResult parsed = parse_parameter_name(name, m);
    const bool angle = parsed.spec && parsed.spec->is_angle();
    const double scale = angle ? 1e6 : 1e3;
    SessionFigure f{name, "", angle ? "µrad" : "µm", model.parameters.values()[i] * scale, std::nullopt};
    if (const auto u = model.uncertainty.get(name))
      f.budget = UncertaintyBudget{{{"fit", *u * scale, "the fit's standard uncertainty", true}}};
    out.figures.push_back(f);
  }
  if (model.fit) {
    out.figures.push_back({"rms from nominal", "", "µm", model.fit->rms_nominal_um, std::nullopt});
    out.figures.push_back({"max from nominal", "", "µm", model.fit->max_nominal_um, std::nullopt});
  }
  return out;
}

}  // namespace ncpost::comp
