#include "number_format.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace afford {
namespace {

// Powers of ten that a double holds exactly.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxExactPow10 = 22;
constexpr uint64_t kIntPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000,
                                  10000000000};
constexpr int kMaxPrecision = 9;

// A scaled value below kMaxScaled is off the exact product or quotient by
// one rounding, at most 2^-53 of it: under 1.2e-6. A fraction further than
// kTieMargin from one half rounds the same way as the exact value's.
constexpr double kMaxScaled = 1e10;
constexpr double kTieMargin = 1e-4;

// The longest text the fast paths write: a sign, 10 integer digits, a point,
// 9 + 4 fraction digits (or an exponent), with room to spare.
constexpr long kFastRoom = 32;

// x (in [0, kMaxScaled)) rounded to the nearest integer, when it rounds as
// the exact value does.
bool round_unambiguous(double x, uint64_t* rounded) {
  const uint64_t whole = static_cast<uint64_t>(x);  // floor, for x >= 0
  const double fraction = x - static_cast<double>(whole);  // exact: x < 2^53
  if (std::abs(fraction - 0.5) < kTieMargin) return false;
  *rounded = whole + (fraction > 0.5 ? 1 : 0);
  return true;
}

// "00" to "99": two digits a division.
constexpr auto kDigitPairs = [] {
  std::array<char, 200> pairs{};
  for (int i = 0; i < 100; ++i) {
    pairs[static_cast<size_t>(2 * i)] = static_cast<char>('0' + i / 10);
    pairs[static_cast<size_t>(2 * i + 1)] = static_cast<char>('0' + i % 10);
  }
  return pairs;
}();

// value in exactly `count` digits, leading zeros included.
char* put_digits(char* p, uint64_t value, int count) {
  int i = count;
  for (; i >= 2; i -= 2) {
    const size_t pair = static_cast<size_t>(2 * (value % 100));
    p[i - 2] = kDigitPairs[pair];
    p[i - 1] = kDigitPairs[pair + 1];
    value /= 100;
  }
  if (i == 1) p[0] = static_cast<char>('0' + value % 10);
  return p + count;
}

// digits without its trailing zeros: how many remain.
int significant(const char* digits, int count) {
  while (count > 0 && digits[count - 1] == '0') --count;
  return count;
}

char* copy(char* p, const char* from, int count) {
  for (int i = 0; i < count; ++i) *p++ = from[i];
  return p;
}

// |v| = digits * 10^(exponent - precision + 1), digits of `precision`
// figures, when the rounding to them is unambiguous.
bool significant_digits(double magnitude, int precision, uint64_t* digits, int* exponent) {
  // The decimal exponent from the binary one (log10(2) = 0.30103 as
  // 78913 / 2^18, floored by the shift): at most one too small, which the
  // scaled value then says.
  int binary_exponent = 0;  // magnitude in [2^(b-1), 2^b), as frexp gives it
  const int biased = static_cast<int>(std::bit_cast<uint64_t>(magnitude) >> 52);  // magnitude >= 0
  if (biased > 0) {
    binary_exponent = biased - 1022;
  } else {
    std::frexp(magnitude, &binary_exponent);  // subnormal
  }
  int e = ((binary_exponent - 1) * 78913) >> 18;
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int k = precision - 1 - e;
    if (k < -kMaxExactPow10 || k > kMaxExactPow10) return false;
    const double x = k >= 0 ? magnitude * kPow10[k] : magnitude / kPow10[-k];
    if (x >= static_cast<double>(kIntPow10[precision])) {
      ++e;
    } else if (x < static_cast<double>(kIntPow10[precision - 1])) {
      --e;
    } else {
      if (!round_unambiguous(x, digits)) return false;
      if (*digits == kIntPow10[precision]) {  // 9.9999999996 to 10.0000000
        *digits = kIntPow10[precision - 1];
        ++e;
      }
      *exponent = e;
      return true;
    }
  }
  return false;
}

}  // namespace

char* write_fixed(char* p, char* end, double v, int precision) {
  const double magnitude = std::abs(v);
  uint64_t scaled = 0;
  const bool fast = precision >= 0 && precision <= kMaxPrecision && end - p >= kFastRoom &&
                    magnitude * kPow10[precision] < kMaxScaled &&
                    round_unambiguous(magnitude * kPow10[precision], &scaled);
  if (!fast) return std::to_chars(p, end, v, std::chars_format::fixed, precision).ptr;
  if (std::signbit(v)) *p++ = '-';  // printf writes -0.000000 too
  const uint64_t unit = kIntPow10[precision];
  p = std::to_chars(p, end, scaled / unit).ptr;
  if (precision > 0) {
    *p++ = '.';
    p = put_digits(p, scaled % unit, precision);
  }
  return p;
}

char* write_general(char* p, char* end, double v, int precision) {
  if (precision == 0) precision = 1;  // as printf reads %.0g
  const double magnitude = std::abs(v);
  if (precision < 0 || precision > kMaxPrecision || end - p < kFastRoom || !std::isfinite(v)) {
    return std::to_chars(p, end, v, std::chars_format::general, precision).ptr;
  }
  if (std::signbit(v)) *p++ = '-';
  if (magnitude == 0) {
    *p++ = '0';
    return p;
  }
  uint64_t scaled = 0;
  int exponent = 0;
  if (!significant_digits(magnitude, precision, &scaled, &exponent)) {
    return std::to_chars(p, end, magnitude, std::chars_format::general, precision).ptr;
  }
  char digits[kMaxPrecision];
  put_digits(digits, scaled, precision);
  if (exponent < -4 || exponent >= precision) {  // d.ddde+XX
    *p++ = digits[0];
    const int fraction = significant(digits + 1, precision - 1);
    if (fraction > 0) {
      *p++ = '.';
      p = copy(p, digits + 1, fraction);
    }
    *p++ = 'e';
    *p++ = exponent < 0 ? '-' : '+';
    const int e = std::abs(exponent);
    if (e < 10) *p++ = '0';
    return std::to_chars(p, end, e).ptr;
  }
  if (exponent >= 0) {  // ddd.ddd
    p = copy(p, digits, exponent + 1);
    const int fraction = significant(digits + exponent + 1, precision - exponent - 1);
    if (fraction > 0) {
      *p++ = '.';
      p = copy(p, digits + exponent + 1, fraction);
    }
    return p;
  }
  *p++ = '0';  // 0.000ddd
  *p++ = '.';
  for (int i = -1; i > exponent; --i) *p++ = '0';
  return copy(p, digits, significant(digits, precision));
}

}  // namespace afford
