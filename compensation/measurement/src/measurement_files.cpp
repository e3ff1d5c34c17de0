// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/measurement_files.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <utility>

#include "ncpost/compensation/thermal_correction.hpp"

namespace ncpost::comp {
namespace {

bool same_row(const MeasurementRow& a, const MeasurementRow& b) {
  return a.time_s == b.time_s && a.run == b.run && a.approach == b.approach && a.command == b.command &&
         a.value == b.value;
}

}  // namespace

int same_rows_as_earlier(const std::vector<MeasurementSet>& sets, std::size_t k) {
  for (std::size_t e = 0; e < k && e < sets.size(); ++e) {
    const auto& a = sets[e].rows;
    const auto& b = sets[k].rows;
    if (sets[e].type != sets[k].type || a.size() != b.size() || a.empty()) continue;
    bool same = true;
    for (std::size_t r = 0; r < a.size() && same; ++r) same = same_row(a[r], b[r]);
    if (same) return static_cast<int>(e);
  }
  return -1;
}

std::vector<MeasurementSet> read_measurement_files(const std::vector<std::string>& paths, const Machine& machine,
                                                   const CsvReadOptions& options) {
  std::vector<std::pair<dev_t, ino_t>> ids;
  std::vector<MeasurementSet> sets;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    struct stat st {};
    if (::stat(paths[k].c_str(), &st) == 0) {
      for (std::size_t e = 0; e < ids.size(); ++e)
        if (ids[e] == std::make_pair(st.st_dev, st.st_ino))
          throw InputError({paths[k], 0, 0},
                           fmt::format("the same file as '{}', given twice: its measurements would count twice and the "
                                       "uncertainties come out too small; give each file once",
                                       paths[e]));
      ids.emplace_back(st.st_dev, st.st_ino);
    } else {
      ids.emplace_back(dev_t(-1), ino_t(-1));  // read_measurement_csv says why it cannot be opened
    }
    sets.push_back(read_measurement_csv(paths[k], machine, options));
    correct_to_20c(sets.back());
    if (const int e = same_rows_as_earlier(sets, k); e >= 0)
      throw InputError({paths[k], sets[k].rows.front().line, 0},
                       fmt::format("holds the same rows as '{}' (a copy of the same measurement): it would count twice "
                                   "and the uncertainties come out too small; give each measurement once",
                                   paths[static_cast<std::size_t>(e)]));
  }
  return sets;
}

}  // namespace ncpost::comp
