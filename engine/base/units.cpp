#include "units.h"

#include <charconv>
#include <cstdio>
#include <cmath>
#include <numbers>

namespace afford {
namespace {

struct UnitDef {
  std::string_view name;
  double factor;  // to SI
  Dimension dimension;
};

constexpr double kPi = std::numbers::pi;

// The units a user may write. Kept short on purpose: every entry is one a
// tool, actee or hand file plausibly needs.
constexpr UnitDef kUnits[] = {
    {"m", 1.0, dim::length},       {"cm", 1e-2, dim::length},
    {"mm", 1e-3, dim::length},     {"um", 1e-6, dim::length},
    {"kg", 1.0, dim::mass},        {"g", 1e-3, dim::mass},
    {"s", 1.0, dim::time},         {"ms", 1e-3, dim::time},
    {"us", 1e-6, dim::time},       {"min", 60.0, dim::time},
    {"N", 1.0, dim::force},        {"kN", 1e3, dim::force},
    {"mN", 1e-3, dim::force},      {"rad", 1.0, dim::angle},
    {"deg", kPi / 180.0, dim::angle}, {"Pa", 1.0, Dimension{{-1, 1, -2, 0}}},
    {"kPa", 1e3, Dimension{{-1, 1, -2, 0}}}, {"MPa", 1e6, Dimension{{-1, 1, -2, 0}}},
    {"J", 1.0, dim::torque},       {"Hz", 1.0, Dimension{{0, 0, -1, 0}}},
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension r;
  for (size_t i = 0; i < exponent.size(); ++i) r.exponent[i] = exponent[i] + o.exponent[i];
  return r;
}

Dimension Dimension::operator/(const Dimension& o) const {
  Dimension r;
  for (size_t i = 0; i < exponent.size(); ++i) r.exponent[i] = exponent[i] - o.exponent[i];
  return r;
}

Dimension Dimension::pow(int p) const {
  Dimension r;
  for (size_t i = 0; i < exponent.size(); ++i) r.exponent[i] = exponent[i] * p;
  return r;
}

std::string Dimension::str() const {
  static constexpr const char* kBase[] = {"m", "kg", "s", "rad"};
  std::string num, den;
  for (size_t i = 0; i < exponent.size(); ++i) {
    const int e = exponent[i];
    if (e == 0) continue;
    std::string& side = e > 0 ? num : den;
    // Read left to right, so each factor below the line gets its own '/'.
    if (!side.empty()) side += e > 0 ? "*" : "/";
    side += kBase[i];
    if (std::abs(e) != 1) side += "^" + std::to_string(std::abs(e));
  }
  if (num.empty() && den.empty()) return "1";
  if (num.empty()) num = "1";
  return den.empty() ? num : num + "/" + den;
}

std::string describe_dimension(const Dimension& d) {
  struct Named {
    Dimension d;
    const char* text;
  };
  static const Named kNamed[] = {
      {dim::none, "a plain number"},
      {dim::length, "a length (e.g. '18 mm')"},
      {dim::mass, "a mass (e.g. '120 g')"},
      {dim::time, "a time (e.g. '200 ms')"},
      {dim::angle, "an angle (e.g. '30 deg')"},
      {dim::force, "a force (e.g. '30 N')"},
      {dim::stiffness, "a stiffness (e.g. '800 N/m')"},
      {dim::cubic_stiffness, "a cubic stiffness (e.g. '2e6 N/m^3')"},
      {dim::torque, "a torque (e.g. '0.02 N*m')"},
      {dim::rotational_damping, "a rotational damping (e.g. '0.001 N*m*s/rad')"},
      {dim::inertia, "a moment of inertia (e.g. '2e-5 kg*m^2')"},
      {dim::damping, "a damping (e.g. '20 N*s/m')"},
      {dim::speed, "a speed (e.g. '5 cm/s')"},
      {dim::angular_speed, "an angular speed (e.g. '1 rad/s')"},
  };
  for (const Named& n : kNamed) {
    if (n.d == d) return n.text;
  }
  return "a quantity in " + d.str();
}

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<Quantity> parse_unit(std::string_view text, std::string* error) {
  text = trim(text);
  Quantity q{1.0, dim::none};
  if (text.empty()) {
    *error = "no unit";
    return std::nullopt;
  }
  bool divide = false;
  size_t i = 0;
  while (i < text.size()) {
    size_t j = i;
    while (j < text.size() && (std::isalpha(static_cast<unsigned char>(text[j])))) ++j;
    const std::string_view name = text.substr(i, j - i);
    const UnitDef* def = nullptr;
    for (const UnitDef& u : kUnits) {
      if (u.name == name) def = &u;
    }
    if (def == nullptr) {
      *error = name.empty() ? "a unit name at '" + std::string(text.substr(i)) + "'"
                            : "unknown unit '" + std::string(name) + "'";
      return std::nullopt;
    }
    int power = 1;
    if (j < text.size() && text[j] == '^') {
      size_t k = j + 1;
      if (k < text.size() && text[k] == '-') ++k;
      while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
      auto [ptr, ec] = std::from_chars(text.data() + j + 1, text.data() + k, power);
      if (ec != std::errc() || ptr != text.data() + k) {
        *error = "an integer power after '^'";
        return std::nullopt;
      }
      j = k;
    }
    const double factor = std::pow(def->factor, power);
    const Dimension d = def->dimension.pow(power);
    if (divide) {
      q.si /= factor;
      q.dimension = q.dimension / d;
    } else {
      q.si *= factor;
      q.dimension = q.dimension * d;
    }
    i = j;
    if (i == text.size()) break;
    if (text[i] == '*') {
      divide = false;  // read left to right: N/m*s is (N/m)*s
    } else if (text[i] == '/') {
      divide = true;
    } else {
      *error = "'*' or '/' between units, found '" + std::string(1, text[i]) + "'";
      return std::nullopt;
    }
    ++i;
    if (i == text.size()) {  // "N/" is not "N"
      *error = "a unit name after '" + std::string(1, text[i - 1]) + "'";
      return std::nullopt;
    }
  }
  return q;
}

std::optional<Quantity> parse_quantity(std::string_view text, std::string* error) {
  text = trim(text);
  size_t split = 0;
  while (split < text.size() && text[split] != ' ' && text[split] != '\t') ++split;
  const std::optional<double> number = parse_number(text.substr(0, split));
  if (!number) {
    *error = "a finite number followed by a unit";
    return std::nullopt;
  }
  const std::string_view unit_text = trim(text.substr(split));
  if (unit_text.empty()) return Quantity{*number, dim::none};
  std::optional<Quantity> unit = parse_unit(unit_text, error);
  if (!unit) return std::nullopt;
  unit->si *= *number;
  return unit;
}

std::string format_quantity(double si, const Dimension& d, int digits) {
  struct Display {
    Dimension d;
    double factor;
    const char* unit;
  };
  static const Display kDisplay[] = {
      {dim::length, 1e-3, "mm"},      {dim::mass, 1e-3, "g"},
      {dim::time, 1.0, "s"},          {dim::angle, 3.14159265358979323846 / 180.0, "deg"},
      {dim::force, 1.0, "N"},         {dim::stiffness, 1.0, "N/m"},
      {dim::torque, 1.0, "N*m"},      {dim::rotational_damping, 1.0, "N*m*s/rad"},
      {dim::inertia, 1.0, "kg*m^2"},  {dim::speed, 1.0, "m/s"},
      {dim::damping, 1.0, "N*s/m"},
      {dim::angular_speed, 1.0, "rad/s"}, {dim::cubic_stiffness, 1.0, "N/m^3"},
  };
  char buf[64];
  if (d == dim::none) {
    std::snprintf(buf, sizeof buf, "%.4g", si);
    return buf;
  }
  for (const Display& disp : kDisplay) {
    if (disp.d == d) {
      std::snprintf(buf, sizeof buf, "%.*g %s", digits, si / disp.factor, disp.unit);
      return buf;
    }
  }
  std::snprintf(buf, sizeof buf, "%.*g %s", digits, si, d.str().c_str());
  return buf;
}

}  // namespace afford
