// SPDX-License-Identifier: Apache-2.0
// Issue 24.5: the parameter and expression evaluator (gcode_expression.hpp), its statements in a
// line (gcode_macro.hpp) and in the reader: jumps and loops. Expected values are worked out by
// hand from the Fanuc Macro B / RS274NGC rules the header states.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "ncpost/postproc/read/gcode/gcode_macro.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

ParamValue eval(const std::string& text, const Parameters& p = {}) {
  Evaluator ev(p);
  std::size_t at = 0;
  const ParamValue v = ev.expression(text, at);
  CHECK(at == text.size());
  return v;
}

double number(const std::string& text, const Parameters& p = {}) {
  const ParamValue v = eval(text, p);
  REQUIRE(v);
  return *v;
}

std::string eval_error(const std::string& text, const Parameters& p = {}) {
  try {
    eval(text, p);
  } catch (const ExpressionError& e) {
    return e.what();
  }
  FAIL("no error for " << text);
  return {};
}

std::vector<cl::Motion> motions(const std::string& text) {
  std::istringstream in(text);
  GcodeReaderOptions o;
  o.check_limits = false;
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), Setup{}, o);
  return test::only<cl::Motion>(test::all_records(r));
}

InputError reader_error(const std::string& text) {
  try {
    motions(text);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

}  // namespace

TEST_CASE("gcode expression: operators and their precedence") {
  CHECK(number("[1 + 2 * 3]") == 7.0);
  CHECK(number("[[1 + 2] * 3]") == 9.0);
  CHECK(number("[10 - 4 - 3]") == 3.0);     // left to right
  CHECK(number("[2 ** 3 ** 2]") == 512.0);  // ** to the right: 2 ** 9
  CHECK(number("[-2 ** 2]") == 4.0);        // the sign binds its value: (-2) ** 2
  CHECK(number("[7 MOD 3]") == 1.0);
  CHECK(number("[7 / 2]") == 3.5);
  CHECK(number("[1 + 2 EQ 3]") == 1.0);        // arithmetic before comparison
  CHECK(number("[2 GT 3 OR 4 LE 4]") == 1.0);  // comparison before logic
  CHECK(number("[1 AND 0 OR 1]") == 1.0);
  CHECK(number("[1 XOR 1]") == 0.0);
  CHECK(number("[3 NE 3]") == 0.0);
  CHECK(number("[2 ge 2]") == 1.0);  // case does not count
  CHECK(number("[1 LT 2 AND 3 LT 2]") == 0.0);
}

TEST_CASE("gcode expression: functions in degrees") {
  CHECK(number("SIN[30]") == Approx(0.5));
  CHECK(number("COS[60]") == Approx(0.5));
  CHECK(number("TAN[45]") == Approx(1.0));
  CHECK(number("ASIN[0.5]") == Approx(30.0));
  CHECK(number("ACOS[0]") == Approx(90.0));
  CHECK(number("ATAN[1]/[-1]") == Approx(135.0));  // atan2: the second quadrant
  CHECK(number("ATAN[1]") == Approx(45.0));
  CHECK(number("SQRT[16]") == 4.0);
  CHECK(number("ABS[-2.5]") == 2.5);
  CHECK(number("ROUND[2.5]") == 3.0);
  CHECK(number("FIX[2.7]") == 2.0);
  CHECK(number("FUP[2.1]") == 3.0);
  CHECK(number("LN[EXP[2]]") == Approx(2.0));
  Parameters p;
  p.set("depth", 4.0);
  CHECK(number("EXISTS[#<depth>]", p) == 1.0);
  CHECK(number("EXISTS[#<width>]", p) == 0.0);
}

TEST_CASE("gcode expression: parameters, vacancy and the refusals") {
  Parameters p;
  p.set(1, 5.0);
  p.set(510, 2.0);
  p.set(7, 510.0);
  p.set("_global", 3.0);
  CHECK(number("[#510 + 1]", p) == 3.0);
  CHECK(number("##7", p) == 2.0);  // the parameter whose number #7 holds
  CHECK(number("#[#1 + 505]", p) == 2.0);
  CHECK(number("#<_Glo Bal>", p) == 3.0);  // LinuxCNC names: case and blanks do not count
  CHECK(number("[#2 EQ #0]", p) == 1.0);   // #2 was never set: vacant
  CHECK(number("[#1 EQ #0]", p) == 0.0);
  CHECK_FALSE(eval("#0", p));
  CHECK_THAT(eval_error("[#2 + 1]", p), Catch::Contains("vacant"));
  CHECK_THAT(eval_error("#5221", p), Catch::Contains("#5221 is a system variable"));
  CHECK_THAT(eval_error("#3000", p), Catch::Contains("#3000"));
  CHECK_THAT(eval_error("[1 / 0]", p), Catch::Contains("division by zero"));
  CHECK_THAT(eval_error("FIX[-2.5]", p), Catch::Contains("Fanuc"));
  CHECK_THAT(eval_error("FUP[-2.5]", p), Catch::Contains("LinuxCNC"));
  CHECK(number("FIX[-2]", p) == -2.0);  // a whole number: every reading agrees
  CHECK_THAT(eval_error("[-7 MOD 3]", p), Catch::Contains("negative"));
  CHECK_THAT(eval_error("[2 AND 1]", p), Catch::Contains("bitwise"));
  CHECK_THAT(eval_error("SQRT[-1]", p), Catch::Contains("no finite value"));
  CHECK_THAT(eval_error("[1 + 2", p), Catch::Contains("']'"));
}

TEST_CASE("gcode expression: values beyond the range of numbers are refused (fuzz findings)") {
  // a parameter number beyond a 64-bit integer is named as written, not converted (undefined
  // behaviour before); sums, products and numbers that overflow to infinity never reach a word
  const std::string digits(400, '9');
  CHECK_THAT(eval_error("#1180591620717411303424"),
             Catch::Contains("#1180591620717411303424 is a system variable"));  // 2^70
  CHECK_THAT(eval_error("[" + digits + "]"), Catch::Contains("beyond the range"));
  const std::string big = "1" + std::string(200, '0');  // 1e200
  CHECK_THAT(eval_error("[" + big + " * " + big + "]"), Catch::Contains("'*' gives a value beyond the range"));
  const std::string near_max = "17" + std::string(307, '0');  // 1.7e308, a finite double
  CHECK(number("[" + near_max + " - " + near_max + "]") == 0.0);
  CHECK_THAT(eval_error("[" + near_max + " + " + near_max + "]"),
             Catch::Contains("'+' gives a value beyond the range"));
  CHECK(number("[" + big + " / " + big + "]") == 1.0);
}

TEST_CASE("gcode macro line: assignments, word values and columns") {
  Parameters p;
  std::string out;
  // assignments on one line read the values from before it (RS274NGC): #1 is still vacant
  CHECK_THROWS_WITH(apply_macro_line("#1 = 5 #<feed> = [#1 * 20]", p, out, "t.ngc", 1), Catch::Contains("vacant"));
  apply_macro_line("#1 = 5 #2 = 6", p, out, "t.ngc", 1);
  CHECK(p.get(1) == 5.0);
  CHECK(p.get(2) == 6.0);
  apply_macro_line("#<feed> = [#1 * 20]", p, out, "t.ngc", 1);
  CHECK(p.get("feed") == 100.0);
  CHECK(out.find_first_not_of(' ') == std::string::npos);  // the statement is blanked
  p.set(24, 12.5);
  p.set(510, 4.0);
  apply_macro_line("G1 X#24 Y[#510+1] Z-#1 F#<feed>", p, out, "t.ngc", 1);
  // `[#510+1]` is 8 characters, `5.` two (a length word's value keeps its point: in units, never least increments,
  // gcode_integer_words.hpp): 6 blanks before it; `-#1` (3) as `-5.`; `#<feed>` (7) as `    100`
  CHECK(out == "G1 X12.5 Y      5. Z-5. F    100");
  // a number longer than its expression moves the rest; a vacant word value is refused
  try {
    apply_macro_line("G1 X#33", p, out, "t.ngc", 7);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().line == 7);
    CHECK(e.where().column == 5);
    CHECK_THAT(e.detail(), Catch::Contains("X takes a vacant value"));
  }
  // comments and Sinumerik MSG texts are copied, their words are no statements
  CHECK_FALSE(may_hold_macro("MSG(\"END OF PROGRAM\")"));
  CHECK_FALSE(may_hold_macro("G0 X1 (IF #1 GOTO 5)"));
  apply_macro_line("#9 = 1 MSG(\"DO IT [NOW]\") (END #2)", p, out, "t.ngc", 1);
  CHECK(out == "       MSG(\"DO IT [NOW]\") (END #2)");
  try {
    apply_macro_line("o100 while [#1 lt 3]", p, out, "t.ngc", 2);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.detail(), Catch::Contains("o-word WHILE"));
  }
}

