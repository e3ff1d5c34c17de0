// SPDX-License-Identifier: Apache-2.0
// Dates of the sessions as days (compare_sessions.hpp): the civil calendar to a day count.
#include <string>

#include "ncpost/compensation/compare_sessions.hpp"
#include "ncpost/compensation/measurement_conditions.hpp"

namespace ncpost::comp {
namespace {

/// Days from 1970-01-01 to y-m-d in the proleptic Gregorian calendar (H. Hinnant's days_from_civil).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

int digits_at(const std::string& s, std::size_t at, std::size_t n) {
  int v = 0;
  for (std::size_t k = at; k < at + n; ++k) v = v * 10 + (s[k] - '0');
  return v;
}

}  // namespace

std::optional<double> days_since_epoch(const std::string& s) {
  if (!is_iso8601_date(s)) return std::nullopt;
  double day = double(days_from_civil(digits_at(s, 0, 4), unsigned(digits_at(s, 5, 2)), unsigned(digits_at(s, 8, 2))));
  if (s.size() == 10) return day;
  std::size_t k = 11;  // after 'T'
  double minutes = digits_at(s, k, 2) * 60.0 + digits_at(s, k + 3, 2);
  k += 5;
  if (k < s.size() && s[k] == ':') minutes += digits_at(s, k + 1, 2) / 60.0, k += 3;
  if (k < s.size() && (s[k] == '+' || s[k] == '-')) {
    const double offset = digits_at(s, k + 1, 2) * 60.0 + digits_at(s, k + 4, 2);
    minutes -= s[k] == '+' ? offset : -offset;  // local time = UTC + offset
  }
  return day + minutes / 1440.0;
}

}  // namespace ncpost::comp
