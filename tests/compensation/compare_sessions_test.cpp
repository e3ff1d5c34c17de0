// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 5: `compare`, the same test before and after compensation. The ISO 230-2 figures of
// a small positioning line are worked out by hand here; the change and its U follow the rule of
// compare_sessions.hpp (U_Δ = √(U_first² + U_last²), proven when |Δ| > U_Δ).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <Eigen/Dense>

#include <cmath>
#include <string>

#include "ncpost/compensation/compare_report.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

Machine vmc() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml"); }
Machine ac() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml"); }

/// Targets 0 and 100 mm, two runs each way; readings (µm) scaled by `k`:
///   target 0:   up {1, 3}, down {0, 2};   target 100: up {10, 12}, down {6, 8}
std::string positioning_csv(double k, const std::string& date) {
  std::string csv = "# type: laser\n# axis: X\n# component: X\n# tool_point: 0, 0, 0\n# instrument_uncertainty: 0.5\n";
  if (!date.empty()) csv += "# date: " + date + "\n";
  csv += "t,run,approach,X,Y,Z,e_um\n";
  const double up0[] = {1, 3}, up1[] = {10, 12}, down1[] = {6, 8}, down0[] = {0, 2};
  int t = 0;
  const auto row = [&](int run, int approach, int x_mm, double e_um) {
    csv += fmt::format("{},{},{:+d},{},0,0,{}\n", t++, run, approach, x_mm, e_um);
  };
  for (int run = 0; run < 2; ++run) {
    row(run + 1, +1, 0, k * up0[run]);
    row(run + 1, +1, 100, k * up1[run]);
    row(run + 1, -1, 100, k * down1[run]);
    row(run + 1, -1, 0, k * down0[run]);
  }
  return csv;
}

MeasurementSet positioning(double k, const std::string& date, const std::string& file) {
  return parse_measurement_csv(positioning_csv(k, date), file, vmc());
}

const FigureTrend& trend(const Comparison& c, const std::string& name) {
  for (const FigureTrend& t : c.figures)
    if (t.name == name) return t;
  throw std::logic_error("no figure " + name);
}

/// A C-axis ballbar run: counter-clockwise C = 0…350°, then clockwise 350…0° (step 10°), with
/// ΔL = d cos 2C, the clockwise run lifted by h (the hysteresis).
MeasurementSet c_ballbar(double d_um, double h_um, double bar_mm) {
  std::string csv = fmt::format(
      "# type: ballbar\n# table_ball: 0, -100, 0\n# tool_ball: 0, 0, 0\n# bar_length: {}\n"
      "# instrument_uncertainty: 0.2\nt,X,Y,Z,A,C,L\n",
      bar_mm);
  int t = 0;
  const auto row = [&](int c_deg, double lift_um) {
    const double dl_um = d_um * std::cos(2.0 * c_deg * M_PI / 180.0) + lift_um;
    csv += fmt::format("{},0,0,0,0,{},{:.9f}\n", t++, c_deg, bar_mm + dl_um * 1e-3);
  };
  for (int c = 0; c < 360; c += 10) row(c, 0.0);
  for (int c = 340; c >= 0; c -= 10) row(c, h_um);
  return parse_measurement_csv(csv, "c.csv", ac());
}

/// ISO 230-4 G written here from its definition: r ≈ a + b cos θ + c sin θ by least squares, G the
/// range of r − b cos θ − c sin θ (µm).
double circular_deviation_um(const std::vector<double>& angle_rad, const std::vector<double>& r_um) {
  Eigen::MatrixXd J(angle_rad.size(), 3);
  Eigen::VectorXd y(angle_rad.size());
  for (std::size_t k = 0; k < angle_rad.size(); ++k) {
    J.row(Eigen::Index(k)) << 1.0, std::cos(angle_rad[k]), std::sin(angle_rad[k]);
    y[Eigen::Index(k)] = r_um[k];
  }
  const Eigen::Vector3d x = J.colPivHouseholderQr().solve(y);
  const Eigen::VectorXd d = y - J.rightCols(2) * x.tail(2);
  return d.maxCoeff() - d.minCoeff();
}

}  // namespace

