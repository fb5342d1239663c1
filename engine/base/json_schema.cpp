#include "json_schema.h"

#include <nlohmann/json.hpp>

#include "errors.h"

namespace afford {
namespace {

using Json = nlohmann::ordered_json;  // keys in the tables' order

// What the loaders accept as text, in the subset of regular expressions
// that JSON Schema validators share.
constexpr const char* kNumber = "-?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?";
constexpr const char* kUnit = "[A-Za-z][A-Za-z0-9*/^-]*";
constexpr const char* kName = "^[A-Za-z_][A-Za-z0-9_-]*$";
constexpr const char* kInteger = "^(0[xX][0-9a-fA-F]+|-?[0-9]+)$";

Json map_schema(const MapSchema& m);

Json value_schema(const ValueSchema& v) {
  using Type = ValueSchema::Type;
  switch (v.type) {
    case Type::quantity:
      return {{"type", "string"},
              {"pattern", std::string("^\\s*") + kNumber + "\\s+" + kUnit + "\\s*$"},
              {"description", describe_dimension(v.dimension)}};
    case Type::number:
      // A number the YAML parser did not take for one ("1e-3") is text.
      return {{"type", Json::array({"number", "string"})}, {"pattern", std::string("^") + kNumber + "$"}};
    case Type::integer:
      return {{"type", Json::array({"integer", "string"})}, {"pattern", kInteger}};
    case Type::boolean:
      return {{"type", "boolean"}};
    case Type::name:
      return {{"type", "string"}, {"pattern", kName}};
    case Type::text:
      return {{"type", "string"}};
    case Type::path:
      return {{"type", "string"}, {"minLength", 1}, {"description", "a file, relative to this file's folder"}};
    case Type::choice:
      return {{"enum", v.choices}};
    case Type::expression:
      return {{"type", "string"}, {"description", "a predicate expression (afford rules --list)"}};
    case Type::vector: {
      const Json item = value_schema(schema::quantity(v.dimension));
      return {{"type", "array"}, {"items", item}, {"minItems", 3}, {"maxItems", 3}};
    }
    case Type::plain_vector:
      return {{"type", "array"}, {"items", value_schema(schema::number())}, {"minItems", 3}, {"maxItems", 3}};
    case Type::sequence: {
      Json s = {{"type", "array"}};
      if (v.items.size() == 2) {
        s["items"] = Json::array({value_schema(v.items[1])});
        s["additionalItems"] = value_schema(v.items[0]);
      } else {
        s["items"] = value_schema(v.items.at(0));
      }
      if (v.min_items > 0) s["minItems"] = v.min_items;
      if (v.max_items > 0) s["maxItems"] = v.max_items;
      return s;
    }
    case Type::mapping:
      return map_schema(*v.mapping);
    case Type::any_of: {
      Json alternatives = Json::array();
      for (const ValueSchema& a : v.items) alternatives.push_back(value_schema(a));
      return {{"anyOf", alternatives}};
    }
  }
  throw LogicError("json_schema: a value type without a schema");
}

Json map_schema(const MapSchema& m) {
  Json properties = Json::object();
  Json required = Json::array();
  for (const KeySchema& k : m.keys) {
    Json p = value_schema(k.value);
    // The key's own description first; a value's (a dimension, ...) after
    // it, but a mapping's is the same thing said twice.
    const bool add_value = p.contains("description") && k.value.type != ValueSchema::Type::mapping;
    const std::string what = add_value ? k.description + ": " + p["description"].get<std::string>() : k.description;
    p.erase("description");
    Json described = {{"description", what}};
    described.update(p);
    properties[k.key] = described;
    if (k.required) required.push_back(k.key);
  }
  Json s = {{"type", "object"}, {"description", m.description}, {"properties", properties}};
  if (!required.empty()) s["required"] = required;
  s["additionalProperties"] = false;
  if (m.exactly_one_key) {
    s["minProperties"] = 1;
    s["maxProperties"] = 1;
  }
  Json all = Json::array();
  for (const std::vector<std::string>& group : m.exactly_one_of) {
    Json one = Json::array();
    for (const std::string& key : group) one.push_back({{"required", Json::array({key})}});
    all.push_back({{"oneOf", one}});
  }
  for (const RequiredWhen& r : m.required_when) {
    Json is = {{"properties", {{r.key, {{"const", r.value}}}}}, {"required", Json::array({r.key})}};
    all.push_back({{"if", is},
                   {"then", {{"required", r.then_required}}},
                   {"else", {{"required", r.otherwise_required}}}});
  }
  for (const StricterWithout& w : m.stricter_without) {
    Json lacks = {{"not", {{"required", Json::array({w.missing_key})}}}};
    all.push_back({{"if", lacks}, {"then", {{"properties", {{w.key, value_schema(w.value)}}}}}});
  }
  if (!all.empty()) s["allOf"] = all;
  return s;
}

}  // namespace

std::string json_schema(const std::string& kind, const MapSchema& root) {
  Json s = {{"$schema", "http://json-schema.org/draft-07/schema#"},
            {"title", "afford " + kind + " file"}};
  s.update(map_schema(root));
  return s.dump(2) + "\n";
}

}  // namespace afford
