// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 1: every axis-table export holds the whole model of the axis, every family of it
// (tables of a rotary and of a linear axis, harmonics, scale and bow, reversal; coupled terms listed
// as left out, never as held). Each file is read back here by a reader of that control's semantics
// written for this test (not the product's code), applied at 1000 commanded positions per direction,
// and the axis's actual position from the model's chain (test::actual_position) must land on the
// commanded one within 0.05 µm (µrad); ISG's list is in whole counts of 0.1 µm / 0.0001° (1.745 µrad),
// so half a count is added to its bound there.
//   LinuxCNC COMP_FILE_TYPE 1 (usrmotintf.cc, control.c compute_screw_comp): rows of three numbers up
//     to the first other line; the trim of the direction of motion, linear in the commanded position
//     between the nominals, ends held, added to the commanded position.
//   SINUMERIK LEC ($AA_ENC_COMP, K3 "Interpolatory compensation"): values at MIN + k·STEP, linear in
//     the measured position, ends held (modulo: round the turn); the loop settles where m + c(m) = n.
//   ISG kw.ssfk (TF5200 "Leadscrew error compensation"): pos / neg values at the setpoints, linear in
//     the axis position, ends held (modulo: round the turn); the drive is commanded n − value.
// The bug this guards (issue 25): ECC:t was written as two rows of zero while "Held: ECC:t (36 nodes)".
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <regex>
#include <sstream>

#include "axis_actual_position.hpp"
#include "cli_run.hpp"
#include "ncpost/compensation/control_entries.hpp"
#include "ncpost/compensation/export_isg.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/export_siemens.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "shipped_machines.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

constexpr double kHalfTurnRad = 3.14159265358979323846;
constexpr double kDeg = kHalfTurnRad / 180.0;
/// The bound of issue 25: 0.05 µm (mm) or 0.05 µrad (rad).
constexpr double kBoundMm = 0.05e-3;
constexpr double kBoundRad = 0.05e-6;

/// The drive command for commanded position n (mm or rad), moving down or up; and whether the file
/// holds the moving-down direction (a SINUMERIK LEC table is one for both: moving up only).
struct Applied {
  std::function<double(double, bool)> motor;
  bool both_directions = true;
};

/// Linear interpolation in a table of (x, y), the end values held beyond it.
double interpolate_held(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  for (std::size_t i = 1; i < x.size(); ++i)
    if (at < x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y.back();
}

/// LinuxCNC: rows of three numbers until the first other line; units mm or degrees.
Applied read_linuxcnc(const std::string& text, bool rotary) {
  std::vector<double> nominal, forward, reverse;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    double r[3];
    if (std::sscanf(line.c_str(), "%lf %lf %lf", &r[0], &r[1], &r[2]) != 3) break;
    nominal.push_back(r[0]);
    forward.push_back(r[1]);
    reverse.push_back(r[2]);
  }
  REQUIRE(nominal.size() >= 2);
  REQUIRE(nominal.size() <= 256);
  for (std::size_t i = 1; i < nominal.size(); ++i) REQUIRE(nominal[i - 1] < nominal[i]);
  const double unit = rotary ? kDeg : 1.0;
  return {[=](double n, bool falling) {
            const double n_file = n / unit;
            return (n_file + interpolate_held(nominal, falling ? reverse : forward, n_file)) * unit;
          },
          true};
}

