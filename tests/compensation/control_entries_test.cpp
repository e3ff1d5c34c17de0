// SPDX-License-Identifier: Apache-2.0
// Issue 17, "the compensation values as they will be entered in the control": identify.html (and
// the laser report) show the model in the chosen control's own entries (`identify --control`), and
// those are the very lines `ncpost export --format` writes: for a one-parameter model of each
// format, every value line of the exported file is in the report, with the documented sign.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cli_run.hpp"
#include "ncpost/compensation/control_entries.hpp"
#include "ncpost/compensation/export_isg.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/export_machine.hpp"
#include "ncpost/compensation/export_siemens.hpp"
#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/report/html_page.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

/// The report of an identification that found `p` (no data: the sections of the model only).
std::string report_of(const Machine& m, const ErrorParameters& p, std::optional<ControlFormat> control) {
  IdentifyResult r;
  r.parameters = p;
  r.message = "given";
  IdentifyReportInputs in;
  in.control = control;
  return html_report(m, {}, r, in);
}

/// The lines of an exported file the control reads: not empty, not a comment (#, ;).
std::vector<std::string> value_lines(const std::string& file) {
  std::vector<std::string> lines;
  std::istringstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && line[0] != ';' && line != "%_N_AX_EEC_INI" && line != "CHANDATA(1)" &&
        line != "M17")
      lines.push_back(line);
  return lines;
}

/// Every value line of the file in the report's entries, in the file's order.
void check_in_report(const std::string& html, const std::vector<std::string>& lines) {
  REQUIRE(!lines.empty());
  std::size_t at = html.find("id=\"control-entries\"");
  REQUIRE(at != std::string::npos);
  for (const std::string& line : lines) {
    INFO(line);
    const std::size_t found = html.find(report::escape(line) + "\n", at);  // as the browser shows it: the line
    CHECK(found != std::string::npos);
    if (found != std::string::npos) at = found;
  }
}

}  // namespace

TEST_CASE("control entries: EXX:p1 = 100 µm/m in the report as the linuxcnc, siemens and isg files have it",
          "[report][export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  ErrorParameters p;
  p.set("EXX:p1", 1e-4);  // X goes 30 µm too far at X = 300
  const MachineModel model(m, p);
  const ExportSource source{"model.json", "vmcl600.toml", "test"};
  SECTION("linuxcnc (the default without a rotary axis): trim = minus the error") {
    const std::string html = report_of(m, p, std::nullopt);
    CHECK(html.find("As entered in the control: LinuxCNC COMP_FILE rows") != std::string::npos);
    const std::string file = format_linuxcnc_comp(linuxcnc_comp_table(model, 'X'), model, source);
    std::vector<std::string> rows;
    for (const std::string& l : value_lines(file)) rows.push_back(l);
    check_in_report(html, rows);
    CHECK(html.find("300.000000 -0.0299970 -0.0299970\n") != std::string::npos);  // (300+t)(1+1e-4) = 300
    // Y and Z have nothing: said so
    CHECK(html.find("axis Y: the model has no positioning error (EYY)") != std::string::npos);
  }
  SECTION("siemens: the value is the error itself") {
    const std::string html = report_of(m, p, ControlFormat::siemens);
    check_in_report(html, value_lines(format_siemens_lec(siemens_lec_table(model, 'X'), model, source)));
    CHECK(html.find("$AA_ENC_COMP_MIN[0,X1]=-300.000000000\n") != std::string::npos);
  }
  SECTION("isg: pos and neg are the error in 0.1 µm") {
    const std::string html = report_of(m, p, ControlFormat::isg);
    const IsgLsecTable table = isg_lsec_table(model, 'X');
    check_in_report(html, value_lines(format_isg_lsec(table, model, source)));
    const std::size_t last = table.setpoints.size() - 1;
    CHECK(html.find(fmt::format("kw.ssfk.table[{}].setpoint 3000000\n", last)) != std::string::npos);
    CHECK(html.find(fmt::format("kw.ssfk.table[{}].pos 300\n", last)) != std::string::npos);
    CHECK(html.find("kw.ssfk.table[0].pos -300\n") != std::string::npos);
  }
}

