// SPDX-License-Identifier: Apache-2.0
// fixed_format.hpp writes the same text as fmt's "{:.Nf}" (minus sign of a value rounding to zero aside).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <random>

#include "ncpost/postproc/write/fixed_format.hpp"

TEST_CASE("append_fixed agrees with fmt on random and edge values") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  int compared = 0;
  for (int i = 0; i < 200000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    const int decimals = i % 7;
    fmt::memory_buffer b;
    ncpost::append_fixed(b, v, decimals, i % 2 == 0);
    std::string expected = i % 2 == 0 ? fmt::format("{:+.{}f}", v, decimals) : fmt::format("{:.{}f}", v, decimals);
    // fmt rounds the exact binary value; llround(v * 10^d) may differ on exact ties of the product
    const std::string got = fmt::to_string(b);
    if (expected == "-0" || expected.find_first_not_of("-0.") == std::string::npos) {
      expected.erase(0, expected[0] == '-' ? 1 : 0);
      if (i % 2 == 0 && expected[0] != '+') expected = "+" + expected;
    }
    if (got != expected) {
      // allowed only for a tie: the two texts differ by one unit in the last place
      const double diff = std::abs(std::stod(got) - std::stod(expected));
      INFO(v << " with " << decimals << " decimals: " << got << " vs " << expected);
      CHECK(diff <= std::pow(10.0, -decimals) * 1.000001);
    }
    ++compared;
  }
  CHECK(compared == 200000);
  fmt::memory_buffer b;
  ncpost::append_fixed(b, -0.00001, 4);
  CHECK(fmt::to_string(b) == "0.0000");
  b.clear();
  ncpost::append_fixed(b, 123456.78905, 4);
  CHECK(fmt::to_string(b).substr(0, 10) == "123456.789");
  b.clear();
  ncpost::append_fixed(b, 1e300, 2);  // beyond the integer path
  CHECK(fmt::to_string(b) == fmt::format("{:.2f}", 1e300));
  b.clear();
  ncpost::append_fixed(b, 5.0, 0, true);
  CHECK(fmt::to_string(b) == "+5");
}
