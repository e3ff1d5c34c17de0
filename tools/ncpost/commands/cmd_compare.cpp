// SPDX-License-Identifier: Apache-2.0
// ncpost compare: the same test before and after compensation, and over several dated sessions
// (issue 25 item 5; docs/cli.md "compare"). Each SESSION is one data file (ballbar, laser
// positioning line) or one identified model (*.json); all of one form and of one test.
#include <fmt/format.h>

#include <memory>

#include "commands.hpp"
#include "file_checks.hpp"
#include "tolerance_option.hpp"
#include "ncpost/compensation/compare_report.hpp"
#include "ncpost/compensation/measurement_files.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"

namespace ncpost::cli {

namespace {

struct CompareArgs {
  std::string machine, tolerance, html;
  std::vector<std::string> sessions;
};

bool is_model(const std::string& path) { return path.size() > 5 && path.substr(path.size() - 5) == ".json"; }

std::vector<comp::Session> read_sessions(const Machine& m, const std::vector<std::string>& paths) {
  std::vector<comp::Session> out;
  const bool models = is_model(paths.front());
  for (const std::string& p : paths)
    if (is_model(p) != models)
      throw UsageError(fmt::format("'{}': the sessions are all models (*.json) or all data files, not both", p));
  if (models) {
    for (const std::string& p : paths) out.push_back(comp::session_from_model(m, comp::read_model_json(p, &m), p));
    return out;
  }
  for (const comp::MeasurementSet& s : comp::read_measurement_files(paths, m))
    out.push_back(comp::session_from_set(m, s));
  return out;
}

int run_compare(const CompareArgs& a) {
  std::vector<NamedPath> inputs{{"--machine", a.machine}};
  for (const std::string& s : a.sessions) inputs.push_back({"SESSION", s});
  check_files({{"--html", a.html}}, inputs);
  const Machine m = load_machine(a.machine);
  const comp::Tolerances tolerances = tolerances_from(a.tolerance, a.machine);
  const comp::Comparison c = comp::compare_sessions(read_sessions(m, a.sessions), tolerances);
  fmt::print("{}", comp::compare_text(c));
  if (!a.html.empty()) write_file_atomically(a.html, comp::compare_html(c, m.name, a.machine));
  return 0;
}

}  // namespace

void add_compare(CLI::App& app, Action& action) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* sub =
      app.add_subcommand("compare", "Compare the same test before and after compensation, or over dated sessions");
  sub->add_option("--machine", a->machine, "machine definition (TOML)")->required();
  sub->add_option("--tolerance", a->tolerance,
                  "tolerances per figure kind for the ISO 14253-1 verdicts, KIND=µm comma-separated (A B E M R G); "
                  "over the machine file's [tolerances]");
  sub->add_option("--html", a->html, "write the comparison with its trend plots as a self-contained HTML page");
  sub->add_option("sessions", a->sessions,
                  "BEFORE AFTER [MORE...]: data files (ballbar, laser positioning) or models "
                  "(*.json), in the order they were measured")
      ->required()
      ->expected(2, -1);
  sub->footer("Example: ncpost compare --machine machines/ac-trunnion.toml --html cmp.html before.csv after.csv");
  sub->callback([&action, a] { action = [a] { return run_compare(*a); }; });
}

}  // namespace ncpost::cli
