// SPDX-License-Identifier: Apache-2.0
// Every command on the TRR-XY machine through the one per-kind dispatch (tools/ncpost/commands/machine_kind.hpp,
// kind_steps.hpp; issue 16 item 2): preview through the common preview (its CSV, summary and HTML),
// plan/simulate/identify through the common writers and messages, the options this machine has not
// refused (exit 1, nothing written), and --nonlinear harmonic measured by re-executing the program.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "cli_run.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;

namespace {

const Vec3d kOrigin(0.0, 0.0, -300.0);

/// `ncpost ARGS`: the exit code; `out` (if given) gets what it printed on stdout and stderr.
int run(const std::string& args, std::string* out = nullptr) {
  const int rc = test::run_ncpost(args, "trr_commands.log");
  if (out) *out = test::read_text_file("trr_commands.log");
  return rc;
}

std::string machine_path() { return test::trr_machine_path(); }
std::string sample_path() { return test::hemisphere_sample_path(); }
std::string job() { return "--machine " + machine_path() + " --workpiece-origin 0,0,-300 "; }

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');) out.push_back(f);
  return out;
}

/// The figure `what` (mm) of the post's account line starting with `line_start`.
double account_figure(const std::string& text, const std::string& line_start) {
  const std::regex re(line_start + "[^\n]*largest contour error ([0-9.]+) mm");
  std::smatch m;
  REQUIRE(std::regex_search(text, m, re));
  return std::stod(m[1].str());
}

}  // namespace

TEST_CASE("TRR-XY preview through the common preview: the CSV, the summary and the report of every machine") {
  std::string out;
  REQUIRE(run("preview " + job() + "--csv tc_preview.csv --html tc_preview.html " + sample_path(), &out) == 0);
  // reviewed: the hemisphere bows most at its rim (last block), as `post --verify` measures it ("before")
  CHECK(out.find("435 CL motions, 433 blocks previewed; largest nonlinear error 0.2710 mm (block 433, CL line 442), "
                 "mean 0.0808 mm, largest orientation error 0.0268 deg; blocks over 5 µm: 416") != std::string::npos);
  const std::vector<std::string> csv = lines_of("tc_preview.csv");
  REQUIRE(csv.size() == 434);
  CHECK(csv[0] ==
        "block,line,max_error_mm,at_t,harmonic_mm,orientation_error_deg,orientation_at_t,harmonic_residual_mm");
  const std::vector<std::string> last = fields(csv.back());
  REQUIRE(last.size() == 8);
  CHECK(last[0] == "433");
  CHECK(last[1] == "442");
  CHECK(std::stod(last[2]) == Approx(0.270964).margin(2e-6));
  CHECK(std::stod(last[3]) == Approx(0.5).margin(0.002));      // a half sine: the peak mid-block
  CHECK(std::stod(last[4]) == Approx(0.270964).margin(2e-6));  // the midpoint fit is the peak here
  CHECK(std::stod(last[5]) == Approx(0.0268).margin(1e-4));
  // the common HTML report, naming this machine, with the worst blocks' source lines
  const std::string html = test::read_text_file("tc_preview.html");
  CHECK(html.find("trr-xy (" + machine_path() + ")") != std::string::npos);
  CHECK(html.find("GOTO/") != std::string::npos);
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("<script") == std::string::npos);

  // the same largest error by the other route: the plain program re-executed by `post --verify`
  REQUIRE(run("post " + job() + "--tolerance none --verify -o tc_plain.nc " + sample_path(), &out) == 0);
  CHECK(account_figure(out, "before") == Approx(0.2709).margin(2e-4));
}