/// SINUMERIK: the assignments $AA_ENC_COMP[0,N,AX], _STEP, _MIN, _MAX, _IS_MODULO.
Applied read_siemens(const std::string& text, bool rotary) {
  std::map<int, double> values;
  std::map<std::string, double> param;
  const std::regex value(R"(^\$AA_ENC_COMP\[0,(\d+),\w+\]=(\S+)$)");
  const std::regex named(R"(^\$AA_ENC_COMP_(STEP|MIN|MAX|IS_MODULO)\[0,\w+\]=(\S+)$)");
  std::istringstream in(text);
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_match(line, m, value)) values[std::stoi(m[1])] = std::stod(m[2]);
    if (std::regex_match(line, m, named)) param[m[1]] = std::stod(m[2]);
  }
  REQUIRE(param.count("STEP") == 1);
  REQUIRE(param.count("MIN") == 1);
  std::vector<double> x, y;
  for (int k = 0; k < static_cast<int>(values.size()); ++k) {
    REQUIRE(values.count(k) == 1);
    x.push_back(param["MIN"] + k * param["STEP"]);
    y.push_back(values[k]);
  }
  REQUIRE(x.back() == Approx(param["MAX"]).margin(1e-6));
  const bool modulo = param["IS_MODULO"] == 1.0;
  const double unit = rotary ? kDeg : 1.0;
  auto c = [=](double m_file) {
    if (modulo) m_file = x.front() + std::fmod(std::fmod(m_file - x.front(), 360.0) + 360.0, 360.0);
    return interpolate_held(x, y, m_file);
  };
  return {[=](double n, bool) {
            const double n_file = n / unit;
            double m_file = n_file;
            for (int it = 0; it < 100; ++it) m_file = n_file - c(m_file);  // the loop: m + c(m) = n
            return m_file * unit;
          },
          false};
}

/// ISG: `key value` lines, `#` comments; kw.ssfk.table[i].setpoint/pos/neg in counts.
Applied read_isg(const std::string& text, bool rotary) {
  std::map<std::string, double> header;
  std::map<int, double> setpoint, pos, neg;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key, word;
    if (!(words >> key) || key[0] == '#' || key == "kopf.log_achs_name") continue;
    REQUIRE(static_cast<bool>(words >> word));
    int i = 0;
    char field[16] = {};
    if (std::sscanf(key.c_str(), "kw.ssfk.table[%d].%15s", &i, field) == 2)
      (std::string(field) == "setpoint" ? setpoint : std::string(field) == "pos" ? pos : neg)[i] = std::stod(word);
    else
      header[key] = std::stod(word);
  }
  REQUIRE(header.at("kw.ssfk.unit") == 1.0);
  REQUIRE(header.at("kw.ssfk.bilateral") == 1.0);
  std::vector<double> s, p, q;
  for (int i = 0; i < static_cast<int>(header.at("kw.ssfk.kw_nr_max")); ++i) {
    s.push_back(setpoint.at(i));
    p.push_back(pos.at(i));
    q.push_back(neg.at(i));
  }
  const bool modulo = header.at("kw.ssfk.modulo") == 1.0;
  const double per_count = rotary ? 1e-4 * kDeg : 1e-4;  // rad or mm per count
  return {[=](double n, bool falling) {
            double x = n / per_count;
            if (modulo) {
              const double span = s.back() - s.front();
              x = s.front() + std::fmod(std::fmod(x - s.front(), span) + span, span);
            }
            return n - interpolate_held(s, falling ? q : p, x) * per_count;
          },
          true};
}

struct Residual {
  double with_file = 0.0;
  double model_only = 0.0;
};

/// 1000 commanded positions over the travel (off the files' own points), each direction the file holds.
Residual residual(const MachineModel& model, char letter, const Applied& applied) {
  const int axis = model.machine().index_of(letter);
  const Axis& a = model.machine().axes[axis];
  const double lo = a.limits ? a.limits->min : 0.0, hi = a.limits ? a.limits->max : 2.0 * kHalfTurnRad;
  auto off = [&](double actual, double n) {
    return std::abs(a.is_rotary() ? std::remainder(actual - n, 2.0 * kHalfTurnRad) : actual - n);
  };
  Residual r;
  for (int k = 0; k < 1000; ++k) {
    const double n = lo + (hi - lo) * (k + 0.371) / 1000.0;
    for (bool falling : {false, true}) {
      if (falling && !applied.both_directions) continue;
      r.with_file =
          std::max(r.with_file, off(test::actual_position(model, axis, applied.motor(n, falling), falling), n));
      r.model_only = std::max(r.model_only, off(test::actual_position(model, axis, n, falling), n));
    }
  }
  return r;
}

