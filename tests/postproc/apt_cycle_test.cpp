// SPDX-License-Identifier: Apache-2.0
// CYCLE/ statements of NX, Creo and SOLIDWORKS CAM read into cl::Cycle (apt_cycle.hpp): every
// distance along the tool axis from the hole's GOTO point, the feed units, the pecks and the
// thread pitch; an unknown kind or word is an error naming the line.
#include <catch2/catch.hpp>

#include <sstream>

#include "ncpost/postproc/read/apt/apt_cycle.hpp"

using namespace ncpost;

namespace {

/// A statement as the lexer gives it: "WORD" or a number per token (digit-first words such as
/// 1STPECK included, whatever the lexer of the day does with them).
cl::AptStatement statement(std::initializer_list<const char*> tokens, int line = 7) {
  cl::AptStatement st;
  st.where = {line, 1};
  st.major = "CYCLE";
  st.has_slash = true;
  int column = 7;
  for (const char* t : tokens) {
    cl::AptStatement::Argument a;
    a.column = column;
    char* end = nullptr;
    const double v = std::strtod(t, &end);
    if (end && *end == '\0' && end != t)
      a.is_number = true, a.number = v;
    else
      a.word = t;
    st.arguments.push_back(a);
    st.raw_arguments += (st.raw_arguments.empty() ? "" : ",") + std::string(t);
    column += static_cast<int>(std::string(t).size()) + 1;
  }
  return st;
}

cl::Cycle read(std::initializer_list<const char*> tokens, bool nx = false, double scale = 1.0) {
  const std::string file = "t.apt";
  auto c = cl::read_apt_cycle(statement(tokens), {file, scale, nx});
  REQUIRE(c.has_value());
  return *c;
}

std::string error_of(std::initializer_list<const char*> tokens) {
  const std::string file = "t.apt";
  try {
    cl::read_apt_cycle(statement(tokens), {file, 1.0, false});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("SOLIDWORKS CAM: DRILL and DEEP2 with FEDTO, RAPTO, RTRCTO, 1STPECK, SUBPECK") {
  const cl::Cycle d =
      read({"DRILL", "FEDTO", "7.85788", "MMPM", "326.770115", "RAPTO", "3.", "RTRCTO", "25.", "DWELL", "0"});
  CHECK(d.kind == cl::Cycle::Kind::drill);
  CHECK(d.depth_mm == 7.85788);
  CHECK(d.rapid_to_mm == 3.0);
  REQUIRE(d.retract_mm);
  CHECK(*d.retract_mm == 25.0);
  REQUIRE(d.feed);
  CHECK(*d.feed == 326.770115);
  CHECK_FALSE(d.feed_per_rev);
  CHECK(d.dwell_s == 0.0);

  const cl::Cycle p = read({"DEEP2", "FEDTO", "42.01108", "1STPECK", "5.", "SUBPECK", "2.", "MMPM", "432.1", "RAPTO",
                            "3.", "RTRCTO", "25."});
  CHECK(p.kind == cl::Cycle::Kind::deep);
  CHECK(p.kind_word == "DEEP2");
  CHECK(p.first_peck_mm == 5.0);
  CHECK(p.peck_mm == 2.0);
  CHECK(p.depth_mm == 42.01108);

  const cl::Cycle i =
      read({"DEEP", "FEDTO", "3.301", "INCR", "10.", "MMPM", "791.67", "RAPTO", "29.", "RTRCTO", "49."});
  CHECK(i.first_peck_mm == 10.0);
  CHECK(i.peck_mm == 10.0);
  CHECK(i.rapid_to_mm == 29.0);

  const std::string file = "t.apt";
  CHECK_FALSE(cl::read_apt_cycle(statement({"INIT"}), {file, 1.0, false}).has_value());
  CHECK_FALSE(cl::read_apt_cycle(statement({"CLEAR"}), {file, 1.0, false}).has_value());
  CHECK(cl::read_apt_cycle(statement({"OFF"}), {file, 1.0, false})->kind == cl::Cycle::Kind::off);
}

TEST_CASE("NX: FEDTO signed along the tool axis, RTRCTO AUTO, DRILL DEEP and BRKCHP, inch units") {
  const cl::Cycle d =
      read({"DRILL", "RAPTO", "3.0000", "FEDTO", "-33.0043", "RTRCTO", "AUTO", "MMPM", "250.0000"}, true);
  CHECK(d.kind == cl::Cycle::Kind::drill);
  CHECK(d.depth_mm == Approx(33.0043));
  CHECK_FALSE(d.retract_mm.has_value());  // back to the R plane
  const cl::Cycle z = read({"DRILL", "DEEP", "RAPTO", "3", "FEDTO", "0", "STEP", "2", "MMPM", "250"}, true);
  CHECK(z.kind == cl::Cycle::Kind::deep);
  CHECK(z.depth_mm == 0.0);  // the GOTO point is the bottom
  CHECK(z.rapid_to_mm == 3.0);
  CHECK(z.peck_mm == 2.0);
  const cl::Cycle b = read({"DRILL", "BRKCHP", "RAPTO", "0.1", "FEDTO", "-1", "STEP", "0.1", "IPM", "10"}, true, 25.4);
  CHECK(b.kind == cl::Cycle::Kind::chip_break);
  CHECK(b.depth_mm == Approx(25.4));
  CHECK(b.rapid_to_mm == Approx(2.54));
  CHECK(*b.feed == Approx(254.0));
  // an NX FEDTO above the R plane is no hole
  const std::string file = "t.apt";
  CHECK_THROWS_AS(cl::read_apt_cycle(statement({"DRILL", "RAPTO", "3", "FEDTO", "5"}), {file, 1.0, true}), InputError);
}

TEST_CASE("Creo: TAP with TPI, DEPTH and CLEAR; BORE, REAM, BORE DRAG; feed per revolution") {
  const cl::Cycle t = read({"TAP", "DEPTH", "10", "TPI", "20", "CLEAR", "2"});
  CHECK(t.kind == cl::Cycle::Kind::tap);
  CHECK(t.pitch_mm == Approx(1.27));
  CHECK(t.depth_mm == 10.0);
  CHECK(t.rapid_to_mm == 2.0);
  const cl::Cycle m = read({"TAP", "DEPTH", "8", "MMPR", "1.25", "CLEAR", "2"});
  CHECK(m.pitch_mm == 1.25);
  CHECK(m.feed_per_rev);
  CHECK(read({"BORE", "DEPTH", "8", "CLEAR", "2", "DWELL", "0.5"}).kind == cl::Cycle::Kind::bore);
  CHECK(read({"REAM", "DEPTH", "8", "CLEAR", "2"}).kind == cl::Cycle::Kind::bore);
  CHECK(read({"BORE", "DRAG", "DEPTH", "8", "CLEAR", "2"}).kind == cl::Cycle::Kind::bore_drag);
}

TEST_CASE("a cycle kind or word the post does not know stops it naming the line") {
  CHECK_THAT(error_of({"CSINK", "DEPTH", "3", "CLEAR", "2"}),
             Catch::Contains("t.apt:7:7:") && Catch::Contains("CSINK"));
  CHECK_THAT(error_of({"BORE", "BACK", "DEPTH", "3"}), Catch::Contains("BORE,BACK") && Catch::Contains("not known"));
  CHECK_THAT(error_of({"DRILL", "DEPTH", "3", "ORIENT", "90"}), Catch::Contains("'ORIENT' is not known"));
  CHECK_THAT(error_of({"DEEP", "DEPTH", "3", "CLEAR", "2"}), Catch::Contains("peck"));
  CHECK_THAT(error_of({"TAP", "DEPTH", "3", "CLEAR", "2"}), Catch::Contains("pitch"));
  CHECK_THAT(error_of({"DRILL", "CLEAR", "2"}), Catch::Contains("without a depth"));
  CHECK_THAT(error_of({"DRILL", "FEDTO", "3", "RAPTO", "5", "RTRCTO", "2"}), Catch::Contains("below the R plane"));
}