TEST_CASE("TRR-XY preview: --model of this machine previews its actual machine; the serial options are refused") {
  trr::Errors e;
  e.chain[0].gp = 2e-4;
  e.chain[1].dl = 0.03;
  std::ofstream("tc_model.json") << comp::format_model_json(trr::model_from_errors(e, "trr-xy"));
  std::string out;
  REQUIRE(run("preview " + job() + "--model tc_model.json --csv tc_model.csv " + sample_path(), &out) == 0);
  CHECK(lines_of("tc_model.csv").size() == 434);
  std::ofstream("tc_other.json") << comp::format_model_json(trr::model_from_errors(e, "other"));
  CHECK(run("preview " + job() + "--model tc_other.json --csv tc_other.csv " + sample_path(), &out) == 2);
  CHECK(out.find("machine 'other', this job's machine is 'trr-xy'") != std::string::npos);
  CHECK_FALSE(std::ifstream("tc_other.csv").good());
  CHECK(run("preview " + job() + "--tool-length 5 --csv tc_tl.csv " + sample_path(), &out) == 1);
  CHECK(out.find("--tool-length: the TRR-XY machine takes its tool offset from the machine file") != std::string::npos);
  CHECK_FALSE(std::ifstream("tc_tl.csv").good());
}

TEST_CASE("TRR-XY preview of a path out of reach: exit 3 naming the line and the axis, as post") {
  // the blocks before it lean far from home: each is evaluated from its own start pose; solved from
  // home, the forward kinematics of the block at line 614 ended beyond the links' reach (exit 3 there)
  std::string out;
  CHECK(run("preview " + job() + "--csv tc_far.csv " + test::data("scenarios/public-clean/path.cls"), &out) == 3);
  CHECK(out.find("path.cls:729: V623.8594 is outside the limits [0, 600]") != std::string::npos);
  CHECK_FALSE(std::ifstream("tc_far.csv").good());
}

TEST_CASE("TRR-XY plan, simulate and identify through the common writers and messages") {
  std::string out;
  REQUIRE(run("plan --machine " + machine_path() + " sphere -o tc_plan.csv", &out) == 0);
  CHECK(out == "plan sphere: 222 rows -> tc_plan.csv\nNC program -> tc_plan.nc\n");
  const std::vector<std::string> plan = lines_of("tc_plan.csv");
  REQUIRE(plan.size() == 4 + 222);
  CHECK(plan[3] == "t,X,Y,U,V,W,stylus");
  CHECK(plan[4] == "0.00,0.0000,0.0000,170.0000,170.0000,170.0000,0.0000");  // home: the three sliders at 170 mm
  const std::string nc = test::read_text_file("tc_plan.nc");
  std::size_t stops = 0;
  for (std::size_t at = nc.find("\nM0"); at != std::string::npos; at = nc.find("\nM0", at + 1)) ++stops;
  CHECK(stops == 222);
  CHECK(nc.find("(change the stylus: 100 mm)") != std::string::npos);
  CHECK(test::read_trr_program("tc_plan.nc").size() == 222);

  trr::Errors truth;
  truth.chain[2].ar = 1e-4;
  std::ofstream("tc_truth.json") << comp::format_model_json(trr::model_from_errors(truth, "trr-xy"));
  REQUIRE(run("simulate --machine " + machine_path() + " --model tc_truth.json -o tc_data.csv tc_plan.csv", &out) == 0);
  CHECK(out == "simulated 222 rows of sphere probing on 'trr-xy' (noise 0 µm) -> tc_data.csv\n");
  REQUIRE(run("identify --machine " + machine_path() + " -o tc_id.json tc_data.csv", &out) == 0);
  CHECK(out.find("TRR-XY identification from 222 probed points: rank 24 of 30") != std::string::npos);
  CHECK(out.ends_with("model -> tc_id.json\n"));  // said once the file is written
  // without --report, nothing is written beside the model (no one-page summary of a report not asked for)
  for (const auto& e : std::filesystem::directory_iterator("."))
    CHECK_FALSE(e.path().filename().string().ends_with("summary.html"));
  CHECK(trr::read_errors_json("tc_id.json").chain[2].ar == Approx(1e-4).margin(1e-7));

  // what the TRR-XY machine has not: exit 1 naming it, nothing written
  CHECK(run("plan --machine " + machine_path() + " laser -o tc_never", &out) == 1);
  CHECK(out.find("plan laser: the TRR-XY machine has the sphere-probing plan only") != std::string::npos);
  CHECK_FALSE(std::ifstream("tc_never.csv").good());
  CHECK_FALSE(std::ifstream("tc_never.nc").good());

  // --report through the same writer as the serial machines (issue 25; its content:
  // compensation/trr_cli_identify_test): the model, the report and its one-page summary
  CHECK(run("identify --machine " + machine_path() + " --report tc_rep.html -o tc_rep.json tc_data.csv", &out) == 0);
  CHECK(trr::read_errors_json("tc_rep.json").chain[2].ar == Approx(1e-4).margin(1e-7));
  CHECK(std::ifstream("tc_rep.html").good());
  CHECK(std::ifstream("tc_rep-summary.html").good());
  for (const char* f : {"tc_rep.json", "tc_rep.html", "tc_rep-summary.html"}) std::filesystem::remove(f);  // a rerun
}

