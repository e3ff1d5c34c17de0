// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace ncpost::trr {

Errors errors_from_model(const comp::ModelFile& model, const std::string& text, const std::string& path) {
  Errors e;
  const auto& names = model.parameters.names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int k = Errors::index_of(names[i]);
    if (k < 0) {
      SourcePosition where{path, 0, 0};
      const auto pos = text.find("\"" + names[i] + "\"");
      if (pos != std::string::npos) {
        where.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
        where.column = static_cast<int>(pos - text.rfind('\n', pos));
      }
      throw InputError(where, fmt::format("parameter '{}' is not a TRR-XY error parameter (expected <param>_<chain> with "
                                          "param dr, dt, ar, at, ds, gp, dl, drs, dts or dzs and chain a, b or c)",
                                          names[i]));
    }
    e[k] = model.parameters.values()[i];
  }
  return e;
}

Errors read_errors_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the model file");
  std::ostringstream s;
  s << in.rdbuf();
  const comp::ModelFile model = comp::parse_model_json(s.str(), path, nullptr);
  return errors_from_model(model, s.str(), path);
}

comp::ModelFile model_from_errors(const Errors& e, const std::string& machine_name) {
  comp::ModelFile m;
  m.machine = machine_name;
  for (int k = 0; k < kParameterCount; ++k) m.parameters.set(Errors::name(k), e[k]);
  return m;
}

}  // namespace ncpost::trr
