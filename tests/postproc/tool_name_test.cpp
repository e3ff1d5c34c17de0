// SPDX-License-Identifier: Apache-2.0
// Tools called by name (issue 28): Klartext `TOOL CALL "name"` and Sinumerik `T="name"` re-posted
// (post_request.hpp). Dialects that call tools by name (heidenhain, sinumerik) keep the names;
// those that call them by number (fanuc) take the number from the tool table (--tool-table,
// docs/formats.md "Tool tables"), or refuse naming the tool and the option. The numbers expected
// are the ones the tests' own tables give. Both programs are executed independently: the input by
// the tests' Klartext interpreter or small Sinumerik interpreter, the written program by
// nc_executor.hpp (Fanuc) or the tests' own Klartext / Sinumerik interpreters (name-keeping
// dialects); every input block end must be reached by the output, in order, within 1 µm.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <regex>
#include <sstream>

#include "klartext_interpreter.hpp"
#include "nc_executor.hpp"
#include "sinumerik_mini.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

constexpr const char* kMachine = "head-table-bc.toml";  ///< the hyperMILL programs' kind of machine

Setup names_setup() {
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, -400);
  s.tool_length_mm = 100;
  return s;
}

test::ExecJob names_job() {
  test::ExecJob j;
  j.workpiece_origin_mm = test::V3(0, 0, -400);
  j.tool_length_mm = 100;
  return j;
}

/// Two tools by name, as hyperMILL writes them (a blank and an X inside the names).
const std::string kKlartext =
    "0 BEGIN PGM NAMES MM\n"
    "1 TOOL CALL \"FRA-X12 D15.2\" Z S2304 DL+0 DR+0\n"
    "2 L X+0 Y+0 Z+100 B+0 C+0 R0 FMAX M3\n"
    "3 L X+20 Y-10 Z+5 FMAX\n"
    "4 L Z-2 F300\n"
    "5 L X+60 F800\n"
    "6 L Z+100 FMAX M5\n"
    "7 TOOL CALL \"G12R6\" Z S301 DL+0 DR+0\n"
    "8 L X+10 Y+10 Z+50 R0 FMAX M3\n"
    "9 L Z-1 F200\n"
    "10 L Y+40 F500\n"
    "11 L Z+100 FMAX M5\n"
    "12 M30\n"
    "13 END PGM NAMES MM\n";

const std::string kSinumerik =
    "; two tools by name\n"
    "G17 G90 G710\n"
    "T=\"DRILL X8.5\"\n"
    "M6\n"
    "D1\n"
    "S2000 M3\n"
    "G0 X0 Y0 Z100 B0 C0\n"
    "G0 X20 Y-10 Z5\n"
    "G1 Z-2 F300\n"
    "G1 X60 F800\n"
    "G0 Z100\n"
    "T=\"G12R6\" M6\n"
    "D1\n"
    "S301 M3\n"
    "G0 X10 Y10 Z50\n"
    "G1 Z-1 F200\n"
    "G1 Y40 F500\n"
    "G0 Z100\n"
    "M30\n";

std::shared_ptr<const ToolTable> table_of(const std::string& toml) {
  return std::make_shared<const ToolTable>(parse_tool_table(toml, "tools.toml"));
}

