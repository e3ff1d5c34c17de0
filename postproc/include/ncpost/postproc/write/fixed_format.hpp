// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fixed-point formatting of NC word values ("-12.3450" with 4 decimals) without the general float
// formatter: the value is rounded to an integer count of 10^-decimals and its digits written.
// Same text as fmt's "{:.Nf}" except that a value rounding to zero never gets a minus sign.
// Falls back to fmt for values too large for the integer path.
#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace ncpost {

/// Appends `value` with `decimals` (0..9) decimals; `plus` writes '+' before non-negative values.
inline void append_fixed(fmt::memory_buffer& out, double value, int decimals, bool plus = false) {
  static constexpr double kScale[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  const double scaled = value * kScale[decimals];
  if (!(std::abs(scaled) < 9.0e15)) {  // also NaN
    if (plus)
      fmt::format_to(std::back_inserter(out), "{:+.{}f}", value, decimals);
    else
      fmt::format_to(std::back_inserter(out), "{:.{}f}", value, decimals);
    return;
  }
  std::int64_t n = std::llround(scaled);
  char digits[24];
  int len = 0;
  const bool negative = n < 0;
  std::uint64_t u = negative ? static_cast<std::uint64_t>(-n) : static_cast<std::uint64_t>(n);
  for (int k = 0; k < decimals; ++k) {
    digits[len++] = static_cast<char>('0' + u % 10);
    u /= 10;
  }
  if (decimals > 0) digits[len++] = '.';
  do {
    digits[len++] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u != 0);
  if (negative)
    digits[len++] = '-';
  else if (plus)
    digits[len++] = '+';
  char text[24];
  for (int k = 0; k < len; ++k) text[k] = digits[len - 1 - k];
  out.append(text, text + len);
}

}  // namespace ncpost
