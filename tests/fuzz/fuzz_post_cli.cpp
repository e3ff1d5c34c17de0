// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the whole `ncpost post` command line (tools/ncpost, cli::run), options and
// files. The fuzz input is cut into: a choice of options and values (from the documented option
// list, valid, edge and fuzzed values), the input program (APT or G-code, written to a file), and
// now and then a second fuzzed file given as the machine, model or dialect.
//
// Findings (besides what the sanitizers report):
//   - exit 4 (an internal fault) or an exit code outside 0-3;
//   - a failed run that leaves its output file (a partial or replaced program), or any run that
//     leaves a temporary `.tmp.*` file behind.
// Run with -close_fd_mask=3 (run.sh does) so the messages of the program do not flood the log.
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_main.hpp"

namespace fs = std::filesystem;

namespace {

const char* const kMachines[] = {
    NCPOST_SOURCE_DIR "/machines/ac-trunnion.toml",     NCPOST_SOURCE_DIR "/machines/haas-umc750.toml",
    NCPOST_SOURCE_DIR "/machines/gantry-bc-head.toml",  NCPOST_SOURCE_DIR "/machines/linuxcnc-xyzac-trt.toml",
    NCPOST_SOURCE_DIR "/machines/tsutsumi-zxfyac.toml", NCPOST_SOURCE_DIR "/machines/vmcl600.toml",
    NCPOST_SOURCE_DIR "/machines/trr-xy.toml",          NCPOST_SOURCE_DIR "/machines/bv100.toml",
};

struct Option {
  const char* name;
  std::vector<const char*> values;  ///< empty: a flag
};

const std::vector<Option>& options() {
  static const std::vector<Option> list = {
      {"--workpiece-origin", {"0,0,0", "10,-20,5", "1e308,0,0", "nan,0,0", "1,2", "a,b,c", ""}},
      {"--tool-length", {"0", "100", "2000", "-500", "nan", "1e400", "inf"}},
      {"--units", {"mm", "inch", "cm"}},
      {"--input-kind", {"auto", "cl", "machine", "rtcp", "x"}},
      {"--allow-unterminated", {}},
      {"--msys", {"ignore", "apply"}},
      {"--model",
       {NCPOST_SOURCE_DIR "/samples/measurements/ac-trunnion/model.json",
        NCPOST_SOURCE_DIR "/samples/measurements/vmcl600/model.json", "@file"}},
      {"--force", {}},
      {"--tolerance", {"0.01", "0.001", "none", "0", "-1", "1e-9", "nan", "100"}},
      {"--nonlinear", {"adaptive", "harmonic"}},
      {"--rtcp", {}},
      {"--dialect", {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain", "@file", "nope"}},
      {"--feed-mode", {"auto", "g93", "g94"}},
      {"--verify", {}},
      {"--retract", {"50", "0", "2000", "-1"}},
      {"--threads", {"1", "2", "3"}},
      {"--report", {"@report"}},
      {"--tolerence", {"0.01"}},
  };
  return list;
}

/// A scratch folder per process (libFuzzer may fork), the working directory, emptied after each run.
const fs::path& scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("ncpost-fuzz-cli-" + std::to_string(::getpid()));
    fs::create_directories(d);
    fs::current_path(d);  // a fuzzed relative path (e.g. --report G90) lands here, and is removed
    return d;
  }();
  return dir;
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider fdp(data, size);
  const fs::path& dir = scratch();
  const fs::path input = dir / (fdp.ConsumeBool() ? "in.cls" : "in.nc");
  const fs::path second = dir / "second.txt";
  const fs::path output = dir / "out.nc";
  const fs::path report = dir / "report.html";

  std::vector<std::string> args = {"ncpost", "post"};
  const int option_count = fdp.ConsumeIntegralInRange(0, 7);
  for (int i = 0; i < option_count; ++i) {
    const Option& o = options()[fdp.ConsumeIntegralInRange<std::size_t>(0, options().size() - 1)];
    args.emplace_back(o.name);
    if (o.values.empty()) continue;
    std::string value;
    if (fdp.ConsumeIntegralInRange(0, 7) == 0)
      value = fdp.ConsumeRandomLengthString(24);
    else
      value = o.values[fdp.ConsumeIntegralInRange<std::size_t>(0, o.values.size() - 1)];
    if (value == "@file") value = second.string();
    if (value == "@report") value = report.string();
    args.push_back(value);
  }
  switch (fdp.ConsumeIntegralInRange(0, 15)) {
    case 0:
      break;  // no machine: a usage error
    case 1:
      args.insert(args.end(), {"--machine", second.string()});
      break;
    default:
      args.insert(args.end(),
                  {"--machine", kMachines[fdp.ConsumeIntegralInRange<std::size_t>(0, std::size(kMachines) - 1)]});
  }
  const bool to_input = fdp.ConsumeIntegralInRange(0, 31) == 0;  // -o the input itself: refused
  args.insert(args.end(), {"-o", to_input ? input.string() : output.string()});
  const std::string second_text = fdp.ConsumeBool() ? fdp.ConsumeRandomLengthString(2048) : std::string();
  write_file(second, second_text);
  const std::string program = fdp.ConsumeRemainingBytesAsString();
  write_file(input, program);
  args.push_back(input.string());

  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (std::getenv("NCPOST_FUZZ_PRINT_ARGS")) {  // to reproduce a finding with the ncpost binary
    for (const std::string& a : args) std::fprintf(stderr, "'%s' ", a.c_str());
    std::fprintf(stderr, "\n");
    std::string keep = (dir / "..").string() + "/ncpost-fuzz-input";
    fs::copy_file(input, keep, fs::copy_options::overwrite_existing);
    fs::copy_file(second, keep + "-second", fs::copy_options::overwrite_existing);
  }
  const int rc = ncpost::cli::run(static_cast<int>(args.size()), argv.data());

  if (rc < 0 || rc > 3) {
    std::fprintf(stderr, "fuzz_post_cli: exit %d for:", rc);
    for (const std::string& a : args) std::fprintf(stderr, " '%s'", a.c_str());
    std::fprintf(stderr, "\n");
    std::abort();
  }
  if (rc != 0 && fs::exists(output)) {
    std::fprintf(stderr, "fuzz_post_cli: exit %d left an output file\n", rc);
    std::abort();
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename().string().find(".tmp") != std::string::npos) {
      std::fprintf(stderr, "fuzz_post_cli: temporary file left: %s\n", entry.path().c_str());
      std::abort();
    }
  }
  if (to_input && fs::exists(input) && fs::file_size(input) != program.size()) {
    std::fprintf(stderr, "fuzz_post_cli: the input was replaced by the output\n");
    std::abort();
  }
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
  return 0;
}
