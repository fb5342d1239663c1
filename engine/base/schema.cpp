#include "schema.h"

namespace afford {

std::vector<std::string> MapSchema::key_names() const {
  std::vector<std::string> names;
  for (const KeySchema& k : keys) names.push_back(k.key);
  return names;
}

namespace schema {
namespace {

ValueSchema of(ValueSchema::Type type) {
  ValueSchema v;
  v.type = type;
  return v;
}

}  // namespace

using Type = ValueSchema::Type;

ValueSchema quantity(const Dimension& d) {
  ValueSchema v = of(Type::quantity);
  v.dimension = d;
  return v;
}
ValueSchema number() { return of(Type::number); }
ValueSchema integer() { return of(Type::integer); }
ValueSchema boolean() { return of(Type::boolean); }
ValueSchema name() { return of(Type::name); }
ValueSchema text() { return of(Type::text); }
ValueSchema path() { return of(Type::path); }
ValueSchema choice(std::vector<std::string> choices) {
  ValueSchema v = of(Type::choice);
  v.choices = std::move(choices);
  return v;
}
ValueSchema expression() { return of(Type::expression); }
ValueSchema vector(const Dimension& d) {
  ValueSchema v = of(Type::vector);
  v.dimension = d;
  return v;
}
ValueSchema plain_vector() { return of(Type::plain_vector); }
ValueSchema sequence(ValueSchema item, size_t min_items, size_t max_items) {
  ValueSchema v = of(Type::sequence);
  v.items.push_back(std::move(item));
  v.min_items = min_items;
  v.max_items = max_items;
  return v;
}
ValueSchema sequence_starting(ValueSchema first, ValueSchema item, size_t min_items) {
  ValueSchema v = sequence(std::move(item), min_items);
  v.items.push_back(std::move(first));
  return v;
}
ValueSchema mapping(const MapSchema& m) {
  ValueSchema v = of(Type::mapping);
  v.mapping = &m;
  return v;
}
ValueSchema any_of(std::vector<ValueSchema> alternatives) {
  ValueSchema v = of(Type::any_of);
  v.items = std::move(alternatives);
  return v;
}

KeySchema required_key(std::string key, ValueSchema value, std::string description) {
  return {std::move(key), std::move(value), true, std::move(description)};
}
KeySchema optional_key(std::string key, ValueSchema value, std::string description) {
  return {std::move(key), std::move(value), false, std::move(description)};
}

}  // namespace schema
}  // namespace afford