TEST_CASE("compare: ISO 230-2 figures before and after, the change and its U", "[compare]") {
  const Machine m = vmc();
  const Session before = session_from_set(m, positioning(1.0, "2026-11-20T09:30", "before.csv"));
  const Session after = session_from_set(m, positioning(0.1, "2026-11-27T10:00", "after.csv"));
  Tolerances tol;
  tol.by_kind_um["A"] = 10.0;
  const Comparison c = compare_sessions({before, after}, tol);
  // by hand (before): x̄↑ 2, 11; x̄↓ 1, 7; s = √2 everywhere; B_i 1, 4; x̄_i 1.5, 9
  const double r2 = std::sqrt(2.0);
  const double A = (11 + 2 * r2) - (1 - 2 * r2), B = 4, E = 11 - 1, M = 9 - 1.5, R = 4 * r2 + 4;
  CHECK(*trend(c, "A").value[0] == Approx(A));
  CHECK(*trend(c, "B").value[0] == Approx(B));
  CHECK(*trend(c, "E").value[0] == Approx(E));
  CHECK(*trend(c, "M").value[0] == Approx(M));
  CHECK(*trend(c, "R").value[0] == Approx(R));
  CHECK(*trend(c, "A").value[1] == Approx(A / 10));  // every reading a tenth
  // U of A: instrument √2 × 0.25, repeatability √2 s_max / √2 = s_max (temperature not given)
  const double U_before = 2 * std::sqrt(0.125 + 2.0), U_after = 2 * std::sqrt(0.125 + 0.02);
  CHECK(trend(c, "A").expanded[0] == Approx(U_before));
  CHECK(trend(c, "A").expanded[1] == Approx(U_after));
  CHECK(trend(c, "A").change == Approx(A / 10 - A));
  CHECK(trend(c, "A").change_U == Approx(std::sqrt(U_before * U_before + U_after * U_after)));
  CHECK(trend(c, "A").outcome == "better (proven)");
  // ISO 14253-1 against A ≤ 10: 15.66 − 2.92 > 10 FAIL; 1.57 + 0.76 ≤ 10 PASS
  CHECK(*trend(c, "A").verdict[0] == Verdict::fail);
  CHECK(*trend(c, "A").verdict[1] == Verdict::pass);
  CHECK_FALSE(trend(c, "B").verdict[0]);  // no tolerance for B
  // dated: 7 days and 30 minutes apart
  REQUIRE(c.dated);
  CHECK(c.day[1] == Approx(7.0 + 0.5 / 24.0));
  const std::string html = compare_html(c, m.name, std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml");
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("days since the first session") != std::string::npos);
  CHECK(html.find("FAIL") != std::string::npos);
}

TEST_CASE("compare: a change within its U is not called proven", "[compare]") {
  CHECK(change_outcome(10.0, 9.0, 1.5) == "no change proven");
  CHECK(change_outcome(10.0, 8.0, 1.5) == "better (proven)");
  CHECK(change_outcome(5.0, 8.0, 1.5) == "worse (proven)");
  CHECK(change_outcome(-6.0, 3.0, 1.0) == "better (proven)");  // a signed error closer to 0
}

TEST_CASE("compare: sessions of another test or out of date order are refused", "[compare]") {
  const Machine m = vmc();
  const Session before = session_from_set(m, positioning(1.0, "2026-11-20", "before.csv"));
  const Session after = session_from_set(m, positioning(0.1, "2026-11-19", "after.csv"));
  CHECK_THROWS_WITH(compare_sessions({before, after}, {}), Catch::Contains("after.csv") && Catch::Contains("before"));
  Session other = after;
  other.date = "2026-11-21";
  other.test = "laser positioning of Y";
  CHECK_THROWS_WITH(compare_sessions({before, other}, {}), Catch::Contains("not the same test"));
  const Session undated = session_from_set(m, positioning(0.5, "", "mid.csv"));
  const Comparison c = compare_sessions({before, undated}, {});
  CHECK_FALSE(c.dated);
  CHECK(c.day == std::vector<double>{1.0, 2.0});
}

