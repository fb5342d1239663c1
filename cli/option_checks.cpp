#include "option_checks.h"

#include <cstdio>
#include <cstdlib>

namespace afford::cli {
namespace {

// A validator returns "" when the value is fine, else what went wrong.
CLI::Validator check(const char* expected, bool (*ok)(const std::string&)) {
  return CLI::Validator(
      [expected, ok](std::string& value) {
        return ok(value) ? std::string() : "expected " + std::string(expected) + ", found '" + value + "'";
      },
      "");  // no description: the help line says what is allowed
}

bool read_number(const std::string& s, double* v) {
  char* end = nullptr;
  *v = std::strtod(s.c_str(), &end);
  return !s.empty() && end != s.c_str() && *end == '\0';
}

bool read_size_parts(const std::string& s, int* w, int* h) {
  char tail = 0;
  return std::sscanf(s.c_str(), "%dx%d%c", w, h, &tail) == 2;
}

}  // namespace

CLI::Validator count_above_zero() {
  return check("a whole number above 0", [](const std::string& s) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    return !s.empty() && *end == '\0' && v > 0;
  });
}

CLI::Validator seconds_above_zero() {
  return check("a number of seconds above 0", [](const std::string& s) {
    double v = 0;
    return read_number(s, &v) && v > 0 && v < 1e9;
  });
}

CLI::Validator frames_per_second() {
  return check("a number of frames per second in (0, 1000]", [](const std::string& s) {
    double v = 0;
    return read_number(s, &v) && v > 0 && v <= 1000;
  });
}

CLI::Validator picture_size() {
  return check("WxH between 64x48 and 3840x2160", [](const std::string& s) {
    int w = 0, h = 0;
    return read_size_parts(s, &w, &h) && w >= 64 && h >= 48 && w <= 3840 && h <= 2160;
  });
}

void read_size(const std::string& text, int* width, int* height) { read_size_parts(text, width, height); }

}  // namespace afford::cli
