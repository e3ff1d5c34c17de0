// SPDX-License-Identifier: Apache-2.0
#pragma once
// The conditions a measurement was taken under (issue 25 item 3; docs/formats.md "Measurement
// conditions"): the temperature of the machine (°C), the linear expansion coefficient of its
// material (1/K), the instrument, its serial number, the operator and the date, read from a data
// file's `# key: value` lines and shown in every identification report.
//
// ISO 1 reference temperature 20 °C. A length ℓ_T measured on a machine at T with expansion α is
// what it would be at 20 °C:  ℓ_20 = ℓ_T / (1 + α (T − 20 °C))  (thermal_correction.hpp applies it).
#include <optional>
#include <string>
#include <vector>

namespace ncpost::comp {

/// ISO 1: the reference temperature of dimensional measurement.
inline constexpr double kReferenceTemperatureC = 20.0;
/// Two files of one identification whose temperatures differ by more than this are warned about.
inline constexpr double kTemperatureAgreementK = 1.0;

struct MeasurementConditions {
  std::optional<double> temperature_c;    ///< `# temperature:` (machine, °C)
  std::optional<double> expansion_per_k;  ///< `# material_expansion:` (1/K)
  std::string instrument;                 ///< `# instrument:`
  std::string serial;                     ///< `# serial:` (the instrument's)
  std::string operator_name;              ///< `# operator:`
  std::string date;                       ///< `# date:` (ISO 8601, as written)
  /// `# instrument_uncertainty:` U (k = 2) of one reading, µm, as the instrument's calibration
  /// certificate states it (for a laser: at the line's length).
  std::optional<double> instrument_U_um;
  std::optional<double> temperature_u_k;    ///< `# temperature_uncertainty:` standard, K
  std::optional<double> expansion_u_per_k;  ///< `# expansion_uncertainty:` standard, 1/K

  /// 1 + α (T − 20 °C); 1 when the temperature or the coefficient is not given.
  double expansion_factor() const;
  /// True if lengths are corrected to 20 °C (both the temperature and the coefficient given).
  bool corrects() const { return temperature_c.has_value() && expansion_per_k.has_value(); }
  bool any() const;
};

/// A header key of the measurement files: which types use it and what it means (the reader's
/// table of known keys; docs/formats.md lists the same).
struct HeaderKey {
  const char* name;
  const char* types;  ///< "ballbar sphere laser" or a subset
  const char* meaning;
};
const std::vector<HeaderKey>& header_keys();

/// True if `date` is ISO 8601 as the files use it: YYYY-MM-DD, optionally THH:MM[:SS] and Z or ±HH:MM.
bool is_iso8601_date(const std::string& date);

}  // namespace ncpost::comp
