// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/model_json.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/model_plausibility.hpp"
#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {
namespace {

using nlohmann::ordered_json;

/// 1-based line and column of a byte offset.
SourcePosition position_of(const std::string& text, std::size_t offset, const std::string& file) {
  SourcePosition p{file, 1, 1};
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

/// Where the key "name" first appears (for messages), or line 0.
SourcePosition position_of_key(const std::string& text, const std::string& key, const std::string& file) {
  const auto at = text.find("\"" + key + "\"");
  if (at == std::string::npos) return {file, 0, 0};
  return position_of(text, at + 1, file);
}

ErrorParameters read_parameters(const ordered_json& obj, const std::string& what, const std::string& text,
                                const std::string& file, const Machine* machine) {
  if (!obj.is_object())
    throw InputError(position_of_key(text, what, file), fmt::format("'{}' must be an object name → number", what));
  ErrorParameters p;
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const SourcePosition at = position_of_key(text, it.key(), file);
    if (!it.value().is_number())
      throw InputError(at, fmt::format("{}: the value of '{}' must be a number (mm or rad)", what, it.key()));
    const double v = it.value().get<double>();
    if (!std::isfinite(v)) throw InputError(at, fmt::format("{}: '{}' is not finite", what, it.key()));
    if (machine) {
      const ParseResult r = parse_parameter_name(it.key(), *machine);
      if (!r.spec) throw InputError(at, fmt::format("unknown error parameter '{}': {}", it.key(), r.error));
    }
    p.set(it.key(), v);
  }
  return p;
}

/// Where the number nlohmann could not hold ("number overflow parsing '1e400'") stands in the text.
SourcePosition position_of_overflow(const std::string& text, const std::string& message, const std::string& file) {
  const auto open = message.find('\'');
  const auto close = open == std::string::npos ? open : message.find('\'', open + 1);
  if (close == std::string::npos) return {file, 1, 1};
  const auto at = text.find(message.substr(open + 1, close - open - 1));
  return at == std::string::npos ? SourcePosition{file, 1, 1} : position_of(text, at, file);
}

/// The machine, its axes and the parameter values: the checks of a model applied to `machine`.
void check_for_machine(ModelFile& m, const std::string& text, const std::string& file, const Machine& machine,
                       const ModelReadOptions& options) {
  std::vector<InputError> problems;
  if (m.machine != machine.name)
    problems.emplace_back(
        position_of_key(text, "machine", file).line > 0 ? position_of_key(text, "machine", file)
                                                        : SourcePosition{file, 1, 1},
        m.machine.empty()
            ? fmt::format(
                  "the model names no machine (key \"machine\"); it may be of another machine than '{}': "
                  "identify it on this machine, or add \"machine\": \"{}\" if it is (--force applies it anyway)",
                  machine.name, machine.name)
            : fmt::format("the model is of machine '{}', not '{}': its errors are another machine's; identify this "
                          "machine or give its model (--force applies it anyway)",
                          m.machine, machine.name));
  if (!m.axes.empty() && m.axes != model_axes(machine))
    problems.emplace_back(position_of_key(text, "axes", file),
                          fmt::format("the model is of axes {}, the machine '{}' has {}: give this machine's model "
                                      "(--force applies it anyway)",
                                      m.axes, machine.name, model_axes(machine)));
  for (std::size_t i = 0; i < m.parameters.size(); ++i) {
    const std::string& name = m.parameters.names()[i];
    const ParseResult r = parse_parameter_name(name, machine);
    if (!r.spec) continue;  // refused by read_parameters already
    const std::string why = implausibility(*r.spec, machine, m.parameters.values()[i]);
    if (!why.empty())
      problems.emplace_back(position_of_key(text, name, file),
                            fmt::format("'{}' {}: a wrong unit (mm/rad, not µm/µrad or degrees) or a wrong file; "
                                        "correct the value (--force applies it anyway)",
                                        name, why));
  }
  if (problems.empty()) return;
  if (!options.force) throw problems.front();
  for (const auto& p : problems) m.warnings.push_back(p.what());
}

}  // namespace

std::string model_axes(const Machine& machine) {
  std::string s;
  for (const auto& a : machine.axes) s += a.letter;
  return s;
}