TEST_CASE("control entries: EY0C = 20 µm in the report as the corrected machine file has it (the default)",
          "[report][export]") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  ErrorParameters p;
  p.set("EY0C", 0.020);
  const MachineModel model(m, p);
  const std::string html = report_of(m, p, std::nullopt);  // a rotary axis: the machine file's lines
  CHECK(html.find("As entered in the control: kinematics corrections") != std::string::npos);
  const MachineExport corrected = corrected_machine(model);
  const std::string file = format_machine_toml(corrected.corrected, {});
  const std::string c = file.substr(file.find("[axes.C]"));
  std::vector<std::string> lines;
  std::istringstream in(c);
  for (std::string line; std::getline(in, line) && !line.empty();) lines.push_back(line);
  check_in_report(html, lines);
  // the C axis line moved by +20 µm in Y (the nominal pivot of C is the origin)
  CHECK(std::count(lines.begin(), lines.end(), "pivot = [0, 0.02, 0]") == 1);
  // a one-axis table cannot hold it: said so, pointing to the machine file
  const std::string isg = report_of(m, p, ControlFormat::isg);
  CHECK(isg.find("location errors EY0C: a one-axis table cannot move an axis line") != std::string::npos);
}

TEST_CASE("identify --control: the reports hold what ncpost export writes from the model file",
          "[report][export][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ncpost_control_entries_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  // laser data of the VMCL600, ISG lists of X Y Z
  const std::string vmc = " --machine " + test::source("machines/vmcl600.toml");
  std::string laser;
  for (const auto& e : fs::directory_iterator(test::source("samples/measurements/vmcl600/data")))
    laser += " " + e.path().string();
  REQUIRE(
      test::run_ncpost("identify --control isg" + vmc + " --report " + d + "laser.html -o " + d + "laser.json" + laser,
                       d + "log") == 0);
  const std::string laser_html = test::read_text_file(d + "laser.html");
  for (const char* axis : {"X", "Y", "Z"}) {
    INFO("axis " << axis);
    REQUIRE(test::run_ncpost(
                std::string("export --format isg --axis ") + axis + vmc + " -o " + d + "a.lis " + d + "laser.json",
                d + "log") == 0);
    check_in_report(laser_html, value_lines(test::read_text_file(d + "a.lis")));
  }
  // ballbar and sphere data of a five-axis machine, default entries: the corrected machine file
  const std::string s = test::data("scenarios/public-clean/");
  REQUIRE(test::run_ncpost("identify --machine " + s + "machine.toml -o " + d + "m.json --report " + d + "r.html " + s +
                               "ballbar_h250.csv " + s + "ballbar_h300.csv " + s + "sphere.csv",
                           d + "log") == 0);
  REQUIRE(test::run_ncpost("export --format machine --machine " + s + "machine.toml -o " + d + "m.toml " + d + "m.json",
                           d + "log") == 0);
  // the sections of the rotary axes, as the file has them
  std::vector<std::string> rotary, section;
  std::istringstream in(test::read_text_file(d + "m.toml") + "\n");
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') {
      section.push_back(line);
      continue;
    }
    if (std::find(section.begin(), section.end(), "type = \"rotary\"") != section.end())
      rotary.insert(rotary.end(), section.begin(), section.end());
    section.clear();
  }
  CHECK(rotary.size() == 9);  // [axes.A] type direction pivot limits, [axes.C] type direction pivot
  check_in_report(test::read_text_file(d + "r.html"), rotary);
  CHECK(test::run_ncpost(
            "identify --control heidenhain --machine " + s + "machine.toml -o " + d + "m2.json " + s + "sphere.csv",
            d + "log") == 1);
  fs::remove_all(dir);
}
