// SPDX-License-Identifier: Apache-2.0
// Every real file of tests/data/real/ (SOURCES.md there) posts completely on a machine of its kind,
// with one output motion per input motion: exactly, less the motions that change no axis word
// (duplicates, which produce no block), where the file has no circles or cycles, counting a rapid
// written in two blocks (retract first / descend last) once; with more (expanded arcs and cycles)
// where it has.
#include <catch2/catch.hpp>

#include <fstream>
#include <memory>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/post.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

struct Case {
  const char* file;
  const char* machine;
  bool gcode;
  bool inch;
  bool expands;  ///< has CIRCLE / CYCLE records (or G2/G3 arcs)
};

std::unique_ptr<cl::Reader> open(std::istream& in, const Case& c, const Machine& m, const Setup& setup) {
  if (!c.gcode) {
    cl::ReaderOptions o;
    o.default_inch = c.inch;
    return std::make_unique<cl::AptReader>(in, c.file, o);
  }
  gcode::GcodeReaderOptions o;
  o.default_inch = c.inch;
  return std::make_unique<gcode::GcodeClReader>(in, c.file, m, setup, o);
}

/// Motions that repeat the previous one (tip, axis and programmed angles): no axis word changes.
/// After a tool change every word is written again (the changer moved the axes): not a repeat.
std::size_t duplicates(const Case& c, const Machine& m, const Setup& setup) {
  std::ifstream in(test::data(std::string("real/") + c.file), std::ios::binary);
  auto reader = open(in, c, m, setup);
  std::size_t n = 0;
  std::optional<cl::Motion> last;
  while (auto r = reader->next()) {
    if (std::holds_alternative<cl::ToolChange>(*r)) last.reset();
    const auto* mo = std::get_if<cl::Motion>(&*r);
    if (!mo) continue;
    if (last && (mo->point.tip_mm - last->point.tip_mm).norm() < 5e-5 &&
        (mo->point.axis - last->point.axis).norm() < 1e-9 &&
        mo->rotary_rad.has_value() == last->rotary_rad.has_value() &&
        (!mo->rotary_rad || (*mo->rotary_rad - *last->rotary_rad).norm() < 1e-9))
      ++n;
    last = *mo;
  }
  return n;
}

}  // namespace

TEST_CASE("every real file posts with one output motion per input motion") {
  const Case cases[] = {
      // NX inch parts have no UNITS record: read as inches (their NX posts write G20). nx_APT_Project2.txt
      // (inch) has helices of 7 turns (apt_reader_test, never_wrong_move_test): more points than motions.
      {"nx_APT_Variable_Axis.txt", "haas-umc750", false, true, false},
      {"nx_APT_SimpleMillPlane.txt", "haas-umc750", false, false, true},
      {"nx_APT_Zig_Zag_Smoothed.txt", "haas-umc750", false, false, true},
      {"catia_peening.aptsource", "ac-trunnion", false, false, false},
      {"creo_schruppen_1.ncl", "ac-trunnion", false, false, true},
      {"creo_bohren_1.ncl", "ac-trunnion", false, false, true},
      {"linuxcnc_impeller-7bl-xyzac.ngc", "linuxcnc-xyzac-trt", true, false, false},
      {"nx_PostProcessed_Variable_Axis.txt", "haas-umc750", true, false, false},
      {"nx_PostProcessed_SimpleMillPlane.txt", "haas-umc750", true, false, true},
      {"nx_PostProcessed_Zig_Zag_Smoothed.txt", "haas-umc750", true, false, true},
  };
  for (const Case& c : cases) {
    INFO(c.file << " on " << c.machine);
    const Machine m = load_machine(test::source(std::string("machines/") + c.machine + ".toml"));
    const Setup setup;
    std::ifstream in(test::data(std::string("real/") + c.file), std::ios::binary);
    REQUIRE(in);
    auto reader = open(in, c, m, setup);
    AtomicFile out("real_files_post_test_out.nc");
    std::string letters;
    for (const Axis& a : m.axes) letters += a.letter;
    NcWriter writer(out, dialect_named("fanuc"), letters);
    PostSummary s;
    REQUIRE_NOTHROW(s = post_program(*reader, c.file, NominalSolver(m, setup), writer, PostOptions{}));
    out.commit();
    const std::size_t dup = duplicates(c, m, setup);
    std::printf("%-40s %-20s %6zu motions -> %6zu blocks (%zu duplicates, %zu rapids in two blocks)\n", c.file,
                c.machine, s.motions_in, s.blocks_out, dup, s.rapid_splits);
    CHECK(s.motions_in > 0);
    const std::size_t motions_out = s.blocks_out - s.rapid_splits;
    if (c.expands)
      CHECK(motions_out >= s.motions_in - dup);
    else
      CHECK(motions_out + dup == s.motions_in);
  }
}

TEST_CASE("the LinuxCNC boat program does not fit the UMC-750's B travel: refused at its line 380 (exit 3)") {
  // B reaches -38.849 deg at line 380; the UMC-750 tilts B -35 .. 120 deg (issue 14, item 11)
  const Case c{"linuxcnc_boat-xyzbc.ngc", "haas-umc750", true, false, false};
  const Machine m = load_machine(test::source(std::string("machines/") + c.machine + ".toml"));
  const Setup setup;
  std::ifstream in(test::data(std::string("real/") + c.file), std::ios::binary);
  REQUIRE(in);
  auto reader = open(in, c, m, setup);
  AtomicFile out("real_files_post_test_boat.nc");
  NcWriter writer(out, dialect_named("fanuc"), "XYZBC");
  try {
    post_program(*reader, c.file, NominalSolver(m, setup), writer, PostOptions{});
    FAIL("the boat program posted on the UMC-750");
  } catch (const Infeasible& e) {
    CHECK_THAT(std::string(e.what()),
               Catch::StartsWith("linuxcnc_boat-xyzbc.ngc:380:1: B -38.849 deg, beyond the B axis limit -35.000 deg"));
  }
}
