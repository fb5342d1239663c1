// Small helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>
#include <unistd.h>
#include <vector>

namespace afford::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = std::numbers::pi / 180;  // rad per degree
#ifdef AFFORD_SOURCE_DIR
inline const std::string kSource = AFFORD_SOURCE_DIR;  // the source tree: the shipped files
#endif

// The message of the E a call throws, or "" when it throws none (another
// exception than E passes through and fails the test).
template <class E = std::exception, class F>
std::string thrown(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

// A fresh, empty folder in the system's temporary one, named for the test
// (`kind`, `name`) and this process, so that tests running at once never share it.
inline std::filesystem::path fresh_dir(const std::string& kind, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("afford-" + kind + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A fresh folder of its own, removed at the end of the test.
struct TempDir {
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "afford-test-XXXXXX").string();
    EXPECT_NE(::mkdtemp(pattern.data()), nullptr);
    path = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string at(const std::string& name) const { return (path / name).string(); }
  std::filesystem::path path;
};

// The index of `name` in `names`; -2 when it is not there (a grid's cells
// hold -1 for "no function").
inline int index_of(const std::vector<std::string>& names, const std::string& name) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -2;
}

// `text` with its one occurrence of `from` replaced by `to`. A `from` that
// is missing or not unique fails the test: the mutation would be unclear.
inline std::string replace_once(const std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    ADD_FAILURE() << "'" << from << "' is not in the document exactly once";
    return text;
  }
  return text.substr(0, at) + to + text.substr(at + from.size());
}

// An ellipsoid of semi-axes (a, b, b) (m), long along the jaws, resting on
// the fixed jaw's face (y = 0) with its centre at (r, b), under a moving jaw
// whose face passes through the hinge. Worked out by hand: the face at
// theta (normal n = (-sin, cos)) touches it where the centre's depth under
// it equals its reach along n, r sin - b cos = root = sqrt(a^2 sin^2 + b^2
// cos^2) (found here by bisection in [0, theta_max]), at P = (r, b) +
// (-a^2 sin, b^2 cos) / root, and pushes it along n with the lever arm
// |P x n| = r cos + b sin - (a^2 - b^2) sin cos / root about the hinge.
struct JawTouch {
  double angle = 0;  // rad, theta_c
  double lever = 0;  // m
};
inline JawTouch ellipsoid_under_jaw(double a, double b, double r, double theta_max) {
  const auto excess = [&](double t) { return r * std::sin(t) - b * std::cos(t) - std::hypot(a * std::sin(t), b * std::cos(t)); };
  double open = theta_max, closed = 0;  // apart at `open`, overlapping at `closed`
  for (int i = 0; i < 200; ++i) (excess(0.5 * (open + closed)) > 0 ? open : closed) = 0.5 * (open + closed);
  const double s = std::sin(open), c = std::cos(open), root = std::hypot(a * s, b * c);
  return {open, r * c + b * s - (a * a - b * b) * s * c / root};
}

}  // namespace afford::test
