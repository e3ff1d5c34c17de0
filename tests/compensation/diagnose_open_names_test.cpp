// SPDX-License-Identifier: Apache-2.0
// Issue 17: the error model holds what the open-ended diagnosis adds: harmonic orders beyond 4
// and periodic tables of a rotary axis (ECC:t:<deg>), by name, in the chain and in the model JSON.
#include <catch2/catch.hpp>

#include "diagnose_open_support.hpp"

using namespace ncpost;
using namespace ncpost::test;

TEST_CASE("Names: harmonic orders beyond 4 and rotary tables in degrees", "[diagnose][open][names]") {
  const Machine m = public_machine();
  const auto h6 = comp::parse_parameter_name("ECC:h6:cos", m);
  REQUIRE(h6.spec);
  CHECK(h6.spec->kind == comp::ParameterKind::harmonic);
  CHECK(h6.spec->order == 6);
  CHECK(comp::parse_parameter_name("EXC:h24:sin", m).spec->order == 24);
  CHECK_FALSE(comp::parse_parameter_name("ECC:h0:cos", m).spec);
  const auto t = comp::parse_parameter_name("ECC:t:30", m);
  REQUIRE(t.spec);
  CHECK(t.spec->kind == comp::ParameterKind::table);
  CHECK(t.spec->periodic);
  CHECK(t.spec->at_rad == Approx(kPi / 6));
  CHECK(t.spec->is_angle());
  CHECK_FALSE(comp::parse_parameter_name("ECC:t:360", m).spec);
  CHECK_FALSE(comp::parse_parameter_name("ECC:t:-10", m).spec);
  CHECK_FALSE(comp::parse_parameter_name("EXX:t:30", m).spec->periodic);  // linear tables unchanged
  CHECK(comp::effect_of("ECC:h6:sin") == "ECC:h6");
  CHECK(comp::effect_of("ECC:t:30") == "ECC:t");
  CHECK(comp::table_parameter_name('C', 'C', 30.0) == "ECC:t:30");
}

TEST_CASE("A rotary table is interpolated linearly round the turn", "[diagnose][open][names]") {
  const Machine m = public_machine();
  const std::vector<std::string> names{"ECC:t:0", "ECC:t:90", "ECC:t:180", "ECC:t:270"};
  const std::vector<double> values{0.0, 1e-5, 0.0, -1e-5};
  const comp::ModelLayout layout(m, names);
  const comp::ErrorFunctor<double> f(layout, values.data());
  const int c = m.index_of('C');
  auto at = [&](double deg) { return f(c, deg_to_rad(deg), false).motion_rad[2]; };
  CHECK(at(45) == Approx(0.5e-5));
  CHECK(at(90) == Approx(1e-5));
  CHECK(at(315) == Approx(-0.5e-5));  // between 270° and 360° = the node at 0°
  CHECK(at(-45) == Approx(-0.5e-5));  // the same angle one turn back
  CHECK(at(405) == Approx(0.5e-5));   // and one turn on
  CHECK(at(-720) == Approx(0.0).margin(1e-15));
  // a table without a node at 0: the last node joins the first across 0°
  const std::vector<std::string> two{"ECC:t:10", "ECC:t:350"};
  const std::vector<double> v2{2e-6, 4e-6};
  const comp::ModelLayout l2(m, two);
  const comp::ErrorFunctor<double> f2(l2, v2.data());
  CHECK(f2(c, deg_to_rad(0.0), false).motion_rad[2] == Approx(3e-6));
  CHECK(f2(c, deg_to_rad(180.0), false).motion_rad[2] == Approx(3e-6));
}

TEST_CASE("The model JSON carries ECC:h6 and C's table; the machine built from it uses them",
          "[diagnose][open][names]") {
  const Machine m = public_machine();
  comp::ModelFile file;
  file.machine = "public-clean";
  file.parameters.set("ECC:h6:cos", 3e-5);
  file.parameters.set("ECC:t:0", 0.0);
  file.parameters.set("ECC:t:180", 2e-5);
  const comp::ModelFile back = comp::parse_model_json(comp::format_model_json(file), "m.json", &m);
  CHECK(back.parameters.value_or("ECC:h6:cos", 0) == Approx(3e-5));
  CHECK(back.parameters.value_or("ECC:t:180", 0) == Approx(2e-5));
  // C at 90°: cos(6·90°) = −1 → −30 µrad, the table halfway from 0 to 180° → +10 µrad
  const comp::MachineModel model(m, back.parameters);
  const comp::ErrorFunctor<double> e = model.errors();
  CHECK(e(m.index_of('C'), deg_to_rad(90.0), false).motion_rad[2] == Approx(-3e-5 + 1e-5));
}
