// Quantities written as text: "18 mm", "0.3 N*m/rad". Parsed to SI with a
// dimension; formatted back in the unit a user reads.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <utility>
#include <optional>
#include <string>

#include "units.h"
#include "test_util.h"

namespace afford {

// GoogleTest prints a Dimension as its units (found by ADL; static so that
// another test file may define its own).
[[maybe_unused]] static void PrintTo(const Dimension& d, std::ostream* os) { *os << d.str(); }

namespace {
using test::kDeg;

using ::testing::HasSubstr;


// The quantity `text` parses to; fails the test when it does not parse.
Quantity quantity(const std::string& text) {
  std::string error;
  const std::optional<Quantity> q = parse_quantity(text, &error);
  if (!q) {
    ADD_FAILURE() << "'" << text << "' did not parse: " << error;
    return Quantity{};
  }
  EXPECT_EQ(error, "") << text;
  return *q;
}

// The error for `text`; fails the test when it parses.
std::string quantity_error(const std::string& text) {
  std::string error;
  const std::optional<Quantity> q = parse_quantity(text, &error);
  if (q) ADD_FAILURE() << "'" << text << "' parsed, as " << q->si << " " << q->dimension.str();
  return error;
}

std::string unit_error(const std::string& text) {
  std::string error;
  const std::optional<Quantity> q = parse_unit(text, &error);
  if (q) ADD_FAILURE() << "'" << text << "' parsed, as " << q->si << " " << q->dimension.str();
  return error;
}

Dimension unit_dimension(const std::string& text) {
  std::string error;
  const std::optional<Quantity> q = parse_unit(text, &error);
  if (!q) {
    ADD_FAILURE() << "'" << text << "' did not parse: " << error;
    return Dimension{{99, 99, 99, 99}};
  }
  return q->dimension;
}

// ---------------------------------------------------------------- parse_quantity

TEST(UnitsParse, Millimetres) {
  const Quantity q = quantity("18 mm");
  EXPECT_DOUBLE_EQ(q.si, 0.018);
  EXPECT_EQ(q.dimension, dim::length);
}

TEST(UnitsParse, Centimetres) {
  const Quantity q = quantity("2.5 cm");
  EXPECT_DOUBLE_EQ(q.si, 0.025);
  EXPECT_EQ(q.dimension, dim::length);
}

TEST(UnitsParse, Micrometres) { EXPECT_DOUBLE_EQ(quantity("250 um").si, 250e-6); }

TEST(UnitsParse, Grams) {
  const Quantity q = quantity("120 g");
  EXPECT_DOUBLE_EQ(q.si, 0.12);
  EXPECT_EQ(q.dimension, dim::mass);
}

TEST(UnitsParse, TimeUnits) {
  EXPECT_DOUBLE_EQ(quantity("200 ms").si, 0.2);
  EXPECT_DOUBLE_EQ(quantity("2 min").si, 120.0);
  EXPECT_EQ(quantity("2 min").dimension, dim::time);
}

TEST(UnitsParse, Stiffness) {
  const Quantity q = quantity("800 N/m");
  EXPECT_DOUBLE_EQ(q.si, 800.0);
  EXPECT_EQ(q.dimension, dim::stiffness);
}

TEST(UnitsParse, KilonewtonsPerMillimetre) {
  const Quantity q = quantity("5 kN/mm");
  EXPECT_DOUBLE_EQ(q.si, 5e6);
  EXPECT_EQ(q.dimension, dim::stiffness);
}

TEST(UnitsParse, NewtonsPerMillimetre) { EXPECT_DOUBLE_EQ(quantity("250 N/mm").si, 250e3); }

TEST(UnitsParse, Torque) {
  const Quantity q = quantity("0.02 N*m");
  EXPECT_DOUBLE_EQ(q.si, 0.02);
  EXPECT_EQ(q.dimension, dim::torque);
}

TEST(UnitsParse, RotationalDamping) {
  const Quantity q = quantity("0.001 N*m*s/rad");
  EXPECT_DOUBLE_EQ(q.si, 0.001);
  EXPECT_EQ(q.dimension, dim::rotational_damping);
}

TEST(UnitsParse, Inertia) {
  const Quantity q = quantity("2e-5 kg*m^2");
  EXPECT_DOUBLE_EQ(q.si, 2e-5);
  EXPECT_EQ(q.dimension, dim::inertia);
}

TEST(UnitsParse, CubicStiffness) {
  const Quantity q = quantity("2e6 N/m^3");
  EXPECT_DOUBLE_EQ(q.si, 2e6);
  EXPECT_EQ(q.dimension, dim::cubic_stiffness);
}

TEST(UnitsParse, DegreesToRadians) {
  const Quantity q = quantity("30 deg");
  EXPECT_DOUBLE_EQ(q.si, 30 * kDeg);
  EXPECT_NEAR(q.si, 0.5235987755982988, 1e-15);
  EXPECT_EQ(q.dimension, dim::angle);
}

TEST(UnitsParse, NegativeDegrees) { EXPECT_DOUBLE_EQ(quantity("-45 deg").si, -45 * kDeg); }

TEST(UnitsParse, Radians) {
  const Quantity q = quantity("1.5 rad");
  EXPECT_DOUBLE_EQ(q.si, 1.5);
  EXPECT_EQ(q.dimension, dim::angle);
}

TEST(UnitsParse, PowersScaleTheFactor) {
  EXPECT_DOUBLE_EQ(quantity("4 mm^2").si, 4e-6);
  EXPECT_EQ(quantity("4 mm^2").dimension, dim::length.pow(2));
  EXPECT_DOUBLE_EQ(quantity("1 cm^3").si, 1e-6);
  EXPECT_EQ(quantity("1 cm^3").dimension, dim::length.pow(3));
}

TEST(UnitsParse, NegativePower) {
  const Quantity q = quantity("2 mm^-1");
  EXPECT_DOUBLE_EQ(q.si, 2000.0);
  EXPECT_EQ(q.dimension, (Dimension{{-1, 0, 0, 0}}));
}

TEST(UnitsParse, PowerInTheDenominator) {
  const Quantity q = quantity("9.81 m/s^2");
  EXPECT_DOUBLE_EQ(q.si, 9.81);
  EXPECT_EQ(q.dimension, (Dimension{{1, 0, -2, 0}}));
}

TEST(UnitsParse, ReadLeftToRight) {
  // N/m*s is (N/m)*s, not N/(m*s).
  EXPECT_EQ(quantity("1 N/m*s").dimension, (Dimension{{0, 1, -1, 0}}));
  EXPECT_EQ(quantity("1 N/m/s").dimension, (Dimension{{0, 1, -3, 0}}));
}

TEST(UnitsParse, Pressure) {
  const Quantity q = quantity("3 MPa");
  EXPECT_DOUBLE_EQ(q.si, 3e6);
  EXPECT_EQ(q.dimension, (Dimension{{-1, 1, -2, 0}}));
}

TEST(UnitsParse, SignsAndExponents) {
  EXPECT_DOUBLE_EQ(quantity("-3.5e2 N").si, -350.0);
  EXPECT_DOUBLE_EQ(quantity("+5 mm").si, 0.005);
  EXPECT_DOUBLE_EQ(quantity("1.5E3 mN").si, 1.5);
  EXPECT_DOUBLE_EQ(quantity(".5 kg").si, 0.5);
}

TEST(UnitsParse, BareNumberIsDimensionless) {
  const Quantity q = quantity("42");
  EXPECT_DOUBLE_EQ(q.si, 42.0);
  EXPECT_EQ(q.dimension, dim::none);
}

TEST(UnitsParse, Whitespace) {
  EXPECT_DOUBLE_EQ(quantity("  18   mm  ").si, 0.018);
  EXPECT_DOUBLE_EQ(quantity("18\tmm").si, 0.018);
  EXPECT_DOUBLE_EQ(quantity("\t7\t").si, 7.0);
  EXPECT_EQ(quantity("  18   mm  ").dimension, dim::length);
}

TEST(UnitsParse, UnitNamesAreCaseSensitive) {
  EXPECT_EQ(quantity_error("18 MM"), "unknown unit 'MM'");
  EXPECT_EQ(quantity_error("5 kn"), "unknown unit 'kn'");
  EXPECT_DOUBLE_EQ(quantity("3 mN").si, 3e-3);
}

// ---------------------------------------------------------------- bad units

TEST(UnitsParse, UnknownUnit) { EXPECT_EQ(quantity_error("30 furlongs"), "unknown unit 'furlongs'"); }

TEST(UnitsParse, UnknownUnitInAProduct) { EXPECT_EQ(quantity_error("30 N*furlongs"), "unknown unit 'furlongs'"); }

TEST(UnitsParse, SpaceBetweenUnits) {
  EXPECT_EQ(quantity_error("30 N m"), "'*' or '/' between units, found ' '");
}

TEST(UnitsParse, OtherSeparator) {
  EXPECT_EQ(quantity_error("30 N.m"), "'*' or '/' between units, found '.'");
  EXPECT_EQ(quantity_error("30 N-m"), "'*' or '/' between units, found '-'");
}

TEST(UnitsParse, TwoOperators) { EXPECT_EQ(quantity_error("30 N//m"), "a unit name at '/m'"); }

TEST(UnitsParse, LeadingOperator) { EXPECT_EQ(quantity_error("30 /m"), "a unit name at '/m'"); }

TEST(UnitsParse, TrailingOperator) {
  EXPECT_EQ(quantity_error("30 N*"), "a unit name after '*'");
  EXPECT_EQ(quantity_error("600 N/"), "a unit name after '/'");
}

TEST(UnitsParse, PowerWithoutExponent) {
  EXPECT_EQ(quantity_error("30 m^"), "an integer power after '^'");
  EXPECT_EQ(quantity_error("30 m^x"), "an integer power after '^'");
}

TEST(UnitsParse, FractionalPower) {
  EXPECT_EQ(quantity_error("30 m^1.5"), "'*' or '/' between units, found '.'");
}

// ---------------------------------------------------------------- bad numbers

TEST(UnitsParse, NotANumber) {
  EXPECT_EQ(quantity_error("abc mm"), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error("mm"), "a finite number followed by a unit");
}

TEST(UnitsParse, EmptyText) {
  EXPECT_EQ(quantity_error(""), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error("   "), "a finite number followed by a unit");
}

TEST(UnitsParse, NoSpaceBeforeTheUnit) {
  EXPECT_EQ(quantity_error("18mm"), "a finite number followed by a unit");
}

TEST(UnitsParse, NonFiniteNumbers) {
  EXPECT_EQ(quantity_error("1e999 N"), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error("inf N"), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error("-inf N"), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error("nan"), "a finite number followed by a unit");
  EXPECT_EQ(quantity_error(".inf"), "a finite number followed by a unit");
}

TEST(UnitsParse, DecimalComma) { EXPECT_EQ(quantity_error("1,5 mm"), "a finite number followed by a unit"); }

TEST(UnitsParse, HexNumber) { EXPECT_EQ(quantity_error("0x10 mm"), "a finite number followed by a unit"); }

TEST(UnitsNumber, ParseNumber) {
  EXPECT_EQ(parse_number("1e3"), 1000.0);
  EXPECT_EQ(parse_number("+2"), 2.0);
  EXPECT_EQ(parse_number(" 7 "), 7.0);
  EXPECT_EQ(parse_number("-0.25"), -0.25);
  EXPECT_EQ(parse_number(""), std::nullopt);
  EXPECT_EQ(parse_number("1.5x"), std::nullopt);
  EXPECT_EQ(parse_number("1e999"), std::nullopt);
  EXPECT_EQ(parse_number("inf"), std::nullopt);
  EXPECT_EQ(parse_number("nan"), std::nullopt);
  EXPECT_EQ(parse_number("++2"), std::nullopt);
  EXPECT_EQ(parse_number("2 mm"), std::nullopt);
}

// ---------------------------------------------------------------- parse_unit

TEST(UnitsUnit, FactorOfAUnit) {
  std::string error;
  const std::optional<Quantity> mm = parse_unit("mm", &error);
  ASSERT_TRUE(mm.has_value());
  EXPECT_DOUBLE_EQ(mm->si, 1e-3);
  EXPECT_EQ(mm->dimension, dim::length);
  const std::optional<Quantity> deg = parse_unit(" deg ", &error);
  ASSERT_TRUE(deg.has_value());
  EXPECT_DOUBLE_EQ(deg->si, kDeg);
}

TEST(UnitsUnit, EmptyUnit) {
  EXPECT_EQ(unit_error(""), "no unit");
  EXPECT_EQ(unit_error("  "), "no unit");
}

TEST(UnitsUnit, NumberIsNotAUnit) { EXPECT_EQ(unit_error("1/s"), "a unit name at '1/s'"); }

// ---------------------------------------------------------------- dimensions

TEST(UnitsDimension, EqualWhateverTheSpelling) {
  EXPECT_EQ(unit_dimension("N/m"), unit_dimension("kg/s^2"));
  EXPECT_EQ(unit_dimension("N*m"), unit_dimension("J"));
  EXPECT_EQ(unit_dimension("N"), unit_dimension("kg*m/s^2"));
  EXPECT_EQ(unit_dimension("Pa"), unit_dimension("N/m^2"));
  EXPECT_EQ(unit_dimension("deg"), unit_dimension("rad"));
  EXPECT_EQ(unit_dimension("Hz"), dim::time.pow(-1));
}

TEST(UnitsDimension, AngleIsItsOwnDimension) {
  EXPECT_NE(unit_dimension("N*m/rad"), dim::torque);
  EXPECT_NE(dim::angle, dim::none);
  EXPECT_EQ(unit_dimension("N*m*s/rad"), dim::rotational_damping);
}

TEST(UnitsDimension, Arithmetic) {
  EXPECT_EQ(dim::force * dim::length, dim::torque);
  EXPECT_EQ(dim::force / dim::length, dim::stiffness);
  EXPECT_EQ(dim::force / dim::length.pow(3), dim::cubic_stiffness);
  EXPECT_EQ(dim::mass * dim::length.pow(2), dim::inertia);
  EXPECT_EQ(dim::angle / dim::time, dim::angular_speed);
  EXPECT_EQ(dim::length / dim::time, dim::speed);
  EXPECT_EQ(dim::length.pow(0), dim::none);
  EXPECT_NE(dim::stiffness, dim::torque);
}

TEST(UnitsDimension, Str) {
  EXPECT_EQ(dim::none.str(), "1");
  EXPECT_EQ(dim::length.str(), "m");
  EXPECT_EQ(dim::force.str(), "m*kg/s^2");
  EXPECT_EQ(dim::inertia.str(), "m^2*kg");
  EXPECT_EQ(dim::time.pow(-1).str(), "1/s");
}

TEST(UnitsDimension, StrWithSeveralDenominatorsReadsBackTheSame) {
  // Units read left to right, so "kg/m*s^2" would mean kg*s^2/m.
  const Dimension pressure{{-1, 1, -2, 0}};
  EXPECT_EQ(pressure.str(), "kg/m/s^2");
  EXPECT_EQ(dim::rotational_damping.str(), "m^2*kg/s/rad");
  for (const Dimension& d : {pressure, dim::rotational_damping, dim::force, dim::cubic_stiffness,
                             dim::angular_speed, dim::inertia}) {
    EXPECT_EQ(unit_dimension(d.str()), d) << d.str();
  }
}

TEST(UnitsDimension, Describe) {
  EXPECT_EQ(describe_dimension(dim::none), "a plain number");
  EXPECT_EQ(describe_dimension(dim::length), "a length (e.g. '18 mm')");
  EXPECT_EQ(describe_dimension(dim::angle), "an angle (e.g. '30 deg')");
  EXPECT_EQ(describe_dimension(dim::force), "a force (e.g. '30 N')");
  EXPECT_EQ(describe_dimension(dim::stiffness), "a stiffness (e.g. '800 N/m')");
  EXPECT_EQ(describe_dimension(dim::torque), "a torque (e.g. '0.02 N*m')");
  EXPECT_EQ(describe_dimension(dim::rotational_damping), "a rotational damping (e.g. '0.001 N*m*s/rad')");
  EXPECT_EQ(describe_dimension(dim::inertia), "a moment of inertia (e.g. '2e-5 kg*m^2')");
  EXPECT_EQ(describe_dimension(Dimension{{-1, 1, -2, 0}}), "a quantity in kg/m/s^2");
}

TEST(UnitsDimension, EveryDescribedExampleHasItsDimension) {
  // The example in each description must itself be a quantity of that kind.
  for (const Dimension& d : {dim::length, dim::mass, dim::time, dim::angle, dim::force, dim::stiffness,
                             dim::cubic_stiffness, dim::torque, dim::rotational_damping, dim::inertia,
                             dim::speed, dim::angular_speed}) {
    const std::string text = describe_dimension(d);
    const size_t open = text.find("'");
    const size_t close = text.rfind("'");
    ASSERT_NE(open, close) << text;
    EXPECT_EQ(quantity(text.substr(open + 1, close - open - 1)).dimension, d) << text;
  }
}

// ---------------------------------------------------------------- format_quantity

TEST(UnitsFormat, InTheUnitAUserReads) {
  EXPECT_EQ(format_quantity(0.018, dim::length), "18 mm");
  EXPECT_EQ(format_quantity(-0.0025, dim::length), "-2.5 mm");
  EXPECT_EQ(format_quantity(0.19, dim::mass), "190 g");
  EXPECT_EQ(format_quantity(30 * kDeg, dim::angle), "30 deg");
  EXPECT_EQ(format_quantity(600, dim::stiffness), "600 N/m");
  EXPECT_EQ(format_quantity(0.02, dim::torque), "0.02 N*m");
  EXPECT_EQ(format_quantity(0.0005, dim::rotational_damping), "0.0005 N*m*s/rad");
  EXPECT_EQ(format_quantity(2e-5, dim::inertia), "2e-05 kg*m^2");
  EXPECT_EQ(format_quantity(2e6, dim::cubic_stiffness), "2e+06 N/m^3");
  EXPECT_EQ(format_quantity(0.2, dim::time), "0.2 s");
}

TEST(UnitsFormat, FourSignificantDigits) {
  EXPECT_EQ(format_quantity(1234.5678, dim::force), "1235 N");
  EXPECT_EQ(format_quantity(123456.0, dim::force), "1.235e+05 N");
  EXPECT_EQ(format_quantity(0.026179938779914945, dim::length), "26.18 mm");
}

TEST(UnitsFormat, OtherDimensionsInBaseUnits) {
  EXPECT_EQ(format_quantity(1000, Dimension{{-1, 1, -2, 0}}), "1000 kg/m/s^2");
}

TEST(UnitsFormat, ReadsBack) {
  for (const auto& [si, d] : {std::pair{0.018, dim::length}, std::pair{0.19, dim::mass},
                              std::pair{30 * kDeg, dim::angle}, std::pair{600.0, dim::stiffness},
                              std::pair{0.0005, dim::rotational_damping}, std::pair{2e-5, dim::inertia},
                              std::pair{1000.0, Dimension{{-1, 1, -2, 0}}}}) {
    const std::string text = format_quantity(si, d);
    const Quantity q = quantity(text);
    EXPECT_NEAR(q.si, si, 1e-12 * std::abs(si)) << text;
    EXPECT_EQ(q.dimension, d) << text;
  }
}

}  // namespace
}  // namespace afford