/// The "Held:" note line of a file, and everything after "Left out" to the end of the notes.
std::string note_line(const std::string& text, const std::string& start) {
  const std::size_t at = text.find(start);
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

struct Family {
  std::string name;
  const Machine* machine;
  char axis;
  ErrorParameters p;
  std::vector<std::string> held;      ///< effects the files must list as held (and hold)
  std::vector<std::string> left_out;  ///< effects every file must list as left out, never as held
};

/// ECC:t of issue 25: 36 nodes, a local error of C around 120° (76 µrad at 120°), zero elsewhere.
ErrorParameters ecc_table() {
  ErrorParameters p;
  for (int deg = 0; deg < 360; deg += 10) {
    const double v = deg == 110 ? 30e-6 : deg == 120 ? 76e-6 : deg == 130 ? 21e-6 : 0.0;
    p.set(fmt::format("ECC:t:{}", deg), v);
  }
  return p;
}

std::vector<Family> families() {
  std::vector<Family> f;
  f.push_back({"rotary table ECC:t (issue 25)", &test::ac_trunnion(), 'C', ecc_table(), {"ECC:t (36 nodes)"}, {}});
  {
    ErrorParameters p;  // A travels -120..120: the node at 345° is the one at -15°
    for (int deg = 0; deg < 360; deg += 15)
      p.set(fmt::format("EAA:t:{}", deg), deg == 345 ? 40e-6 : deg == 90 ? -25e-6 : 5e-6 * std::sin(deg * kDeg));
    f.push_back({"rotary table EAA:t of a limited axis", &test::ac_trunnion(), 'A', p, {"EAA:t (24 nodes)"}, {}});
  }
  {
    ErrorParameters p;
    for (int k = -11; k <= 11; ++k) p.set(fmt::format("EXX:t:{}", 25 * k), 1e-3 * ((k * 7 + 3) % 5) - 0.002);
    p.set("EYX:t:0", 0.001);  // straightness: left out
    f.push_back({"linear table EXX:t", &test::vmcl600(), 'X', p, {"EXX:t (23 nodes)"}, {"EYX:t"}});
  }
  {
    ErrorParameters p;
    p.set("ECC:h1:cos", 40e-6);
    p.set("ECC:h2:sin", -25e-6);
    p.set("ECC:h4:cos", 8e-6);
    p.set("ECC:h7:sin", 3e-6);
    f.push_back({"harmonics ECC:h", &test::ac_trunnion(), 'C', p, {"ECC:h1", "ECC:h2", "ECC:h4", "ECC:h7"}, {}});
  }
  {
    ErrorParameters p;
    p.set("EYY:p1", 40e-6);   // scale: 40 µm/m
    p.set("EYY:p2", 1.5e-7);  // bow
    p.set("EYY:p3", -2e-10);
    f.push_back({"scale and bow EYY:p", &test::vmcl600(), 'Y', p, {"EYY:p1", "EYY:p2", "EYY:p3"}, {}});
  }
  {
    ErrorParameters p = ecc_table();
    p.set("reversal:C", 30e-6);
    f.push_back({"reversal with a table, C", &test::ac_trunnion(), 'C', p, {"ECC:t (36 nodes)", "reversal:C"}, {}});
  }
  {
    ErrorParameters p;
    p.set("EZZ:p1", -25e-6);
    p.set("reversal:Z", 0.003);
    f.push_back({"reversal with a scale error, Z", &test::vmcl600(), 'Z', p, {"EZZ:p1", "reversal:Z"}, {}});
  }
  {
    ErrorParameters p;
    p.set("ECC:h1:sin", 30e-6);
    p.set("EC0C:A:p1", 20e-6);  // the zero of C changes with A: not a table of C
    p.set("EA0C:A:p1", 15e-6);
    f.push_back({"coupled terms (left out) with a harmonic",
                 &test::ac_trunnion(),
                 'C',
                 p,
                 {"ECC:h1"},
                 {"EC0C:A:p1", "EA0C:A:p1"}});
  }
  return f;
}

void check_notes(const std::string& text, const Family& f, const std::vector<std::string>& left_out_too,
                 const std::string& comment) {
  const std::string held = note_line(text, comment + " Held: ");
  INFO(held);
  for (const std::string& h : f.held) CHECK(held.find(h) != std::string::npos);
  std::vector<std::string> out = f.left_out;
  out.insert(out.end(), left_out_too.begin(), left_out_too.end());
  const std::size_t left = text.find("Left out (NOT compensated by this file)");
  for (const std::string& l : out) {
    INFO(l);
    CHECK(held.find(l) == std::string::npos);  // never as held
    CHECK(left != std::string::npos);
    if (left != std::string::npos) CHECK(text.find(l + " (", left) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("export families: every format holds every family within 0.05 µm (µrad), read back independently",
          "[export]") {
  for (const Family& f : families()) {
    const MachineModel model(*f.machine, f.p);
    const bool rotary = f.machine->axes[f.machine->index_of(f.axis)].is_rotary();
    const double bound = rotary ? kBoundRad : kBoundMm;
    const double half_count = rotary ? 0.5e-4 * kDeg : 0.5e-4;
    const double micro = rotary ? 1e6 : 1e3;
    const ExportSource source{"model.json", "machine.toml", "test"};
    INFO(f.name);

    const LinuxcncCompTable lt = linuxcnc_comp_table(model, f.axis);
    const std::string lfile = format_linuxcnc_comp(lt, model, source);
    const Residual lr = residual(model, f.axis, read_linuxcnc(lfile, rotary));
    check_notes(lfile, f, {}, "#");

    const SiemensLecTable st = siemens_lec_table(model, f.axis);
    const std::string sfile = format_siemens_lec(st, model, source);
    const Residual sr = residual(model, f.axis, read_siemens(sfile, rotary));
    std::vector<std::string> siemens_left;
    for (const std::string& h : f.held)
      if (h.rfind("reversal", 0) == 0) siemens_left.push_back(h);  // one table for both directions
    Family siemens_family = f;
    std::erase_if(siemens_family.held, [](const std::string& h) { return h.rfind("reversal", 0) == 0; });
    check_notes(sfile, siemens_family, siemens_left, ";");

    const IsgLsecTable it = isg_lsec_table(model, f.axis);
    const std::string ifile = format_isg_lsec(it, model, source);
    const Residual ir = residual(model, f.axis, read_isg(ifile, rotary));
    check_notes(ifile, f, {}, "#");

    fmt::print("{:<45} model {:8.3f} | linuxcnc {:.4f} | siemens {:.4f} | isg {:.4f} {}\n", f.name,
               lr.model_only * micro, lr.with_file * micro, sr.with_file * micro, ir.with_file * micro,
               rotary ? "µrad" : "µm");
    CHECK(lr.model_only > 100.0 * bound);  // the model's own error is there to compensate
    CHECK(lr.with_file <= bound);
    CHECK(sr.with_file <= bound);
    CHECK(ir.with_file <= bound + half_count);
    // the files' own round trip, in their notes, agrees with the independent one
    CHECK(lt.landing.with_file <= bound);
    CHECK(st.landing.with_file <= bound);
  }
}

TEST_CASE("export families: the model of ECC:t is the documented periodic interpolation of its nodes", "[export]") {
  // what the residuals above are measured against, checked by hand: 76 µrad at 120°, linear to 0 at
  // 140° through 21 µrad at 130°, 0 from 140° round to 100°
  const MachineModel model(test::ac_trunnion(), ecc_table());
  const int c = test::ac_trunnion().index_of('C');
  auto hand = [](double deg) {
    const std::vector<double> x{100, 110, 120, 130, 140}, y{0, 30e-6, 76e-6, 21e-6, 0};
    return deg < 100 || deg > 140 ? 0.0 : interpolate_held(x, y, deg);
  };
  for (double deg : {0.0, 95.0, 105.0, 115.0, 120.0, 125.0, 133.0, 200.0, 359.0})
    CHECK(std::remainder(test::actual_position(model, c, deg * kDeg, false) - deg * kDeg, 2.0 * kHalfTurnRad) ==
          Approx(hand(deg)).margin(1e-12));
}

TEST_CASE("export ECC:t on the command line: the table in all three files and in the report's entries",
          "[export][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ncpost_export_ecct_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  ModelFile file;
  file.machine = "ac-trunnion";
  file.axes = model_axes(test::ac_trunnion());
  file.parameters = ecc_table();
  {
    std::FILE* out = std::fopen((d + "model.json").c_str(), "w");
    REQUIRE(out != nullptr);
    std::fputs(format_model_json(file).c_str(), out);
    std::fclose(out);
  }
  const MachineModel model(test::ac_trunnion(), file.parameters);
  const std::string machine = " --machine " + test::source("machines/ac-trunnion.toml");
  for (const std::string format : {"linuxcnc", "siemens", "isg"}) {
    INFO(format);
    REQUIRE(test::run_ncpost(
                "export --format " + format + " --axis C" + machine + " -o " + d + format + " " + d + "model.json",
                d + "log") == 0);
    const std::string text = test::read_text_file(d + format);
    const Applied applied = format == "linuxcnc"  ? read_linuxcnc(text, true)
                            : format == "siemens" ? read_siemens(text, true)
                                                  : read_isg(text, true);
    const Residual r = residual(model, 'C', applied);
    CHECK(r.model_only == Approx(76e-6).margin(1e-6));  // the bump is the model's error ...
    CHECK(r.with_file <= (format == "isg" ? kBoundRad + 0.5e-4 * kDeg : kBoundRad));  // ... and the file takes it
    CHECK(test::read_text_file(d + "log").find("round trip: the axis lands within") != std::string::npos);
  }
  // LinuxCNC by hand: the drive passes the node at 120° (76 µrad) at the commanded 120° + 76 µrad,
  // where the trim is -76 µrad = -0.004354479°
  const std::string l = test::read_text_file(d + "linuxcnc");
  CHECK(l.find("120.004354 -0.004354479 -0.004354479\n") != std::string::npos);
  // the report's "as entered in the control" block: the very rows of the file
  const ControlEntries entries = control_entries(model, ControlFormat::linuxcnc);
  bool found = false;
  for (const ControlEntryFile& f : entries.files)
    if (f.heading == "axis C") {
      found = true;
      CHECK(f.lines == linuxcnc_comp_lines(linuxcnc_comp_table(model, 'C')));
      CHECK(f.lines.size() > 36);
      CHECK(std::find(f.lines.begin(), f.lines.end(), "120.004354 -0.004354479 -0.004354479") != f.lines.end());
    }
  CHECK(found);
  fs::remove_all(dir);
}

TEST_CASE("export: a linear table is held at its end values beyond its nodes, said in the file and on stderr",
          "[export][cli]") {
  ErrorParameters p;
  p.set("EXX:t:-200", -0.004);
  p.set("EXX:t:0", 0.0);
  p.set("EXX:t:250", 0.006);
  const MachineModel model(test::vmcl600(), p);  // X travels -300..300
  const LinuxcncCompTable t = linuxcnc_comp_table(model, 'X');
  // held, not extrapolated: the end rows' trims are the end nodes' (-(-4 µm) and -6 µm)
  CHECK(t.rows.front()[0] == Approx(-300.0));
  CHECK(t.rows.front()[1] == Approx(0.004).margin(1e-9));
  CHECK(t.rows.back()[1] == Approx(-0.006).margin(1e-9));
  REQUIRE(t.axis.held_beyond.size() == 2);
  const std::string text = format_linuxcnc_comp(t, model, {"m.json", "", "test"});
  CHECK(text.find("# Beyond the measured travel: EXX:t: from -300 to -200 mm") != std::string::npos);
  CHECK(text.find("# Beyond the measured travel: EXX:t: from 250 to 300 mm") != std::string::npos);
  const std::string siemens = format_siemens_lec(siemens_lec_table(model, 'X'), model, {"m.json", "", "test"});
  CHECK(siemens.find("; Beyond the measured travel: EXX:t: from 250 to 300 mm") != std::string::npos);

  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ncpost_export_held_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  ModelFile file;
  file.machine = "vmcl600";
  file.axes = model_axes(test::vmcl600());
  file.parameters = p;
  {
    std::FILE* out = std::fopen((d + "model.json").c_str(), "w");
    REQUIRE(out != nullptr);
    std::fputs(format_model_json(file).c_str(), out);
    std::fclose(out);
  }
  REQUIRE(test::run_ncpost("export --format isg --axis X --machine " + test::source("machines/vmcl600.toml") + " -o " +
                               d + "x.lis " + d + "model.json",
                           d + "log") == 0);
  const std::string log = test::read_text_file(d + "log");
  CHECK(log.find("note: beyond the measured travel: EXX:t: from 250 to 300 mm") != std::string::npos);
  fs::remove_all(dir);
}
