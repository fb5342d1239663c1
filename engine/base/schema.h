// The keys of every YAML mapping, declared once: the loader reads the
// mapping with them (MapReader) and json_schema.cpp writes them out as a
// JSON Schema for editors, so the two cannot disagree on a key.
#pragma once

#include <string>
#include <vector>

#include "units.h"

namespace afford {

struct MapSchema;

// What one value may be.
struct ValueSchema {
  enum class Type {
    quantity,      // "<number> <unit>" of `dimension`
    number,        // a bare finite number
    integer,       // a whole number, decimal or 0x hex
    boolean,       // true or false
    name,          // [A-Za-z_][A-Za-z0-9_-]*
    text,          // any string
    path,          // a file, relative to the file that names it
    choice,        // one of `choices`
    expression,    // a predicate expression (rules)
    vector,        // three quantities of `dimension`
    plain_vector,  // three bare numbers
    sequence,      // of items[0] (its first element items[1], if given), min_items..max_items long
    mapping,       // the keys of `mapping`
    any_of,        // one of the alternatives in `items`
  };
  Type type = Type::text;
  Dimension dimension{};
  std::vector<std::string> choices;
  const MapSchema* mapping = nullptr;
  std::vector<ValueSchema> items;
  size_t min_items = 0;
  size_t max_items = 0;  // 0: no bound
};

struct KeySchema {
  std::string key;
  ValueSchema value;
  bool required = false;
  std::string description;  // one line, for the editor's hover
};

// Keys required only when another key has a given value (rig: plates
// needs an actee) or has not, or is absent (any other rig an object).
struct RequiredWhen {
  std::string key;
  std::string value;
  std::vector<std::string> then_required;
  std::vector<std::string> otherwise_required;
};

// A key's value held to a stricter schema when the mapping lacks another
// key (a rule test without rules needs them in its session).
struct StricterWithout {
  std::string missing_key;
  std::string key;
  ValueSchema value;
};

struct MapSchema {
  explicit MapSchema(std::string description_, std::vector<KeySchema> keys_ = {}, bool exactly_one_key_ = false,
                     std::vector<std::vector<std::string>> exactly_one_of_ = {})
      : description(std::move(description_)),
        keys(std::move(keys_)),
        exactly_one_key(exactly_one_key_),
        exactly_one_of(std::move(exactly_one_of_)) {}

  std::string description;
  std::vector<KeySchema> keys;
  bool exactly_one_key = false;  // a tagged union: shape: {box: ...}
  std::vector<std::vector<std::string>> exactly_one_of;  // groups of keys of which one is given
  std::vector<RequiredWhen> required_when;
  std::vector<StricterWithout> stricter_without;

  // The keys the mapping may have, in declaration order (MapReader's list).
  std::vector<std::string> key_names() const;
};

// Builders for the tables beside the loaders.
namespace schema {
ValueSchema quantity(const Dimension& d);
ValueSchema number();
ValueSchema integer();
ValueSchema boolean();
ValueSchema name();
ValueSchema text();
ValueSchema path();
ValueSchema choice(std::vector<std::string> choices);
ValueSchema expression();
ValueSchema vector(const Dimension& d);
ValueSchema plain_vector();
ValueSchema sequence(ValueSchema item, size_t min_items = 0, size_t max_items = 0);
// A sequence whose first element has more to say than the rest.
ValueSchema sequence_starting(ValueSchema first, ValueSchema item, size_t min_items);
ValueSchema mapping(const MapSchema& m);
ValueSchema any_of(std::vector<ValueSchema> alternatives);

KeySchema required_key(std::string key, ValueSchema value, std::string description);
KeySchema optional_key(std::string key, ValueSchema value, std::string description);
}  // namespace schema

}  // namespace afford