TEST_CASE("compare: ISO 8601 dates as days", "[compare]") {
  CHECK(*days_since_epoch("1970-01-01") == 0.0);
  CHECK(*days_since_epoch("2000-01-01") == 10957.0);  // 30 years with 7 leap days
  CHECK(*days_since_epoch("2000-03-01") == 10957.0 + 31 + 29);
  CHECK(*days_since_epoch("2000-01-02T12:00+02:00") == Approx(10958.0 + 10.0 / 24.0));
  CHECK(*days_since_epoch("2000-01-02T12:00:30Z") == Approx(10958.5 + 30.0 / 86400.0));
  CHECK_FALSE(days_since_epoch("20.11.2026"));
}

TEST_CASE("compare: a ballbar run both ways gives G of each direction and the hysteresis", "[compare]") {
  const Machine m = ac();
  const Session before = session_from_set(m, c_ballbar(5.0, 2.0, 100.0));
  const Session after = session_from_set(m, c_ballbar(1.0, 0.4, 100.0));
  const Comparison c = compare_sessions({before, after}, {});
  // the two runs sample the same angles: H is the lift h itself
  CHECK(*trend(c, "H").value[0] == Approx(2.0).margin(1e-6));
  CHECK(*trend(c, "H").value[1] == Approx(0.4).margin(1e-6));
  // one direction alone: the counter-clockwise run samples the whole turn evenly, so its
  // least-squares centre takes nothing from a 2/rev shape: G = 2d exactly
  CHECK(*trend(c, "G ccw").value[0] == Approx(10.0).epsilon(1e-6));
  // the clockwise run lacks 350°: G from the definition, computed here on its 35 points
  std::vector<double> cw_rad, cw_um;
  for (int deg = 340; deg >= 0; deg -= 10) {
    cw_rad.push_back(deg * M_PI / 180.0);
    cw_um.push_back(1.0 * std::cos(2.0 * deg * M_PI / 180.0) + 0.4);
  }
  CHECK(*trend(c, "G cw").value[1] == Approx(circular_deviation_um(cw_rad, cw_um)).epsilon(1e-6));
  CHECK(*trend(c, "G").value[0] > *trend(c, "G ccw").value[0]);  // both runs: the lift adds
  CHECK(trend(c, "G").outcome == "better (proven)");
  CHECK_THROWS_WITH(compare_sessions({before, session_from_set(m, c_ballbar(1.0, 0.4, 150.0))}, {}),
                    Catch::Contains("not the same test"));
}

TEST_CASE("compare: the command line, its page, and what it refuses", "[compare][cli]") {
  const std::string dir = test::make_temp_dir("ncpost_compare");
  const std::string machine = std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml";
  const std::string before = test::write_text_file(dir + "/before.csv", positioning_csv(1.0, "2026-11-20"));
  const std::string after = test::write_text_file(dir + "/after.csv", positioning_csv(0.1, "2026-11-27"));
  const std::string log = dir + "/log.txt", html = dir + "/cmp.html";
  const std::string args = "compare --machine " + machine + " --tolerance A=10 ";
  REQUIRE(test::run_ncpost(args + "--html " + html + " " + before + " " + after, log) == 0);
  const std::string out = test::read_text_file(log);
  CHECK(out.find("A (µm): 15.657 ± 2.915 [FAIL]; 1.566 ± 0.762 [PASS]; -14.091 ± 3.013: better (proven)") !=
        std::string::npos);
  CHECK(test::read_text_file(html).find("<svg") != std::string::npos);
  // in the wrong order by date, another test, models mixed with data, one session: nothing compared
  CHECK(test::run_ncpost(args + after + " " + before, log) == 2);
  CHECK(test::read_text_file(log).find("before.csv") != std::string::npos);
  std::string other = positioning_csv(0.5, "2026-11-28");
  other.replace(other.find("# tool_point: 0, 0, 0"), 21, "# tool_point: 0, 0, 50");  // another point measured
  CHECK(test::run_ncpost(args + before + " " + test::write_text_file(dir + "/other.csv", other), log) == 2);
  CHECK(test::read_text_file(log).find("not the same test") != std::string::npos);
  CHECK(test::run_ncpost(
            args + before + " " + std::string(NCPOST_SOURCE_DIR) + "/samples/measurements/vmcl600/model.json", log) ==
        1);
  CHECK(test::run_ncpost(args + before, log) == 1);
}