TEST_CASE("gcode macro program: parameters place the motions (X[#510+1], X#24)") {
  const auto ms = motions(
      "%\nG21 G90 G94\n#24 = 12.5\n#510 = 4\n#<depth> = -[#510 / 2]\n"
      "G0 X#24 Y[#510+1] Z10\nG1 Z#<depth> F100\nX[#24 * 2]\nM30\n%\n");
  REQUIRE(ms.size() == 3);
  CHECK(ms[0].point.tip_mm.isApprox(Vec3d(12.5, 5, 10)));
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(12.5, 5, -2)));
  CHECK(ms[2].point.tip_mm.isApprox(Vec3d(25, 5, -2)));
}

TEST_CASE("gcode macro program: WHILE loops, IF GOTO and GOTO, as a control runs them") {
  // a loop of 4 passes stepping down 1.5 mm: Z -1.5, -3, -4.5, -6, each with a cut to X40 and back
  const std::string loop =
      "%\nG21 G90 G94\nG0 X0 Y0 Z5\n#1 = 0\nWHILE [#1 LT 4] DO1\n#1 = #1 + 1\nG1 Z[-1.5 * #1] F200\nX40\nX0\n"
      "END1\nG0 Z5\nM30\n%\n";
  const auto ms = motions(loop);
  REQUIRE(ms.size() == 1 + 4 * 3 + 1);
  for (int pass = 1; pass <= 4; ++pass) {
    INFO(pass);
    const double z = -1.5 * pass;
    CHECK(ms[static_cast<std::size_t>(1 + 3 * (pass - 1))].point.tip_mm.isApprox(Vec3d(0, 0, z)));
    CHECK(ms[static_cast<std::size_t>(2 + 3 * (pass - 1))].point.tip_mm.isApprox(Vec3d(40, 0, z)));
  }
  CHECK(ms.back().point.tip_mm.isApprox(Vec3d(0, 0, 5)));
  // a false WHILE skips to after its END
  CHECK(motions("G21 G90\nG0 X1 Y0 Z5\n#1 = 9\nWHILE [#1 LT 4] DO2\nG0 X2\nEND2\nG0 X3\nM30\n").size() == 2);
  // IF GOTO forward skips blocks; GOTO backward with a counter runs a block three times
  const auto jumped = motions("G21 G90\nG0 X1 Y0 Z5\n#5 = 1\nIF [#5 EQ 1] GOTO 30\nG0 X99\nN30 G0 X2\nM30\n");
  REQUIRE(jumped.size() == 2);
  CHECK(jumped[1].point.tip_mm.x() == 2.0);
  const auto back = motions("G21 G90\nG0 X0 Y0 Z5\n#2 = 0\nN10 #2 = #2 + 1\nG0 X#2\nIF [#2 LT 3] GOTO 10\nM30\n");
  REQUIRE(back.size() == 4);
  CHECK(back[1].point.tip_mm.x() == 1.0);
  CHECK(back[2].point.tip_mm.x() == 2.0);
  CHECK(back[3].point.tip_mm.x() == 3.0);
  // IF THEN: a conditional assignment
  const auto then =
      motions("G21 G90\n#3 = 1\nIF [#3 GT 0] THEN #3 = 7\nIF [#3 GT 100] THEN #3 = 0\nG0 X#3 Y0 Z5\nM30\n");
  REQUIRE(then.size() == 1);
  CHECK(then[0].point.tip_mm.x() == 7.0);
}

TEST_CASE("gcode macro program: refusals with their line") {
  const InputError missing = reader_error("G21\nGOTO 50\nM30\n");
  CHECK(missing.where().line == 2);
  CHECK_THAT(missing.detail(), Catch::Contains("no block N50"));
  const InputError endless = reader_error("G21\nG0 X0 Y0 Z5\nWHILE [1 EQ 1] DO1\nEND1\nM30\n");
  CHECK_THAT(endless.detail(), Catch::Contains("never ends"));
  const InputError system = reader_error("G21\nG0 X#5221 Y0 Z5\nM30\n");
  CHECK(system.where().line == 2);
  CHECK(system.where().column == 5);
  CHECK_THAT(system.detail(), Catch::Contains("#5221 is a system variable"));
  const InputError stray = reader_error("G21\nG0 X0 Y0 Z5\nEND3\nM30\n");
  CHECK_THAT(stray.detail(), Catch::Contains("END 3 without its WHILE"));
}
