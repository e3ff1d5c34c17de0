// SPDX-License-Identifier: Apache-2.0
// ncpost preview --html: a self-contained report (no scripts, no network) that headless Chromium
// renders; the screenshot must exist and show more than a blank page. Skipped (with a message)
// when chromium is not installed.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "test_paths.hpp"
#include "text_file.hpp"

namespace {

bool have_chromium() { return std::system("command -v chromium > /dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE("ncpost preview --html renders in headless Chromium", "[preview][html]") {
  const std::string scenario = ncpost::test::data("scenarios/public-clean/");
  const std::string cmd = std::string(NCPOST_BINARY) + " preview --machine " + scenario +
                          "machine.toml --workpiece-origin 0,0,80 --html preview_html_test.html " + scenario +
                          "path.cls > preview_html_test.out 2>&1";
  REQUIRE(WEXITSTATUS(std::system(cmd.c_str())) == 0);
  const std::string html = ncpost::test::read_text_file("preview_html_test.html");
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("Worst blocks") != std::string::npos);
  CHECK(html.find("GOTO/") != std::string::npos);                          // source lines of the worst blocks
  CHECK(html.find("<script") == std::string::npos);                        // no scripts
  CHECK(html.find("http://") == html.find("http://www.w3.org/2000/svg"));  // only the SVG namespace
  CHECK(html.find("https://") == std::string::npos);

  if (!have_chromium()) {
    WARN("chromium not installed (apt-get install chromium): screenshot check skipped");
    return;
  }
  std::remove("preview_html_test.png");
  char cwd[4096];
  REQUIRE(getcwd(cwd, sizeof cwd) != nullptr);
  const std::string shot =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-background-networking "
      "--disable-component-update --no-first-run --screenshot=preview_html_test.png --window-size=1200,2000 file://" +
      std::string(cwd) + "/preview_html_test.html > preview_html_chromium.log 2>&1";
  std::system(shot.c_str());
  const std::string png = ncpost::test::read_text_file("preview_html_test.png");
  REQUIRE(png.size() > 8);
  CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  // a blank 1200x2000 page compresses to a few kB; the charts make it far larger
  CHECK(png.size() > 50000);
}
