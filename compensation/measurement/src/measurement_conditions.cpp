// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/measurement_conditions.hpp"

#include <cctype>

namespace ncpost::comp {

double MeasurementConditions::expansion_factor() const {
  if (!corrects()) return 1.0;
  return 1.0 + *expansion_per_k * (*temperature_c - kReferenceTemperatureC);
}

bool MeasurementConditions::any() const {
  return temperature_c || expansion_per_k || !instrument.empty() || !serial.empty() || !operator_name.empty() ||
         !date.empty() || instrument_U_um || temperature_u_k || expansion_u_per_k;
}

const std::vector<HeaderKey>& header_keys() {
  static const std::vector<HeaderKey> keys = {
      {"type", "ballbar sphere laser", "ballbar, sphere or laser"},
      {"tool_length", "ballbar sphere laser", "tool or stylus length while measuring (mm)"},
      {"table_ball", "ballbar", "table ball centre at home (mm, M)"},
      {"tool_ball", "ballbar", "tool ball centre from the TCP (mm)"},
      {"bar_length", "ballbar", "nominal bar length (mm)"},
      {"sphere", "sphere", "sphere centre at home (mm, M)"},
      {"component", "laser", "measured component X, Y or Z"},
      {"tool_point", "laser", "measured point from the TCP (mm)"},
      {"axis", "laser", "the moving axis"},
      {"line", "laser", "the commanded positions of the two other axes (mm)"},
      {"approach", "laser", "bidirectional or unidirectional (description)"},
      {"test", "ballbar sphere laser", "what the plan measures (description)"},
      {"height", "ballbar sphere laser", "the plan's height (description)"},
      {"temperature", "ballbar sphere laser", "machine temperature while measuring (°C)"},
      {"material_expansion", "ballbar sphere laser", "linear expansion coefficient of the machine (1/K)"},
      {"instrument", "ballbar sphere laser", "the instrument"},
      {"serial", "ballbar sphere laser", "the instrument's serial number"},
      {"operator", "ballbar sphere laser", "who measured"},
      {"date", "ballbar sphere laser", "when it was measured (ISO 8601)"},
      {"instrument_uncertainty", "ballbar sphere laser", "U (k = 2) of one reading, µm (calibration certificate)"},
      {"temperature_uncertainty", "ballbar sphere laser", "standard uncertainty of the temperature, K"},
      {"expansion_uncertainty", "ballbar sphere laser", "standard uncertainty of the expansion coefficient, 1/K"},
  };
  return keys;
}

namespace {

/// `count` digits at s[at…] as a number, or -1.
int digits(const std::string& s, std::size_t at, std::size_t count) {
  if (at + count > s.size()) return -1;
  int v = 0;
  for (std::size_t k = at; k < at + count; ++k) {
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return -1;
    v = 10 * v + (s[k] - '0');
  }
  return v;
}

bool days_fit(int year, int month, int day) {
  static const int kDays[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12 || day < 1 || day > kDays[month - 1]) return false;
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return !(month == 2 && day == 29 && !leap);
}

}  // namespace

bool is_iso8601_date(const std::string& s) {
  const int year = digits(s, 0, 4), month = digits(s, 5, 2), day = digits(s, 8, 2);
  if (year < 0 || month < 0 || day < 0 || s[4] != '-' || s[7] != '-' || !days_fit(year, month, day)) return false;
  if (s.size() == 10) return true;
  if (s[10] != 'T' && s[10] != ' ') return false;
  const int hour = digits(s, 11, 2), minute = digits(s, 14, 2);
  if (hour < 0 || hour > 23 || minute < 0 || minute > 59 || s.size() < 16 || s[13] != ':') return false;
  std::size_t at = 16;
  if (at < s.size() && s[at] == ':') {
    const int second = digits(s, at + 1, 2);
    if (second < 0 || second > 60) return false;
    at += 3;
  }
  if (at == s.size()) return true;
  if (s[at] == 'Z') return at + 1 == s.size();
  if (s[at] != '+' && s[at] != '-') return false;
  const int zh = digits(s, at + 1, 2), zm = digits(s, at + 4, 2);
  return zh >= 0 && zh <= 14 && zm >= 0 && zm <= 59 && s[at + 3] == ':' && at + 6 == s.size();
}

}  // namespace ncpost::comp
