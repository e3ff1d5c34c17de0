// SPDX-License-Identifier: Apache-2.0
// TRR-XY sensitivity maps (docs/trr-xy.md, seed 004 section 5): the seed's conclusions — angular
// errors dominate position and length errors; chains b and c repeat chain a turned by 120° and
// 240° — and the CLI's JSON and HTML.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ncpost/compensation/trr_sensitivity.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

const SensitivityResult& result() {
  static const SensitivityResult r = sensitivity(load_trr_xy_machine(test::source("machines/trr-xy.toml")));
  return r;
}

double largest(const ParameterMap& m) { return std::max(std::abs(m.max_um), std::abs(m.min_um)); }

}  // namespace

TEST_CASE("all 30 parameters, in the spec's order, over the hemisphere's 0-30 deg cap") {
  const SensitivityResult& r = result();
  REQUIRE(r.maps.size() == 30);
  CHECK(r.maps[0].name == "dr_a");
  CHECK(r.maps[6].name == "dl_a");
  CHECK(r.maps[29].name == "dzs_c");
  CHECK(r.points.size() == 1 + 30 * 360);
  for (const SurfacePoint& p : r.points) {
    CHECK(p.polar_rad <= deg_to_rad(30.0) + 1e-12);
    CHECK(std::abs(p.cl.tip_mm.norm() - 120.0) < 1e-9);
  }
}

TEST_CASE("angular errors dominate the position and length errors (seed 004, table 3)") {
  const SensitivityResult& r = result();
  double smallest_angle = 1e300, largest_length = 0.0;
  for (int k = 0; k < kParameterCount; ++k) {
    if (Errors::is_angle(k))
      smallest_angle = std::min(smallest_angle, largest(r.maps[static_cast<std::size_t>(k)]));
    else
      largest_length = std::max(largest_length, largest(r.maps[static_cast<std::size_t>(k)]));
  }
  WARN("smallest angular effect " << smallest_angle << " um, largest length effect " << largest_length << " um");
  CHECK(smallest_angle > largest_length);
  // the pin-axis error gp (link plane tilted) dominates everything
  CHECK(largest(r.maps[5]) > 3.0 * largest(r.maps[3]));
}

TEST_CASE("chains b and c repeat chain a turned by 120 and 240 deg") {
  const SensitivityResult& r = result();
  const int sectors = 360;
  for (int f = 0; f < kPerChain; ++f) {
    const ParameterMap& a = r.maps[static_cast<std::size_t>(f)];
    for (int c = 1; c < 3; ++c) {
      const ParameterMap& o = r.maps[static_cast<std::size_t>(c * kPerChain + f)];
      INFO(o.name);
      CHECK(o.max_um == Approx(a.max_um).margin(1e-6));
      CHECK(o.min_um == Approx(a.min_um).margin(1e-6));
      double worst = std::abs(o.deviation_um[0] - a.deviation_um[0]);
      for (int ring = 1; ring <= 30; ++ring)
        for (int j = 0; j < sectors; ++j) {
          const std::size_t ia = static_cast<std::size_t>(1 + (ring - 1) * sectors + j);
          const std::size_t io = static_cast<std::size_t>(1 + (ring - 1) * sectors + (j + 120 * c) % sectors);
          worst = std::max(worst, std::abs(o.deviation_um[io] - a.deviation_um[ia]));
        }
      CHECK(worst < 1e-5);
    }
  }
}

TEST_CASE(
    "chain a's maps are mirror-symmetric about its radial plane (XZ), or antisymmetric for the tangential errors") {
  // the seed: the error pattern lies along the line through screw a and the midpoint of b-c
  const SensitivityResult& r = result();
  const int sectors = 360;
  for (int f = 0; f < kPerChain; ++f) {
    const ParameterMap& a = r.maps[static_cast<std::size_t>(f)];
    const bool tangential = f == 1 || f == 3 || f == 5 || f == 8;  // dt, at, gp, dts turn the pattern over
    const double sign = tangential ? -1.0 : 1.0;
    INFO(a.name);
    double worst = 0.0;
    for (int ring = 1; ring <= 30; ++ring)
      for (int j = 0; j < sectors; ++j) {
        const std::size_t i = static_cast<std::size_t>(1 + (ring - 1) * sectors + j);
        const std::size_t m = static_cast<std::size_t>(1 + (ring - 1) * sectors + (sectors - j) % sectors);
        worst = std::max(worst, std::abs(a.deviation_um[i] - sign * a.deviation_um[m]));
      }
    CHECK(worst < 1e-3 + 3e-3 * largest(a));  // up to the second-order part (see below)
  }
}

TEST_CASE(
    "first order: twice the error, twice the deviation; a ball-joint offset along the plate normal is absorbed by the "
    "set-up at home") {
  const trr::Machine m = load_trr_xy_machine(test::source("machines/trr-xy.toml"));
  SensitivityOptions o;
  o.polar_step_deg = 5.0;
  o.azimuth_step_deg = 10.0;
  SensitivityOptions o2 = o;
  o2.length_step_mm = 0.02;
  o2.angle_step_deg = 0.02;
  const SensitivityResult r1 = sensitivity(m, o), r2 = sensitivity(m, o2);
  for (int k = 0; k < kParameterCount; ++k) {
    INFO(Errors::name(k));
    const auto& a = r1.maps[static_cast<std::size_t>(k)].deviation_um;
    const auto& b = r2.maps[static_cast<std::size_t>(k)].deviation_um;
    // second-order terms: under 0.3 % of the map's largest deviation (gp: 0.11 %)
    const double allowed = 3e-3 * largest(r1.maps[static_cast<std::size_t>(k)]) + 1e-3;
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(b[i] - 2.0 * a[i]));
    CHECK(worst < allowed);
  }
  // dzs moves one ball joint along the plate normal: the three joints still span a plane, the
  // plate is the same body with another frame, and its motion relative to home is unchanged
  CHECK(largest(result().maps[9]) < 1e-3);
  CHECK(largest(result().maps[0]) > 0.1);
}

TEST_CASE("ncpost sensitivity: JSON of the spec and a self-contained HTML page") {
  const std::string cmd = std::string(NCPOST_BINARY) + " sensitivity --machine " +
                          test::source("machines/trr-xy.toml") +
                          " --json trr_sens.json --html trr_sens.html >trr_sens.out 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  std::ifstream in("trr_sens.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  REQUIRE(j.size() == 30);
  const SensitivityResult& r = result();
  for (const ParameterMap& m : r.maps) {
    INFO(m.name);
    REQUIRE(j.contains(m.name));
    CHECK(j[m.name]["max_um"].get<double>() == Approx(m.max_um).margin(1e-6));
    CHECK(j[m.name]["min_um"].get<double>() == Approx(m.min_um).margin(1e-6));
    CHECK(j[m.name]["range_um"].get<double>() == Approx(m.max_um - m.min_um).margin(2e-6));
  }
  std::ifstream h("trr_sens.html");
  std::stringstream s;
  s << h.rdbuf();
  const std::string html = s.str();
  std::size_t svgs = 0;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  CHECK(svgs == 60);  // a map and its colour bar per parameter
  // dzs has no first-order effect: its three maps are drawn as zero (white), not saturated noise
  std::size_t no_effect = 0;
  for (auto p = html.find(">no effect</text>"); p != std::string::npos; p = html.find(">no effect</text>", p + 1))
    ++no_effect;
  CHECK(no_effect == 3);
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("http") == std::string::npos);  // nothing fetched
}
