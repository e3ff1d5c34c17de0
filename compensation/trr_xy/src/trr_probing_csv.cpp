// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_probing_csv.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::trr {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    field.erase(0, field.find_first_not_of(" \t\r"));
    field.erase(field.find_last_not_of(" \t\r") + 1);
    out.push_back(field);
  }
  return out;
}

}  // namespace

ProbingData read_probing_csv(const std::string& path, bool plan) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the measurement file");
  ProbingData d;
  std::string line;
  int n = 0;
  std::vector<std::string> header;
  std::map<std::string, int> col;
  const std::vector<std::string> needed = plan ? std::vector<std::string>{"X", "Y", "U", "V", "W"}
                                               : std::vector<std::string>{"X", "Y", "U", "V", "W", "dx", "dy", "dz"};
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string key = line.substr(1, colon - 1), value = line.substr(colon + 1);
        key.erase(0, key.find_first_not_of(' '));
        key.erase(key.find_last_not_of(' ') + 1);
        value.erase(0, value.find_first_not_of(' '));
        d.metadata[key] = value;
      }
      continue;
    }
    if (header.empty()) {
      header = split(line);
      for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = static_cast<int>(i);
      for (const auto& c : needed)
        if (!col.count(c))
          throw InputError(
              {path, n, 1},
              fmt::format("header: missing column '{}' (expected t,X,Y,U,V,W,stylus{})", c, plan ? "" : ",dx,dy,dz"),
              line);
      continue;
    }
    const std::vector<std::string> f = split(line);
    if (f.size() != header.size())
      throw InputError({path, n, 1}, fmt::format("{} fields, the header has {}", f.size(), header.size()), line);
    auto num = [&](const std::string& c, double fallback) {
      const auto it = col.find(c);
      if (it == col.end()) return fallback;
      const std::string& s = f[static_cast<std::size_t>(it->second)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || *end != '\0' || !std::isfinite(v))
        throw InputError({path, n, 1}, fmt::format("column '{}': expected a finite number, got '{}'", c, s), line);
      return v;
    };
    ProbingRow r;
    r.t_s = num("t", 0.0);
    r.command.table_mm = Eigen::Vector2d(num("X", 0), num("Y", 0));
    r.command.slider_mm = Vec3d(num("U", 0), num("V", 0), num("W", 0));
    r.stylus_mm = num("stylus", 0.0);
    if (!plan) r.deviation_mm = Vec3d(num("dx", 0), num("dy", 0), num("dz", 0));
    d.rows.push_back(r);
  }
  if (header.empty()) throw InputError({path, n, 0}, "no header line (expected t,X,Y,U,V,W,stylus...)");
  return d;
}

std::string format_probing_csv(const ProbingData& d, bool plan) {
  std::string s;
  std::map<std::string, std::string> meta = d.metadata;
  meta["type"] = "sphere";
  s += "# type: sphere\n";
  for (const auto& [k, v] : meta)
    if (k != "type") s += fmt::format("# {}: {}\n", k, v);
  s += plan ? "t,X,Y,U,V,W,stylus\n" : "t,X,Y,U,V,W,stylus,dx,dy,dz\n";
  for (const ProbingRow& r : d.rows) {
    s += fmt::format("{:.2f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}", r.t_s, r.command.table_mm.x(),
                     r.command.table_mm.y(), r.command.slider_mm.x(), r.command.slider_mm.y(), r.command.slider_mm.z(),
                     r.stylus_mm);
    if (!plan) s += fmt::format(",{:.7f},{:.7f},{:.7f}", r.deviation_mm.x(), r.deviation_mm.y(), r.deviation_mm.z());
    s += "\n";
  }
  return s;
}

std::vector<ProbeMeasurement> measurements(const ProbingData& d) {
  std::vector<ProbeMeasurement> out;
  for (const ProbingRow& r : d.rows) out.push_back({r.command.slider_mm, r.stylus_mm, r.deviation_mm});
  return out;
}

}  // namespace ncpost::trr
