// SPDX-License-Identifier: Apache-2.0
// Hostile input and file safety of the ncpost executable (issue 14): what -o may replace, output
// paths that are inputs, signals, stdin, numeric options, escaped messages, misspelt options.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

/// A fresh folder of its own for each test case.
struct Folder {
  fs::path dir;
  explicit Folder(const std::string& name) : dir(fs::temp_directory_path() / ("ncpost_cli_safety_" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Folder() { fs::remove_all(dir); }
  std::string operator/(const std::string& f) const { return (dir / f).string(); }
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// Runs a bash script in the folder; its exit code.
int script(const Folder& f, const std::string& text) {
  write(f / "script.sh", "cd '" + f.dir.string() + "'\n" + text + "\n");
  const int rc = std::system(("bash '" + (f / "script.sh") + "'").c_str());
  return WEXITSTATUS(rc);
}

/// Runs `ncpost <args>` through bash (so args may hold redirections); stderr into *err.
int run(const Folder& f, const std::string& args, std::string* err = nullptr) {
  const int rc = script(f, std::string(NCPOST_BINARY) + " " + args + " 2>stderr.txt");
  if (err) *err = slurp(f / "stderr.txt");
  return rc;
}

std::size_t temp_files_in(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) ++n;
  return n;
}

const std::string kMachine = ncpost::test::source("machines/ac-trunnion.toml");
const std::string kCl = ncpost::test::source("samples/hemisphere_5axis.cls");

}  // namespace

TEST_CASE("-o refuses devices and FIFOs without waiting, keeps links and modes") {
  Folder f("output_kinds");
  std::string err;
  CHECK(run(f, "post --machine " + kMachine + " -o /dev/null " + kCl, &err) == 2);
  CHECK_THAT(err, Catch::Contains("ncpost: error: cannot write '/dev/null': it is a device"));
  CHECK(fs::is_character_file("/dev/null"));

  REQUIRE(::mkfifo((f / "fifo").c_str(), 0644) == 0);
  // a FIFO opened for writing would block until a reader comes: the refusal must come first
  CHECK(run(f, "post --machine " + kMachine + " -o fifo " + kCl, &err) == 2);
  CHECK_THAT(err, Catch::Contains("it is a FIFO"));
  CHECK(fs::is_fifo(f / "fifo"));

  fs::create_directory(f / "folder");
  CHECK(run(f, "post --machine " + kMachine + " -o folder " + kCl, &err) == 2);
  CHECK_THAT(err, Catch::Contains("it is a folder"));

  // a link: its target is replaced, the link stays, the target keeps its mode
  write(f / "target.nc", "OLD\n");
  ::chmod((f / "target.nc").c_str(), 0640);
  fs::create_symlink("target.nc", f / "link.nc");
  REQUIRE(run(f, "post --machine " + kMachine + " -o link.nc " + kCl, &err) == 0);
  CHECK(fs::is_symlink(f / "link.nc"));
  CHECK(fs::read_symlink(f / "link.nc") == "target.nc");
  CHECK(slurp(f / "target.nc").rfind("%\nO0001 (NCPOST)\n", 0) == 0);
  CHECK((fs::status(f / "target.nc").permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  CHECK(temp_files_in(f.dir) == 0);
}

TEST_CASE("a missing or unwritable output folder: exit 2 with the reason, never 'internal error'") {
  Folder f("folders");
  std::string err;
  CHECK(run(f, "post --machine " + kMachine + " -o nowhere/x.nc " + kCl, &err) == 2);
  CHECK_THAT(err, Catch::Contains("the folder 'nowhere' does not exist") && Catch::Contains("No such file"));
  CHECK_THAT(err, !Catch::Contains("internal"));
  // found before the run: a --report into a missing folder leaves -o untouched
  write(f / "out.nc", "GOOD\n");
  CHECK(run(f, "post --machine " + kMachine + " --report nowhere/r.html -o out.nc " + kCl, &err) == 2);
  CHECK(slurp(f / "out.nc") == "GOOD\n");
  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directory(f / "ro");
    ::chmod((f / "ro").c_str(), 0555);
    CHECK(run(f, "post --machine " + kMachine + " -o ro/x.nc " + kCl, &err) == 2);
    CHECK_THAT(err, Catch::Contains("Permission denied"));
  }
}

TEST_CASE("an output that is an input is refused before anything is written") {
  Folder f("same_file");
  std::string err;
  fs::copy_file(kCl, f / "h.cls");
  const std::string original = slurp(f / "h.cls");
  CHECK(run(f, "post --machine " + kMachine + " -o h.cls h.cls", &err) == 1);
  CHECK_THAT(err, Catch::Contains("-o 'h.cls' is the same file as INPUT 'h.cls'"));
  fs::create_symlink("h.cls", f / "alias.nc");  // another name, same device and inode
  CHECK(run(f, "post --machine " + kMachine + " -o alias.nc ./h.cls", &err) == 1);
  fs::create_hard_link(f / "h.cls", f / "hard.nc");
  CHECK(run(f, "post --machine " + kMachine + " -o hard.nc h.cls", &err) == 1);
  CHECK(run(f, "post --machine " + kMachine + " -o h.cls --machine h.cls h.cls", &err) != 0);
  CHECK(slurp(f / "h.cls") == original);

  CHECK(run(f, "post --machine " + kMachine + " --report x.nc -o x.nc h.cls", &err) == 1);
  CHECK_THAT(err, Catch::Contains("--report 'x.nc' is the same file as -o 'x.nc'"));
  CHECK_FALSE(fs::exists(f / "x.nc"));
  CHECK(run(f, "preview --machine " + kMachine + " --csv p --html ./p h.cls", &err) == 1);
  CHECK_FALSE(fs::exists(f / "p"));
  write(f / "sp.csv", "x\n");
  CHECK(run(f, "simulate --machine " + kMachine + " --model m.json -o sp.csv sp.csv", &err) == 1);
  CHECK(slurp(f / "sp.csv") == "x\n");
  CHECK(temp_files_in(f.dir) == 0);
}

TEST_CASE("SIGTERM, SIGINT, SIGHUP remove the temporary file; the previous output stays") {
  Folder f("signals");
  // a CL file long enough to be stopped mid-run (about 200,000 motions)
  {
    std::ofstream big(f / "big.cls");
    big << "FEDRAT/1000\n";
    for (int i = 0; i < 200000; ++i) big << "GOTO/" << (i % 200) * 0.5 << "," << (i / 200) * 0.1 << ",0,0,0,1\n";
  }
  for (const char* sig : {"TERM", "INT", "HUP"}) {
    INFO(sig);
    write(f / "out.nc", "PREVIOUS\n");
    // stdin from a pipe that stays open 30 s: the run is inside its input spool or its post
    // set -m: without job control bash starts background commands with SIGINT ignored
    script(f, "set -m\n" + std::string(NCPOST_BINARY) + " post --machine " + kMachine +
                  " --tolerance 0.0001 --verify -o out.nc big.cls 2>/dev/null & p=$!\n" +
                  // wait (up to 30 s: a loaded machine) until the run writes its temporary file
                  "for i in $(seq 300); do ls | grep -q '[.]tmp[.]' && break; sleep 0.1; done\n" +
                  "ls | grep -c '[.]tmp[.]' > during.txt; kill -" + sig + " $p; wait $p; echo $? > rc.txt");
    CHECK(slurp(f / "during.txt") == "1\n");  // the run was writing when stopped
    CHECK(temp_files_in(f.dir) == 0);
    CHECK(slurp(f / "out.nc") == "PREVIOUS\n");
    CHECK(std::atoi(slurp(f / "rc.txt").c_str()) > 128);  // ended by the signal
  }
  // the spool of standard input too (TMPDIR: the spool goes into this test's folder)
  write(f / "out.nc", "PREVIOUS\n");
  // (the writer is killed at the end: a `sleep 30` left behind holds ctest's pipes for 30 s)
  script(f, "export TMPDIR=$PWD; mkfifo in.fifo\n(cat big.cls; exec sleep 30) > in.fifo 2>/dev/null & w=$!\n" +
                std::string(NCPOST_BINARY) + " post --machine " + kMachine +
                " -o out.nc - < in.fifo 2>/dev/null & p=$!\n" +
                "for i in $(seq 300); do ls | grep -q ncpost-input && break; sleep 0.1; done\n" +
                "ls | grep -c ncpost-input > during.txt; kill -TERM $p; wait $p; echo $? > rc.txt\n" +
                "kill $w; wait $w 2>/dev/null; true");
  CHECK(slurp(f / "during.txt") == "1\n");
  CHECK(std::atoi(slurp(f / "rc.txt").c_str()) > 128);
  for (const auto& e : fs::directory_iterator(f.dir)) CHECK(e.path().filename().string().rfind("ncpost-input", 0) != 0);
  CHECK(slurp(f / "out.nc") == "PREVIOUS\n");
}

TEST_CASE("input from standard input, /dev/stdin and a process substitution") {
  Folder f("stdin");
  std::string err;
  REQUIRE(run(f, "post --machine " + kMachine + " -o file.nc " + kCl, &err) == 0);
  const std::string expected = slurp(f / "file.nc");
  for (const std::string in : {"- < " + kCl, "/dev/stdin < " + kCl, "<(cat " + kCl + ")", "- --verify < " + kCl}) {
    INFO(in);
    REQUIRE(run(f, "post --machine " + kMachine + " -o piped.nc " + in, &err) == 0);
    const std::string got = slurp(f / "piped.nc");
    // the same program; only the header's input name (line 3) differs
    const auto after_line3 = [](const std::string& s) {
      std::size_t at = 0;
      for (int k = 0; k < 3; ++k) at = s.find('\n', at) + 1;
      return s.substr(at);
    };
    CHECK(after_line3(got) == after_line3(expected));
    CHECK(got.size() > 10000);
  }
  // G-code on stdin: its kind found from the content
  write(f / "prog.nc", "G90 G21\nG0 X10 Y0 Z50 A0 C0\nG1 X20 F500\nM30\n");
  CHECK(run(f, "post --machine " + kMachine + " --input-kind auto -o g.nc - < prog.nc", &err) == 0);
  CHECK_THAT(slurp(f / "g.nc"), Catch::Contains("X20.0000"));
  for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
    CHECK(e.path().filename().string().rfind("ncpost-input.", 0) != 0);  // spools removed
}

TEST_CASE("numeric options: finite and in range, the message names the option and repeats the text") {
  Folder f("numbers");
  std::string err;
  const std::string post = "post --machine " + kMachine + " ";
  for (const std::string bad :
       {"--tool-length nan", "--tool-length -500", "--tool-length 1e308", "--tolerance 1e400", "--tolerance 0",
        "--tolerance inf", "--retract -1", "--workpiece-origin 1e308,0,0", "--workpiece-origin nan,0,0"}) {
    INFO(bad);
    CHECK(run(f, post + bad + " -o x.nc " + kCl, &err) == 1);
    CHECK_THAT(err, Catch::Contains(bad.substr(0, bad.find(' ')) + ":"));
    CHECK(err.size() < 300);  // never a 300-digit number
    CHECK_FALSE(fs::exists(f / "x.nc"));
  }
  CHECK(run(f, post + "--tolerance 1e400 " + kCl, &err) == 1);
  CHECK_THAT(err, Catch::Contains("--tolerance: expected a finite number above 0 and at most 10 (mm), got '1e400'"));
  CHECK(run(f, post + "--tool-length -500 " + kCl, &err) == 1);
  CHECK_THAT(err, Catch::Contains("--tool-length: expected a finite number from 0 to 2000 (mm), got '-500'"));
  CHECK(run(f, "simulate --machine " + kMachine + " --model m.json --noise-um nan -o o.csv p.csv", &err) == 1);
  CHECK_THAT(err, Catch::Contains("--noise-um:"));
  CHECK(run(f, "plan ballbar-4axis --machine " + kMachine + " --bar-length 1e400 -o plan", &err) == 1);
  CHECK_THAT(err, Catch::Contains("--bar-length:"));
}

TEST_CASE("messages: misspelt options get a suggestion, control characters are escaped") {
  Folder f("messages");
  std::string err;
  CHECK(run(f, "post --machine " + kMachine + " --tolerence 0.01 " + kCl, &err) == 1);
  CHECK(err == "ncpost: error: unknown option --tolerence; did you mean --tolerance?\n");
  CHECK(run(f, "psot --machine " + kMachine, &err) == 1);
  CHECK_THAT(err, Catch::Contains("unknown subcommand 'psot'; did you mean post?"));
  CHECK(run(f, "post --machine " + kMachine + " --dialect $'\\x1b[2Jfanuc' " + kCl, &err) == 1);
  CHECK_THAT(err, Catch::Contains("\\x1B[2Jfanuc"));
  CHECK(err.find('\x1b') == std::string::npos);
  // a CL line with an escape sequence in a bad number: escaped, and the caret under the character
  write(f / "esc.cls",
        "GOTO/1,2,3\nGOTO/1,\xc2\x9b"
        "2,3\n");
  CHECK(run(f, "post --machine " + kMachine + " esc.cls", &err) == 2);
  CHECK_THAT(err, Catch::StartsWith("ncpost: error: esc.cls:2:"));
  CHECK(err.find("\xc2\x9b") == std::string::npos);  // the C1 control (CSI) never reaches the terminal
}

TEST_CASE("exit 4 is not used for user errors; help texts cite the README, not internal documents") {
  Folder f("help");
  std::string err;
  for (const char* sub : {"post", "preview", "identify", "simulate", "plan", "sensitivity"}) {
    INFO(sub);
    REQUIRE(run(f, std::string(sub) + " --help > help.txt", &err) == 0);
    const std::string help = slurp(f / "help.txt");
    CHECK_THAT(help, !Catch::Contains("formats.md") && !Catch::Contains("cli.md") && !Catch::Contains("spec/"));
    CHECK_THAT(help, !Catch::Contains(" um"));
    CHECK_THAT(help, !Catch::Contains("seed 00") && !Catch::Contains("issue "));
  }
}
