// write_fixed and write_general write what printf's "%.*f" and "%.*g" do,
// byte for byte: on the values a trace holds, on ties and near-ties of the
// rounding, and on random bit patterns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "number_format.h"

using afford::write_fixed;
using afford::write_general;

namespace {

std::string printf_text(const char* format, int precision, double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, precision, v);
  return buf;
}

// Every precision of both formats for v; the first difference, or "".
std::string first_difference(double v) {
  char buf[512];
  for (int precision = 0; precision <= 12; ++precision) {
    const std::string fixed(buf, write_fixed(buf, buf + sizeof buf, v, precision));
    if (fixed != printf_text("%.*f", precision, v)) return "%." + std::to_string(precision) + "f gave " + fixed;
    const std::string general(buf, write_general(buf, buf + sizeof buf, v, precision));
    if (general != printf_text("%.*g", precision, v)) return "%." + std::to_string(precision) + "g gave " + general;
  }
  return "";
}

// Values a trace holds: times on a millisecond grid, decimals of a few
// digits, ties of the rounding (x.5 at some digit) and their neighbours.
std::vector<double> decimal_values() {
  std::vector<double> out = {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1.5, 2.5, 0.125, 0.0000005, 0.0000015, 999999999.5,
                             9.9999999996, 99999.99999, 0.00099999999995, 1e-5, 1e-4, 1e9, 1e10, 1e15, 1e16,
                             1e22, 1e23, 123456789.0, 0.314159265, 0.0204877754, 18.3173759, 31.5463428};
  for (int ms = 0; ms <= 20000; ++ms) out.push_back(ms * 0.001);
  for (int k = 0; k <= 12; ++k) {
    for (int n = -300; n <= 300; ++n) {
      const double tie = (n + 0.5) / std::pow(10.0, k);
      out.push_back(tie);
      out.push_back(std::nextafter(tie, 0.0));
      out.push_back(std::nextafter(tie, 1e300));
    }
  }
  return out;
}

}  // namespace

TEST(NumberFormat, DecimalsTiesAndNeighboursAreWrittenAsPrintfDoes) {
  for (double v : decimal_values()) {
    ASSERT_EQ(first_difference(v), "") << v;
    ASSERT_EQ(first_difference(-v), "") << -v;
  }
}

TEST(NumberFormat, ExtremesAreWrittenAsPrintfDoes) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {inf, -inf, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(), 1e-300, 1e300,
                   1e-15, 1e-14, 1e30, 1e31}) {
    ASSERT_EQ(first_difference(v), "") << v;
    ASSERT_EQ(first_difference(-v), "") << -v;
  }
}

TEST(NumberFormat, RandomMagnitudesAreWrittenAsPrintfDoes) {
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-70, 110);
  for (int i = 0; i < 20000; ++i) {
    const double v = std::ldexp(mantissa(random), exponent(random));
    ASSERT_EQ(first_difference(v), "") << v;
  }
}

TEST(NumberFormat, RandomBitPatternsAreWrittenAsPrintfDoes) {
  std::mt19937_64 random(13);
  for (int i = 0; i < 3000; ++i) {
    const uint64_t bits = random();
    double v = 0;
    std::memcpy(&v, &bits, sizeof v);
    ASSERT_EQ(first_difference(v), "") << v;
  }
}