std::string repost(const std::string& text, const std::string& name, const std::string& dialect,
                   std::shared_ptr<const ToolTable> table) {
  PostRequest r;
  r.machine = serial_post_machine(load_machine(test::source(std::string("machines/") + kMachine)));
  r.setup = names_setup();
  r.dialect = dialect_named(dialect);
  r.tool_table = std::move(table);
  r.threads = 1;
  r.input_name = name;
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

/// The refusal's message ("" when it posts).
std::string refusal(const std::string& text, const std::string& name, std::shared_ptr<const ToolTable> table) {
  try {
    repost(text, name, "fanuc", std::move(table));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Every input block end is reached by an output block end, in order, within 1 µm.
void check_ends(const std::vector<test::V3>& input_tips, const std::vector<test::V3>& output_tips) {
  REQUIRE(!input_tips.empty());
  std::size_t next = 0;
  for (std::size_t i = 0; i < input_tips.size(); ++i) {
    INFO("input end " << i << " tip " << input_tips[i].transpose());
    bool found = false;
    for (; next < output_tips.size() && !found; ++next) found = (output_tips[next] - input_tips[i]).norm() < 1e-3;
    CHECK(found);
  }
}

std::vector<test::V3> klartext_tips(const std::string& program) {
  const test::ExecMachine m = test::ExecMachine::load(test::source(std::string("machines/") + kMachine));
  test::KlartextInterpreter k(m, names_job(), [](const test::M3&, int) { return std::map<char, double>{}; });
  std::vector<test::V3> tips;
  for (const test::KlartextEnd& e : k.run(program)) tips.push_back(e.tip_W);
  return tips;
}

std::vector<test::V3> sinumerik_tips(const std::string& program) {
  const test::ExecMachine m = test::ExecMachine::load(test::source(std::string("machines/") + kMachine));
  std::vector<test::V3> tips;
  for (const test::SinumerikEnd& e : test::sinumerik_block_ends(program, m, names_job())) tips.push_back(e.tip_W);
  return tips;
}

std::vector<test::V3> fanuc_tips(const std::string& nc) {
  const test::Executor ex(test::source(std::string("machines/") + kMachine), names_job(), nc);
  std::vector<test::V3> tips;
  for (const test::ExecBlock& b : ex.blocks) tips.push_back(ex.at(b, 1.0).tip_W);
  return tips;
}

/// The tool words of the written program, in order: "T12", "TOOL CALL \"x\"", "T=\"x\"".
std::vector<std::string> tool_words(const std::string& nc) {
  static const std::regex word(R"((TOOL CALL "[^"]*"|T="[^"]*"|\bT\d+))");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(nc.begin(), nc.end(), word); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1].str());
  return out;
}

const char* const kTable =
    "[tools]\n"
    "\"FRA-X12 D15.2\" = 12\n"
    "\"G12R6\" = { number = 7, length = 100.0 }\n"
    "\"DRILL X8.5\" = 3\n";

}  // namespace

TEST_CASE("tool table: names to numbers and lengths; a malformed table refused at its line") {
  const auto t = table_of(kTable);
  REQUIRE(t->by_name.size() == 3);
  CHECK(t->by_name.at("FRA-X12 D15.2").number == 12);
  CHECK_FALSE(t->by_name.at("FRA-X12 D15.2").length_mm);
  CHECK(t->by_name.at("G12R6").number == 7);
  CHECK(*t->by_name.at("G12R6").length_mm == 100.0);
  CHECK(t->by_name.count("g12r6") == 0);  // names are exact
  struct Bad {
    const char* text;
    const char* message;
  };
  const Bad bad[] = {
      {"[tools]\n\"A\" = 1\n\"B\" = 1\n", "tools.toml:3:1: tool \"B\" has number 1, as \"A\" has"},
      {"[tools]\n\"A\" = -1\n", "tools.toml:2:7: tool \"A\": expected a tool number"},
      {"[tools]\n\"A\" = 1.5\n", "tools.toml:2:7: tool \"A\": expected a tool number"},
      {"[tools]\n\"A\" = { number = 2, lenght = 3 }\n", "tools.toml:2:21: tool \"A\": unknown key 'lenght'"},
      {"[tools]\n\"A\" = { number = 2, length = 0 }\n", "tool \"A\": expected a length in mm"},
      {"[tools]\n\"A\" = { length = 50 }\n", "tools.toml:2:7: tool \"A\": no number"},
      {"[tool]\n\"A\" = 1\n", "tools.toml:1:2: unknown key 'tool'"},
  };
  for (const Bad& b : bad) {
    INFO(b.text);
    try {
      parse_tool_table(b.text, "tools.toml");
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains(b.message));
    }
  }
}

TEST_CASE("TOOL CALL by name re-posted for Fanuc: the tool table's numbers, every block end reached") {
  const std::string nc = repost(kKlartext, "names.h", "fanuc", table_of(kTable));
  INFO(nc);
  CHECK(tool_words(nc) == std::vector<std::string>{"T12", "T7"});
  CHECK(nc.find("T12 M6") != std::string::npos);
  CHECK(nc.find("G43 H7") != std::string::npos);  // the length register of the table's number
  CHECK(nc.find("tool \"G12R6\" length 100.0000 mm from the tool table tools.toml") != std::string::npos);
  check_ends(klartext_tips(kKlartext), fanuc_tips(nc));
}