TEST_CASE("TRR-XY post --tilted-plane: exit 1 saying why, no program") {
  std::string out;
  CHECK(run("post " + job() + "--tilted-plane -o tc_tilted.nc " + sample_path(), &out) == 1);
  CHECK(out.find("--tilted-plane: the TRR-XY machine has no tilted work plane") != std::string::npos);
  CHECK_FALSE(std::ifstream("tc_tilted.nc").good());
}

TEST_CASE("TRR-XY post --nonlinear harmonic: the paper's shift, error before and after by re-execution") {
  const trr::Machine m = load_trr_xy_machine(machine_path());
  const trr::Kinematics nominal(m);
  const std::vector<Vec3d> path = test::read_cl_tips(sample_path());
  std::string out;
  REQUIRE(run("post " + job() + "--tolerance none -o tc_h_plain.nc " + sample_path()) == 0);
  REQUIRE(run("post " + job() + "--tolerance 0.005 --nonlinear harmonic --verify -o tc_h.nc " + sample_path(), &out) ==
          0);
  REQUIRE(run("post " + job() + "--tolerance 0.005 -o tc_a.nc " + sample_path()) == 0);
  const auto plain = test::trr_executed_deviation(nominal, test::read_trr_program("tc_h_plain.nc"), path, kOrigin);
  const std::vector<trr::Command> harmonic_program = test::read_trr_program("tc_h.nc");
  const auto harmonic = test::trr_executed_deviation(nominal, harmonic_program, path, kOrigin);
  const std::vector<trr::Command> adaptive_program = test::read_trr_program("tc_a.nc");
  REQUIRE(plain);
  REQUIRE(harmonic);
  WARN("TRR-XY hemisphere, executed at 100 points per block: one block per motion "
       << *plain << " mm; harmonic 0.005: " << harmonic_program.size() << " blocks, " << *harmonic
       << " mm; adaptive 0.005: " << adaptive_program.size() << " blocks");
  CHECK(*plain == Approx(0.271).margin(0.001));
  // the half-sine model removes ~94 % of the bow; what is left is the part that is not a half sine
  // (as on the serial machines, README "Nonlinear error"): not bounded by the tolerance
  CHECK(*harmonic < 0.02);
  CHECK(*harmonic > 0.01);
  CHECK(harmonic_program.size() < adaptive_program.size());
  CHECK(account_figure(out, "after") == Approx(*harmonic).margin(0.001));
  CHECK(out.find("notice: --nonlinear harmonic") == std::string::npos);  // no longer replaced by adaptive
  CHECK(test::read_text_file("tc_h.nc").find("(model none [nominal machine], tolerance 0.005 mm [harmonic])") !=
        std::string::npos);
}
