// SPDX-License-Identifier: Apache-2.0
// The library entry point ncpost::post (post_request.hpp) from string streams against the
// `ncpost post` command on the same input: the same program, byte for byte, and the same figures
// (the command's stderr is rebuilt from the result: its summary line and account_text).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

struct FromCode {
  std::string program;
  PostResult result;
};

/// ncpost::post on the text of `cl_path`, read into a string stream (named `cl_path` in messages).
FromCode post_from_string(const std::string& cl_path, const PostRequest& request, const std::string& prefix = "") {
  std::istringstream in(prefix + test::read_text_file(cl_path));
  if (!prefix.empty()) {
    std::string skipped;
    std::getline(in, skipped);  // the stream starts where the caller left it
  }
  std::ostringstream out;
  FromCode f;
  f.result = post(in, out, request);
  f.program = out.str();
  return f;
}

PostRequest request_for(const std::string& machine_path, const std::string& input) {
  PostRequest r;
  r.machine = serial_post_machine(load_machine(machine_path));
  r.machine_source = machine_path;
  r.setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  r.input_name = input;
  return r;
}

}  // namespace

TEST_CASE("post from code: hemisphere, default tolerance, --verify: the CLI's program and figures", "[post][entry]") {
  const std::string dir = test::make_temp_dir("post_request_test");
  const std::string machine = test::source("machines/ac-trunnion.toml");
  const std::string input = test::source("samples/hemisphere_5axis.cls");
  const std::string nc = dir + "/cli.nc", log = dir + "/cli.log";
  REQUIRE(test::run_ncpost(
              fmt::format("post --machine {} --workpiece-origin 0,0,80 --verify -o {} {}", machine, nc, input), log) ==
          0);
  PostRequest r = request_for(machine, input);
  r.verify = true;
  const FromCode code = post_from_string(input, r);
  CHECK(code.program == test::read_text_file(nc));
  const PostAccount& a = code.result.account;
  REQUIRE(code.result.verified);
  std::string expected_log;
  for (const auto& n : code.result.summary.notices) expected_log += "notice: " + n + "\n";
  expected_log += fmt::format("ncpost post: {} CL motions -> {} blocks in {}\n", a.motions_in, a.blocks_out, nc);
  expected_log += account_text(a);
  CHECK(test::read_text_file(log) == expected_log);
  // the default tolerance (0.01 mm) holds in the written program; the plain post bows more
  CHECK(a.tolerance_mm == kDefaultTolerance_mm);
  CHECK(a.after.max_contour_mm <= kDefaultTolerance_mm);
  CHECK(a.before_max_mm > 0.02);
  CHECK(a.blocks_out > a.motions_in);
  CHECK(a.before_blocks > 0);
}

TEST_CASE("post from code: a stream that starts after what the caller read, tolerance none", "[post][entry]") {
  const std::string dir = test::make_temp_dir("post_request_test");
  const std::string machine = test::source("machines/ac-trunnion.toml");
  const std::string input = test::source("samples/hemisphere_5axis.cls");
  const std::string log = dir + "/cli.log";
  REQUIRE(test::run_ncpost(fmt::format("post --machine {} --workpiece-origin 0,0,80 --tolerance none --dialect "
                                       "sinumerik --threads 1 -o {}/cli.nc {}",
                                       machine, dir, input),
                           log) == 0);
  PostRequest r = request_for(machine, input);
  r.tolerance_mm.reset();
  r.tolerance_is_default = false;
  r.dialect = dialect_named("sinumerik");
  r.threads = 1;
  const FromCode code = post_from_string(input, r, "not part of the input\n");
  CHECK(code.program == test::read_text_file(dir + "/cli.nc"));
  CHECK_FALSE(code.result.verified);
  CHECK(code.result.summary.blocks_out >=
        code.result.summary.motions_in);  // one block per CL motion, plus rapids split
}

TEST_CASE("post from code: with a model, verify-on, and under RTCP: the CLI's programs", "[post][entry]") {
  const std::string dir = test::make_temp_dir("post_request_test");
  const std::string machine = test::data("scenarios/public-clean/machine.toml");
  const std::string truth = test::data("scenarios/public-clean/truth.json");
  const std::string input = test::source("samples/hemisphere_5axis.cls");
  const std::string nc = dir + "/model.nc", log = dir + "/model.log";
  REQUIRE(test::run_ncpost(fmt::format("post --machine {} --workpiece-origin 0,0,80 --model {} --tolerance 0.005 "
                                       "--verify-on {} -o {} {}",
                                       machine, truth, truth, nc, input),
                           log) == 0);
  PostRequest r = request_for(machine, input);
  const Machine m = load_machine(machine);
  const comp::ModelFile model = comp::read_model_json(truth, &m);
  r.machine = serial_post_machine(m, model.parameters, model.parameters);
  r.model_source = truth;
  r.verify_on_source = truth;
  r.tolerance_mm = 0.005;
  r.tolerance_is_default = false;
  const FromCode code = post_from_string(input, r);
  CHECK(code.program == test::read_text_file(nc));
  const PostAccount& a = code.result.account;
  REQUIRE(code.result.verified);
  CHECK(a.executed_on == "the machine of " + truth);
  std::string expected_log;
  for (const auto& n : code.result.summary.notices) expected_log += "notice: " + n + "\n";
  expected_log += fmt::format("ncpost post: {} CL motions -> {} blocks in {}\n", a.motions_in, a.blocks_out, nc);
  expected_log += account_text(a);
  CHECK(test::read_text_file(log) == expected_log);
  CHECK(a.after.max_contour_mm <= 0.005);  // compensated for the machine it runs on
  CHECK(a.uncompensated_tip_max_mm > 0.005);

  SECTION("RTCP, haas: the default tolerance is off, nothing re-executed") {
    const std::string rtcp_nc = dir + "/rtcp.nc";
    REQUIRE(test::run_ncpost(fmt::format("post --machine {} --workpiece-origin 0,0,80 --rtcp --dialect haas --verify "
                                         "-o {} {}",
                                         machine, rtcp_nc, input),
                             dir + "/rtcp.log") == 0);
    PostRequest q = request_for(machine, input);
    q.rtcp = true;
    q.dialect = dialect_named("haas");
    q.verify = true;
    const FromCode rtcp = post_from_string(input, q);
    CHECK(rtcp.program == test::read_text_file(rtcp_nc));
    CHECK_FALSE(rtcp.result.verified);
    CHECK(rtcp.result.account.tolerance_mm == 0.0);
    CHECK(rtcp.result.summary.blocks_out >= rtcp.result.summary.motions_in);
  }
}

TEST_CASE("post from code: a request that cannot run says why", "[post][entry]") {
  PostRequest r;
  std::istringstream in("FINI\n");
  std::ostringstream out;
  CHECK_THROWS_AS(post(in, out, r), std::invalid_argument);  // no machine
  r = request_for(test::source("machines/ac-trunnion.toml"), "empty.cls");
  r.threads = 3;
  CHECK(r.validate() == "threads: expected 1 or 2, got 3");
  r.threads = 1;
  std::istringstream empty("  \n");
  CHECK_THROWS_AS(post(empty, out, r), InputError);
  CHECK(out.str().empty());
}
