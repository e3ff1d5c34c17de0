// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measurement data and plans (docs/formats.md "Measurement data (CSV)"; docs/conventions.md
// "Measurements"). A plan is a measurement set whose value columns are absent.
//
// Units: commands in mm and rad (degrees only in the file), time in s, values in mm for ballbar
// (L) and sphere (dx, dy, dz), µm for laser (e_um). Vectors (balls, sphere, tool point) in mm in
// M at home.
#include <string>
#include <utility>
#include <vector>

#include "ncpost/compensation/measurement_conditions.hpp"
#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

enum class MeasurementType { ballbar, sphere, laser };

const char* to_string(MeasurementType t);

struct MeasurementRow {
  int line = 0;  ///< 1-based line in the file (0 for rows made in memory)
  double time_s = 0.0;
  AxisPosition command;  ///< mm, rad
  int run = 0;           ///< laser: run number (the instrument is zeroed at each run's first row)
  int approach = 0;      ///< laser: +1 approached from below, −1 from above (column `approach`), 0 not given
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  ///< L | dx,dy,dz | e_um in value[0]
};

struct MeasurementSet {
  std::string file;  ///< where it was read from (messages), or a name
  MeasurementType type = MeasurementType::ballbar;
  /// Every `# key: value` line in order (also the known keys; unknown ones are kept and written back).
  std::vector<std::pair<std::string, std::string>> metadata;
  Vec3d table_ball_mm = Vec3d::Zero();  ///< ballbar: table ball centre at home
  Vec3d tool_ball_mm = Vec3d::Zero();   ///< ballbar: tool ball centre from the TCP (tool axes at home)
  double bar_length_mm = 0.0;           ///< ballbar: nominal bar length
  Vec3d sphere_mm = Vec3d::Zero();      ///< sphere: centre at home
  char component = 'X';                 ///< laser: measured component (M axis)
  Vec3d tool_point_mm = Vec3d::Zero();  ///< laser: measured point from the TCP
  double tool_length_mm = 0.0;          ///< `tool_length` key (all types; default 0)
  bool has_values = true;               ///< false for a plan (value columns absent)
  std::vector<MeasurementRow> rows;
  /// Temperature, expansion, instrument, serial, operator, date (measurement_conditions.hpp).
  MeasurementConditions conditions;
  /// What the reader noticed without refusing the file (unknown keys, keys among the rows), each
  /// "file:line: text"; `identify` prints them on stderr and in the report.
  std::vector<std::string> notices;
  /// thermal_correction.hpp: true once the values are corrected to 20 °C; the largest change (µm).
  bool corrected_to_20c = false;
  double thermal_correction_max_um = 0.0;

  /// Number of values per row: 1 (ballbar, laser) or 3 (sphere).
  int values_per_row() const { return type == MeasurementType::sphere ? 3 : 1; }
  /// Value column names of the type.
  std::vector<std::string> value_columns() const;
  /// The value of a metadata key, or empty.
  std::string meta(const std::string& key) const;
  void set_meta(const std::string& key, const std::string& value);
};

}  // namespace ncpost::comp
