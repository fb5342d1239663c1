// Physical quantities written as text, "18 mm" or "0.3 N*m/rad": parsed into
// SI values with a dimension that is checked against what a field expects.
// Shared by the data files and the predicate language.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace afford {

// Exponents of the base dimensions: length (m), mass (kg), time (s) and plane
// angle (rad). Angle is kept as its own dimension so that "30 N" cannot be
// given where an angle is meant.
struct Dimension {
  std::array<int, 4> exponent{};  // m, kg, s, rad

  bool operator==(const Dimension&) const = default;
  Dimension operator*(const Dimension& o) const;
  Dimension operator/(const Dimension& o) const;
  Dimension pow(int p) const;
  std::string str() const;  // "kg*m/s^2"
};

namespace dim {
inline constexpr Dimension none{{0, 0, 0, 0}};
inline constexpr Dimension length{{1, 0, 0, 0}};
inline constexpr Dimension mass{{0, 1, 0, 0}};
inline constexpr Dimension time{{0, 0, 1, 0}};
inline constexpr Dimension angle{{0, 0, 0, 1}};
inline constexpr Dimension force{{1, 1, -2, 0}};             // N
inline constexpr Dimension stiffness{{0, 1, -2, 0}};         // N/m
inline constexpr Dimension cubic_stiffness{{-2, 1, -2, 0}};  // N/m^3
inline constexpr Dimension torque{{2, 1, -2, 0}};            // N*m
inline constexpr Dimension rotational_damping{{2, 1, -1, -1}};  // N*m*s/rad
inline constexpr Dimension inertia{{2, 1, 0, 0}};            // kg*m^2
inline constexpr Dimension damping{{0, 1, -1, 0}};           // N*s/m
inline constexpr Dimension speed{{1, 0, -1, 0}};             // m/s
inline constexpr Dimension angular_speed{{0, 0, -1, 1}};     // rad/s
}  // namespace dim

// Limits compared with a relative tolerance, so that a documented limit
// written in any unit passes exactly: "10 us" is 10 x 1e-6 s, which is a
// hair below 1e-5 s in floating point. 1e-9 is far below any difference
// a limit means.
inline constexpr double kLimitTolerance = 1e-9;
inline bool at_least(double value, double least) { return value >= least * (1 - kLimitTolerance); }
inline bool at_most(double value, double most) { return value <= most * (1 + kLimitTolerance); }

// A human name and an example for error messages: "a length (e.g. '18 mm')".
std::string describe_dimension(const Dimension& d);

struct Quantity {
  double si = 0;  // value in SI units (m, kg, s, rad and products)
  Dimension dimension;
};

// Parses a unit expression such as "mm", "N/m", "N*m*s/rad", "kg*m^2".
// Returns nullopt and sets `error` when the text is not one.
std::optional<Quantity> parse_unit(std::string_view text, std::string* error);

// Parses "<number> <unit>" ("18 mm", "-3.5e2 N"). A bare number is
// dimensionless; the caller checks the dimension against what it expects.
std::optional<Quantity> parse_quantity(std::string_view text, std::string* error);

// Formats an SI value in the unit a user is likely to read ("18 mm").
std::string format_quantity(double si, const Dimension& d, int digits = 4);

// Parses a finite decimal number, the whole text; nullopt otherwise.
std::optional<double> parse_number(std::string_view text);

}  // namespace afford
