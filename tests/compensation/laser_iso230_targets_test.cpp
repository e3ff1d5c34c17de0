// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 5: the ISO 230-2 table per target (x̄↑, x̄↓, 2s, B_i, x̄_i, R↑_i, R↓_i, R_i), each
// value worked out by hand from the readings written here.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "ncpost/compensation/laser_iso230_targets.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

TEST_CASE("ISO 230-2 per target: means, 2s, reversal and repeatability of each target", "[laser][iso230]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml");
  // three runs; at 0 mm: up 0, 1, 2 and down -1, 0, 1; at 50 mm: up 4, 4, 7 and down 2, 2, 2 (µm)
  const std::string csv =
      "# type: laser\n# axis: Y\n# component: Y\n# tool_point: 0, 0, 0\nt,run,approach,X,Y,Z,e_um\n"
      "0,1,+1,0,0,0,0\n1,1,+1,0,50,0,4\n2,1,-1,0,50,0,2\n3,1,-1,0,0,0,-1\n"
      "4,2,+1,0,0,0,1\n5,2,+1,0,50,0,4\n6,2,-1,0,50,0,2\n7,2,-1,0,0,0,0\n"
      "8,3,+1,0,0,0,2\n9,3,+1,0,50,0,7\n10,3,-1,0,50,0,2\n11,3,-1,0,0,0,1\n";
  const Iso230Figures g = iso230_2_figures(parse_measurement_csv(csv, "y.csv", m));
  REQUIRE(g.ok);
  const std::vector<Iso230TargetRow> rows = iso230_2_target_rows(g);
  REQUIRE(rows.size() == 2);
  // 0 mm: x̄↑ 1, s↑ 1; x̄↓ 0, s↓ 1; B 1; x̄ 0.5; R↑ = R↓ = 4; R = max(2 + 2 + 1, 4, 4) = 5
  CHECK(rows[0].target_mm == 0.0);
  CHECK(rows[0].runs_up == 3);
  CHECK(rows[0].mean_up_um == Approx(1.0));
  CHECK(rows[0].mean_down_um == Approx(0.0).margin(1e-12));
  CHECK(rows[0].two_s_up_um == Approx(2.0));
  CHECK(rows[0].reversal_um == Approx(1.0));
  CHECK(rows[0].mean_bidirectional_um == Approx(0.5));
  CHECK(rows[0].repeat_up_um == Approx(4.0));
  CHECK(rows[0].repeat_um == Approx(5.0));
  // 50 mm: x̄↑ 5, s↑ = √((1 + 1 + 4) / 2) = √3; x̄↓ 2, s↓ 0; B 3; x̄ 3.5;
  //        R↑ = 4√3 = 6.928; R↓ 0; R = max(2√3 + 0 + 3 = 6.464, 6.928, 0) = 6.928
  CHECK(rows[1].target_mm == 50.0);
  CHECK(rows[1].mean_up_um == Approx(5.0));
  CHECK(rows[1].two_s_up_um == Approx(2.0 * std::sqrt(3.0)));
  CHECK(rows[1].two_s_down_um == Approx(0.0).margin(1e-12));
  CHECK(rows[1].reversal_um == Approx(3.0));
  CHECK(rows[1].mean_bidirectional_um == Approx(3.5));
  CHECK(rows[1].repeat_down_um == Approx(0.0).margin(1e-12));
  CHECK(rows[1].repeat_um == Approx(4.0 * std::sqrt(3.0)));
  // the line's R is the largest R_i
  CHECK(g.repeatability_R_um == Approx(4.0 * std::sqrt(3.0)));
  const std::string html = iso230_2_target_table_html(g);
  CHECK(html.find("<td>50.000</td><td>3/3</td><td>+5.000</td><td>+2.000</td><td>3.464</td><td>0.000</td><td>+3.000</td>"
                  "<td>+3.500</td><td>6.928</td><td>0.000</td><td>6.928</td>") != std::string::npos);
}
