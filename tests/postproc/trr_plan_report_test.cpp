// SPDX-License-Identifier: Apache-2.0
// The TRR-XY machine in two places of the one pipeline (issue 16): `plan sphere --dialect` writes the
// probing program through the NC writer in the chosen dialect (two dialects differ exactly in their
// program start and end and their comments, and read back to the same positions as the plan's CSV),
// and `post --report` shows the tool path coloured by the contour error before and after, as on the
// serial machines.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_run.hpp"
#include "ncpost/compensation/trr_probing_csv.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;

namespace {

int run(const std::string& args, std::string* log = nullptr) {
  const int rc = test::run_ncpost(args, "trr_plan_report.log");
  if (log) *log = test::read_text_file("trr_plan_report.log");
  return rc;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// The fanuc dialect file with other program start and end words and semicolon comments: what a user
/// who copies fanuc.toml might change.
std::string user_dialect() {
  std::string d = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));
  const auto replace = [&d](const std::string& from, const std::string& to) {
    const auto at = d.find(from);
    REQUIRE(at != std::string::npos);
    d.replace(at, from.size(), to);
  };
  replace("name = \"fanuc\"", "name = \"shop\"");
  replace("start = [\"O0001 ({program})\", \"{comments}\", \"G90 G21 G94 G17 G40 G49 G80\"]",
          "start = [\"O0002 ({program})\", \"{comments}\", \"G90 G21 G94 G17 G40 G49 G80\", \"G54\"]");
  replace("end = [\"M5\", \"M9\", \"G91 G28 Z0\", \"G90\", \"M30\"]", "end = [\"M5\", \"M99\"]");
  replace("style = \"parentheses\"", "style = \"semicolon\"");
  return d;
}

/// A comment in either style as the text it holds; any other line as it is.
std::string comment_text(const std::string& line, bool* is_comment) {
  static const std::regex paren("^(.*?) ?\\((.*)\\)$"), semi("^(.*?) ?; (.*)$");
  std::smatch m;
  *is_comment = std::regex_match(line, m, paren) || std::regex_match(line, m, semi);
  return *is_comment ? m[1].str() + "|" + m[2].str() : line;
}

}  // namespace

TEST_CASE("TRR-XY plan sphere --dialect: the dialect's words only, the same positions", "[plan][trr]") {
  const std::string machine = test::trr_machine_path();
  std::ofstream("shop.toml") << user_dialect();
  REQUIRE(run("plan sphere --machine " + machine + " -o trr_plan_fanuc") == 0);  // fanuc: the default
  REQUIRE(run("plan sphere --machine " + machine + " --dialect shop.toml -o trr_plan_shop") == 0);
  REQUIRE(run("plan sphere --machine " + machine + " --dialect linuxcnc -o trr_plan_linuxcnc") == 0);

  const std::vector<std::string> fanuc = lines_of("trr_plan_fanuc.nc"), shop = lines_of("trr_plan_shop.nc");
  // fanuc: %, O0001 (TRRPROBE), header comment, G90 ... | body | M5 M9 G90 M30, % (the writer leaves out
  //        the end's "G91 G28 Z0": the machine has no Z)
  // shop:  %, O0002 (TRRPROBE), header comment, G90 ..., G54 | body | M5 M99, %
  REQUIRE(fanuc.size() > 100);
  CHECK(fanuc[0] == "%");
  CHECK(fanuc[1] == "O0001 (TRRPROBE)");
  CHECK(shop[1] == "O0002 (TRRPROBE)");  // the start sequence's own text
  CHECK(shop[4] == "G54");
  CHECK(std::vector<std::string>(fanuc.end() - 5, fanuc.end()) ==
        std::vector<std::string>{"M5", "M9", "G90", "M30", "%"});
  CHECK(std::vector<std::string>(shop.end() - 3, shop.end()) == std::vector<std::string>{"M5", "M99", "%"});
  // between them, line for line: the same blocks, the comments in the other style
  const std::size_t fanuc_start = 4, shop_start = 5, fanuc_end = 5, shop_end = 3;
  bool header_a = false, header_b = false;
  CHECK(comment_text(fanuc[2], &header_a) == comment_text(shop[2], &header_b));  // the header comment
  CHECK((header_a && header_b));
  REQUIRE(fanuc.size() - fanuc_start - fanuc_end == shop.size() - shop_start - shop_end);
  int comments = 0, blocks = 0;
  for (std::size_t i = 0; i < fanuc.size() - fanuc_start - fanuc_end; ++i) {
    const std::string& a = fanuc[fanuc_start + i];
    const std::string& b = shop[shop_start + i];
    bool ca = false, cb = false;
    const std::string ta = comment_text(a, &ca), tb = comment_text(b, &cb);
    CHECK(ca == cb);
    CHECK(ta == tb);
    if (ca) {
      CHECK(a != b);  // "(text)" against "; text"
      ++comments;
    } else {
      CHECK(a == b);
      ++blocks;
    }
  }
  CHECK(comments > 90);  // the stop blocks' notes and the stylus change
  CHECK(blocks > 90);

  // every program moves to the positions of the plan's CSV (rounded as the dialect writes them)
  const trr::ProbingData plan = trr::read_probing_csv("trr_plan_fanuc.csv", true);
  CHECK(test::read_text_file("trr_plan_fanuc.csv") == test::read_text_file("trr_plan_shop.csv"));
  for (const std::string name : {"fanuc", "shop", "linuxcnc"}) {
    const std::vector<trr::Command> program = test::read_trr_program("trr_plan_" + name + ".nc");
    REQUIRE(program.size() == plan.rows.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < program.size(); ++i)
      worst = std::max(worst, (program[i].words() - plan.rows[i].command.words()).cwiseAbs().maxCoeff());
    CHECK(worst < 1e-9);
  }
  const std::vector<std::string> linuxcnc = lines_of("trr_plan_linuxcnc.nc");
  CHECK(linuxcnc.back() == "M2");
  CHECK(linuxcnc.front() != "%");
}

TEST_CASE("TRR-XY post --report: the tool path coloured by the contour error before and after", "[post][trr][report]") {
  REQUIRE(run("post --machine " + test::trr_machine_path() +
              " --workpiece-origin 0,0,-300 --tolerance 0.005 --verify "
              "--report trr_report.html -o trr_report.nc " +
              test::hemisphere_sample_path()) == 0);
  const std::string html = test::read_text_file("trr_report.html");
  CHECK(html.find("No path to show") == std::string::npos);
  // both maps, each with one point per feed motion of the hemisphere (435 CL motions, 2 of them rapids:
  // the 433 rows of its preview)
  for (const std::string id : {"path-before", "path-after"}) {
    CHECK(html.find("id=\"" + id + "\"") != std::string::npos);
    const std::regex data("\\{\"id\":\"" + id + "\",\"p\":\\[([^\\]]*)\\]");
    std::smatch m;
    REQUIRE(std::regex_search(html, m, data));
    const std::string p = m[1].str();
    const long coordinates = std::count(p.begin(), p.end(), ',') + 1;
    CHECK(coordinates == 3 * 433);
  }
  CHECK(html.find("before: one block per CL motion, nominal commands") != std::string::npos);
  CHECK(html.find("after: the written program re-executed") != std::string::npos);
}
