// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading and writing measurement CSV (docs/formats.md "Measurement data (CSV)").
//
// Reader: `# key: value` comment lines, a header, rows. Required keys per type (ballbar:
// table_ball, tool_ball, bar_length; sphere: sphere; laser: component, tool_point), `tool_length`
// optional (default 0; required for laser on a machine with head axes). Columns: `t`, X, Y, Z,
// the machine's rotary axes (optional for laser, default 0), `run` (laser), the value columns;
// other columns are ignored. Laser files may add (issue 7, LASER.md) `# axis:` (the moving axis,
// X | Y | Z), `# line:` (the commanded positions of the two other axes, XYZ order, mm; every row
// must agree) and a column `approach` (+1 from below, −1 from above). A missing key or column, a wrong field count, a
// non-number, NaN or Inf is an InputError with file and line. Angles are read in degrees and kept in radians.
#include <string>

#include "ncpost/compensation/measurement.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost::comp {

struct CsvReadOptions {
  bool allow_plan = false;  ///< accept a file without value columns (a measurement plan)
};

MeasurementSet parse_measurement_csv(const std::string& text, const std::string& file_name, const Machine& machine,
                                     const CsvReadOptions& options = {});
MeasurementSet read_measurement_csv(const std::string& path, const Machine& machine,
                                    const CsvReadOptions& options = {});

/// The CSV text of a set (plan if !set.has_values): metadata, header, rows.
std::string format_measurement_csv(const MeasurementSet& set, const Machine& machine);

}  // namespace ncpost::comp
