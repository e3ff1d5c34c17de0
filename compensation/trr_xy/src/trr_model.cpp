// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ncpost::trr {

namespace {

/// The position of `"name"` in the file's text (line and column; 0 when not found).
SourcePosition where_in(const std::string& text, const std::string& path, const std::string& quoted) {
  SourcePosition where{path, 0, 0};
  const auto pos = text.find(quoted);
  if (pos != std::string::npos) {
    where.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
    where.column = static_cast<int>(pos - text.rfind('\n', pos));
  }
  return where;
}

/// True for the parameters in rad (ar, at, gp); the others are in mm (docs/trr-xy.md).
bool is_angle(const std::string& name) {
  return name.rfind("ar_", 0) == 0 || name.rfind("at_", 0) == 0 || name.rfind("gp_", 0) == 0;
}

void fail_or_warn(const ModelChecks& c, const SourcePosition& where, const std::string& what) {
  if (!c.force)
    throw InputError(where,
                     what + "; check that this is the model of this machine, or pass --force to apply it anyway");
  if (c.warnings) c.warnings->push_back(fmt::format("{}:{}: {}", where.file, where.line, what));
}

}  // namespace

Errors errors_from_model(const comp::ModelFile& model, const std::string& text, const std::string& path) {
  Errors e;
  const auto& names = model.parameters.names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int k = Errors::index_of(names[i]);
    if (k < 0) {
      throw InputError(where_in(text, path, "\"" + names[i] + "\""),
                       fmt::format("parameter '{}' is not a TRR-XY error parameter (expected <param>_<chain> with "
                                   "param dr, dt, ar, at, ds, gp, dl, drs, dts or dzs and chain a, b or c)",
                                   names[i]));
    }
    e[k] = model.parameters.values()[i];
  }
  return e;
}

Errors read_errors_json(const std::string& path, const ModelChecks& checks) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the model file");
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const comp::ModelFile model = comp::parse_model_json(text, path, nullptr);
  const Errors e = errors_from_model(model, text, path);
  if (!checks.machine_name.empty() && model.machine != checks.machine_name)
    fail_or_warn(checks, where_in(text, path, "\"machine\""),
                 model.machine.empty()
                     ? fmt::format("the model names no machine; this job's machine is '{}'", checks.machine_name)
                     : fmt::format("the model is for machine '{}', this job's machine is '{}'", model.machine,
                                   checks.machine_name));
  const auto& names = model.parameters.names();
  const auto& values = model.parameters.values();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const bool angle = is_angle(names[i]);
    const double bound = angle ? checks.angle_rad : checks.length_mm;
    if (std::abs(values[i]) <= bound) continue;
    fail_or_warn(checks, where_in(text, path, "\"" + names[i] + "\""),
                 fmt::format("{} = {:.6g} {} is not a plausible error of the TRR-XY (bound ±{:g} {})", names[i],
                             values[i], angle ? "rad" : "mm", bound, angle ? "rad" : "mm"));
  }
  return e;
}

comp::ModelFile model_from_errors(const Errors& e, const std::string& machine_name) {
  comp::ModelFile m;
  m.machine = machine_name;
  for (int k = 0; k < kParameterCount; ++k) m.parameters.set(Errors::name(k), e[k]);
  return m;
}

}  // namespace ncpost::trr
