// SPDX-License-Identifier: Apache-2.0
// Text written into NC programs (issue 14 item 13): one sanitiser per dialect, so that no file
// name, machine name, PARTNO or comment becomes a block, ends the tape or carries non-ASCII.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/postproc/write/nc_text.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace ncpost;

namespace {

const char* const kDialects[] = {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"};

// a newline and a CR with a block behind each, comment terminators, '%', UTF-8, a C1 and a DEL
const std::string kHostile = "part) G0 Z-500 (\nG0 Z-500\r\nM30\n%\n; x\xc2\xb5m \xe2\x80\x94 \xc2\x9b\x7f end";

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// True if `line` is one whole comment of the dialect and nothing else.
bool is_comment_line(const std::string& line, const Dialect& d) {
  if (d.comments == Dialect::Comments::parentheses)
    return line.size() >= 2 && line.front() == '(' && line.back() == ')' &&
           line.find_first_of("()", 1) == line.size() - 1;
  std::string body = line;
  if (d.line_numbers) body = line.substr(line.find(' ') + 1);  // "7 ; text"
  return body.rfind("; ", 0) == 0;
}

}  // namespace

TEST_CASE("nc_comment_text: the rules of each dialect") {
  for (const char* name : kDialects) {
    INFO(name);
    const Dialect d = dialect_named(name);
    const std::string s = nc_comment_text(kHostile, d);
    for (const char c : s) {
      CHECK(static_cast<unsigned char>(c) >= 0x20);
      CHECK(static_cast<unsigned char>(c) < 0x7F);
    }
    CHECK(s.find('%') == std::string::npos);
    CHECK(s.find(';') == std::string::npos);
    if (d.comments == Dialect::Comments::parentheses) CHECK(s.find_first_of("()") == std::string::npos);
    // one '?' per non-ASCII character: µ, the dash, the C1 control (DEL becomes a space)
    CHECK(s == (d.comments == Dialect::Comments::parentheses ? "part] G0 Z-500 [ G0 Z-500  M30     x?m ? ?  end"
                                                             : "part) G0 Z-500 ( G0 Z-500  M30     x?m ? ?  end"));
    const std::string long_text = "from /a/very/long/folder/" + std::string(300, 'f') + "/part.cls";
    const std::string cut = nc_comment_text(long_text, d);
    CHECK(cut.size() == d.comment_rules.max_chars);
    CHECK_THAT(
        cut, Catch::StartsWith("from /a/very/long/folder/") && Catch::EndsWith("/part.cls") && Catch::Contains("..."));
    CHECK(nc_program_name("my part\n%1", d) == "MYPART1");
    CHECK(nc_program_name("\xc2\xb5\n", d) == "NCPOST");
  }
}

TEST_CASE("NcWriter: hostile comments and program names stay comments in every dialect") {
  const fs::path dir = fs::temp_directory_path() / "ncpost_nc_text_test";
  fs::create_directories(dir);
  for (const char* name : kDialects) {
    INFO(name);
    const Dialect d = dialect_named(name);
    const std::string path = (dir / (std::string(name) + ".nc")).string();
    {
      AtomicFile out(path);
      NcWriter w(out, d, "XYZAC");
      w.begin_program("NC\nG0 Z-500", {kHostile, "machine " + kHostile});
      w.comment(kHostile);
      NcMotion m;
      m.values = {1, 2, 3, 0, 0};
      m.feed = 100;
      w.motion(m);
      w.end_program();
      out.commit();
    }
    const std::string text = slurp(path);
    for (const char c : text) CHECK(bool((c >= 0x20 && c < 0x7F) || c == '\n'));
    const auto lines = lines_of(text);
    int comments = 0, percent = 0;
    for (const auto& l : lines) {
      if (l == "%")
        ++percent;
      else
        CHECK(l.find('%') == std::string::npos);
      if (is_comment_line(l, d)) ++comments;
      const bool in_comment =
          l.find("G0 Z-500") == std::string::npos || is_comment_line(l, d) || l.rfind("O0001 (", 0) == 0;
      CHECK(in_comment);
    }
    CHECK(comments == 3);  // the two header comments and the comment: no line of them became a block
    CHECK(percent == (d.percent_framing ? 2 : 0));
    if (d.name == "heidenhain") CHECK(lines.front() == "0 BEGIN PGM NCG0Z500 MM");
    if (d.name == "fanuc" || d.name == "haas") CHECK(lines[1] == "O0001 (NCG0Z500)");
  }
  fs::remove_all(dir);
}

TEST_CASE("post: a file name with a newline and a hostile PARTNO never become blocks") {
  const fs::path dir = fs::temp_directory_path() / "ncpost_nc_text_post";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cl = (dir / "part\nG0 Z-500\n%.cls").string();
  {
    std::ofstream out(cl);
    out << "PARTNO/ab) G0 Z-500 (% \xc3\xbc\nPPRINT/x) M30 "
           "(\nFEDRAT/500\nGOTO/0,0,10,0,0,1\nGOTO/10,0,10,0,0,1\nFINI\n";
  }
  for (const char* name : kDialects) {
    INFO(name);
    const Dialect d = dialect_named(name);
    const std::string nc = (dir / "out.nc").string();
    const std::string cmd = std::string(NCPOST_BINARY) + " post --machine '" +
                            test::source("machines/ac-trunnion.toml") + "' --dialect " + name + " -o '" + nc + "' '" +
                            cl + "' 2>/dev/null";
    REQUIRE(WEXITSTATUS(std::system(cmd.c_str())) == 0);
    const std::string text = slurp(nc);
    for (const char c : text) CHECK(bool((c >= 0x20 && c < 0x7F) || c == '\n'));
    for (const auto& l : lines_of(text)) {
      if (l.find("Z-500") != std::string::npos || l.find("M30 ") != std::string::npos) CHECK(is_comment_line(l, d));
      if (l != "%") CHECK(l.find('%') == std::string::npos);
    }
    CHECK_THAT(text, Catch::Contains(d.comments == Dialect::Comments::parentheses ? "PARTNO ab] G0 Z-500 [  ?"
                                                                                  : "PARTNO ab) G0 Z-500 (  ?"));
  }
  fs::remove_all(dir);
}