TEST_CASE("TOOL CALL by name for a dialect of tool numbers: refused at the call without the tool's number") {
  const int second_call = 8;  // the line of TOOL CALL "G12R6" in kKlartext (1-based)
  std::string e = refusal(kKlartext, "names.h", nullptr);
  CHECK_THAT(e, Catch::StartsWith("names.h:2:"));
  CHECK_THAT(e, Catch::Contains("tool \"FRA-X12 D15.2\" is called by name") && Catch::Contains("--tool-table FILE"));
  e = refusal(kKlartext, "names.h", table_of("[tools]\n\"FRA-X12 D15.2\" = 12\n"));
  CHECK_THAT(e, Catch::StartsWith("names.h:" + std::to_string(second_call) + ":"));
  CHECK_THAT(e, Catch::Contains("add \"G12R6\" = <number> to [tools] in tools.toml"));
  // a length in the table that differs from the one the head's axes are solved for
  e = refusal(kKlartext, "names.h",
              table_of("[tools]\n\"FRA-X12 D15.2\" = { number = 12, length = 80 }\n\"G12R6\" = 7\n"));
  CHECK_THAT(e, Catch::StartsWith("names.h:2:") && Catch::Contains("is 80.0000 mm long (the tool table tools.toml)"));
}

TEST_CASE("TOOL CALL by name re-posted for Heidenhain keeps the names; the program runs to the same ends") {
  const std::string nc = repost(kKlartext, "names.h", "heidenhain", nullptr);
  INFO(nc);
  CHECK(tool_words(nc) == std::vector<std::string>{"TOOL CALL \"FRA-X12 D15.2\"", "TOOL CALL \"G12R6\""});
  CHECK(nc.find("TOOL CALL \"FRA-X12 D15.2\" Z S2304") != std::string::npos);
  check_ends(klartext_tips(kKlartext), klartext_tips(nc));
}

TEST_CASE("Sinumerik T=\"name\": the sinumerik dialect keeps the names, fanuc takes the table's numbers") {
  const std::string kept = repost(kSinumerik, "names.mpf", "sinumerik", nullptr);
  INFO(kept);
  CHECK(tool_words(kept) == std::vector<std::string>{"T=\"DRILL X8.5\"", "T=\"G12R6\""});
  check_ends(sinumerik_tips(kSinumerik), sinumerik_tips(kept));
  const std::string nc = repost(kSinumerik, "names.mpf", "fanuc", table_of(kTable));
  INFO(nc);
  CHECK(tool_words(nc) == std::vector<std::string>{"T3", "T7"});
  check_ends(sinumerik_tips(kSinumerik), fanuc_tips(nc));
  const std::string e = refusal(kSinumerik, "names.mpf", nullptr);
  CHECK_THAT(e, Catch::StartsWith("names.mpf:4:") && Catch::Contains("tool \"DRILL X8.5\" is called by name"));
}

// tests/data/real/sinumerik_cam_test.mpf (MIT, SOURCES.md): `N100 T="DRILL 8.5" M6` (line 10), then
// plain ISO blocks from line 18 to line 992 (G0-G3 with numbers), executed here by the tests' small
// Sinumerik interpreter; on the AC trunnion at A = C = 0 the machine X Y Z are the tip's.
TEST_CASE("the real Sinumerik program with T=\"DRILL 8.5\": numbered from the table, or kept by name") {
  const std::string text = test::read_text_file(test::data("real/sinumerik_cam_test.mpf"));
  std::istringstream lines(text);
  std::string body;
  int n = 0;
  for (std::string l; std::getline(lines, l);)
    if (++n >= 18 && n <= 992) body += l + "\n";
  PostRequest r;
  r.machine = serial_post_machine(load_machine(test::source("machines/ac-trunnion.toml")));
  r.setup.workpiece_origin_mm = Vec3d(0, 0, -400);
  r.tool_table = table_of("[tools]\n\"DRILL 8.5\" = 5\n");
  r.threads = 1;
  r.input_name = "sinumerik_cam_test.mpf";
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  const std::string nc = out.str();
  CHECK(tool_words(nc) == std::vector<std::string>{"T5", "T0"});  // the table's number; the closing T0 as written
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(0, 0, -400);
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  std::vector<test::V3> want;
  for (const test::SinumerikEnd& e : test::sinumerik_block_ends(body, m, job)) want.push_back(e.tip_W);
  CHECK(want.size() > 900);
  const test::Executor ex(test::source("machines/ac-trunnion.toml"), job, nc);
  std::vector<test::V3> got;
  for (const test::ExecBlock& b : ex.blocks) got.push_back(ex.at(b, 1.0).tip_W);
  check_ends(want, got);

  r.dialect = dialect_named("sinumerik");
  r.tool_table = nullptr;
  std::istringstream again(text);
  std::ostringstream kept;
  post(again, kept, r);
  CHECK(tool_words(kept.str()) == std::vector<std::string>{"T=\"DRILL 8.5\"", "T0"});
}