ModelFile parse_model_json(const std::string& text, const std::string& file, const Machine* machine,
                           const ModelReadOptions& options) {
  ordered_json j;
  try {
    j = ordered_json::parse(text);
  } catch (const ordered_json::parse_error& e) {
    throw InputError(position_of(text, e.byte > 0 ? e.byte - 1 : 0, file), fmt::format("not valid JSON: {}", e.what()));
  } catch (const ordered_json::out_of_range& e) {  // 1e400: beyond double
    throw InputError(position_of_overflow(text, e.what(), file),
                     fmt::format("a number beyond the range of a double ({}): values are mm and rad, a few digits; "
                                 "correct the number",
                                 e.what()));
  } catch (const ordered_json::exception& e) {
    throw InputError({file, 1, 1}, fmt::format("not valid JSON: {}", e.what()));
  }
  if (!j.is_object()) throw InputError({file, 1, 1}, "expected a JSON object with 'parameters'");
  if (!j.contains("parameters")) throw InputError({file, 1, 1}, "missing key 'parameters' (name → value in mm/rad)");
  ModelFile m;
  std::string key;  // the key being read, for a message on a value of the wrong type
  try {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      key = k;
      const auto& v = it.value();
      if (k == "machine") {
        if (!v.is_string()) throw InputError(position_of_key(text, k, file), "'machine' must be a string");
        m.machine = v.get<std::string>();
      } else if (k == "axes") {
        if (!v.is_string())
          throw InputError(position_of_key(text, k, file), "'axes' must be a string of axis letters, e.g. \"XYZAC\"");
        m.axes = v.get<std::string>();
      } else if (k == "parameters") {
        m.parameters = read_parameters(v, k, text, file, machine);
      } else if (k == "uncertainty") {
        m.uncertainty = read_parameters(v, k, text, file, nullptr);
      } else if (k == "effects_added") {
        if (!v.is_array())
          throw InputError(position_of_key(text, k, file), "'effects_added' must be an array of names");
        for (const auto& e : v) {
          if (!e.is_string()) throw InputError(position_of_key(text, k, file), "'effects_added' must hold strings");
          m.effects_added.push_back(e.get<std::string>());
        }
      } else if (k == "identifiability" && v.is_object()) {
        Identifiability id;
        id.rank = v.value("rank", 0);
        id.parameters = v.value("parameters", 0);
        if (v.contains("null_space") && v["null_space"].is_array())
          for (const auto& d : v["null_space"]) {
            NullDirection dir;
            if (d.is_object())
              for (auto w = d.begin(); w != d.end(); ++w)
                if (w.value().is_number()) dir.emplace_back(w.key(), w.value().get<double>());
            id.null_space.push_back(dir);
          }
        if (v.contains("pinned") && v["pinned"].is_array())
          for (const auto& p : v["pinned"])
            if (p.is_string()) id.pinned.push_back(p.get<std::string>());
        if (v.contains("combinations") && v["combinations"].is_array())
          for (const auto& p : v["combinations"])
            if (p.is_string()) id.combinations.push_back(p.get<std::string>());
        m.identifiability = id;
      } else if (k == "fit" && v.is_object()) {
        FitSummary f;
        f.rms_before_um = v.value("rms_before_um", 0.0);
        f.max_before_um = v.value("max_before_um", 0.0);
        f.rms_after_um = v.value("rms_after_um", 0.0);
        f.max_after_um = v.value("max_after_um", 0.0);
        f.rms_nominal_um = v.value("rms_nominal_um", 0.0);
        f.max_nominal_um = v.value("max_nominal_um", 0.0);
        m.fit = f;
      } else {
        m.extra[k] = v.dump();
      }
    }
  } catch (const ordered_json::exception& e) {
    throw InputError(position_of_key(text, key, file),
                     fmt::format("'{}' has a value of the wrong type: {}", key, e.what()));
  }
  if (machine) check_for_machine(m, text, file, *machine, options);
  return m;
}

ModelFile read_model_json(const std::string& path, const Machine* machine, const ModelReadOptions& options) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError({path, 0, 0}, "cannot open the model file");
  std::ostringstream s;
  s << f.rdbuf();
  return parse_model_json(s.str(), path, machine, options);
}

std::string format_model_json(const ModelFile& m) {
  ordered_json j;
  j["machine"] = m.machine;
  if (!m.axes.empty()) j["axes"] = m.axes;
  ordered_json p = ordered_json::object();
  for (std::size_t i = 0; i < m.parameters.size(); ++i) p[m.parameters.names()[i]] = m.parameters.values()[i];
  j["parameters"] = p;
  if (!m.uncertainty.empty()) {
    ordered_json u = ordered_json::object();
    for (std::size_t i = 0; i < m.uncertainty.size(); ++i) u[m.uncertainty.names()[i]] = m.uncertainty.values()[i];
    j["uncertainty"] = u;
  }
  j["effects_added"] = m.effects_added;
  if (m.identifiability) {
    const auto& id = *m.identifiability;
    ordered_json o;
    o["rank"] = id.rank;
    o["parameters"] = id.parameters;
    ordered_json ns = ordered_json::array();
    for (const auto& d : id.null_space) {
      ordered_json w = ordered_json::object();
      for (const auto& [n, v] : d)
        if (std::abs(v) >= 0.05) w[n] = std::round(v * 1e4) / 1e4;
      ns.push_back(w);
    }
    o["null_space"] = ns;
    o["pinned"] = id.pinned;
    o["combinations"] = id.combinations;
    j["identifiability"] = o;
  }
  if (m.fit) {
    const auto& f = *m.fit;
    auto r = [](double v) { return std::round(v * 1e4) / 1e4; };
    j["fit"] = {{"rms_before_um", r(f.rms_before_um)},   {"max_before_um", r(f.max_before_um)},
                {"rms_after_um", r(f.rms_after_um)},     {"max_after_um", r(f.max_after_um)},
                {"rms_nominal_um", r(f.rms_nominal_um)}, {"max_nominal_um", r(f.max_nominal_um)}};
  }
  for (const auto& [key, text] : m.extra) j[key] = ordered_json::parse(text);
  return j.dump(1) + "\n";
}

}  // namespace ncpost::comp
