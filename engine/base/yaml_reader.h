// Reading user YAML with the location of every value, so that any mistake,
// found now or later in compilation, is reported as file:line:col.
// Unknown keys, duplicate keys, wrong types and missing keys are errors.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <yaml-cpp/yaml.h>

#include "errors.h"
#include "files.h"
#include "schema.h"
#include "units.h"

namespace afford {

// A YAML node and the file it came from.
class Node {
 public:
  Node(YAML::Node node, std::shared_ptr<const std::string> file);

  SourceLoc loc() const;
  const YAML::Node& yaml() const { return node_; }
  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  size_t size() const { return node_.size(); }
  Node operator[](size_t i) const;  // sequence element
  Node child(const YAML::Node& node) const;  // a node of the same file

  // How the node reads in a "found ..." clause: "'abc'", "a sequence", ...
  std::string found() const;
  [[noreturn]] void fail(const std::string& expected) const;  // found = found()
  [[noreturn]] void fail(const std::string& expected, const std::string& found) const;

 private:
  YAML::Node node_;
  std::shared_ptr<const std::string> file_;
};

// The node of `key` itself in a mapping, for errors about the key (a
// missing file, two keys that exclude each other); the mapping when the key
// is absent.
Node key_node(const Node& map, std::string_view key);

// Limits on a YAML file (documented in the folder READMEs): its size, how
// many values it holds and how deeply they nest. One document per file.
inline constexpr size_t kMaxYamlBytes = size_t{1} << 20;
inline constexpr size_t kMaxYamlNodes = 20000;
inline constexpr int kMaxYamlDepth = 32;

// Loads a YAML file; syntax errors become DataErrors with the parser's mark.
Node load_yaml_file(const std::string& path);
Node load_yaml_string(const std::string& text, const std::string& name);

// The text with the comment lines before its first content emptied (line
// ends kept: every line and column stays), which yaml-cpp reads slowly;
// what the loaders parse.
std::string without_leading_comments(const std::string& text);

// Reads the keys of one mapping against its schema: the keys it may have
// are declared up front, so a key that is not one of them is reported first,
// with "did you mean", before any key counts as missing.
class MapReader {
 public:
  // what: "the lever", ...; keys: every key the mapping may have.
  MapReader(const Node& node, std::string what, std::vector<std::string> keys);
  // The same with the keys of a declared table (schema.h).
  MapReader(const Node& node, std::string what, const MapSchema& schema);
  ~MapReader() = default;
  MapReader(const MapReader&) = delete;
  MapReader& operator=(const MapReader&) = delete;

  Node required(std::string_view key);
  std::optional<Node> optional(std::string_view key);
  bool has(std::string_view key) const;
  const Node& node() const { return node_; }
  // Every key of the map, in file order.
  std::vector<std::pair<std::string, Node>> entries() const;

 private:
  Node node_;
  std::string what_;
  std::vector<std::string> keys_;
};

// Typed scalar reads. Each fails with file:line:col on a wrong type.
std::string read_string(const Node& node);
std::string read_name(const Node& node);  // [A-Za-z_][A-Za-z0-9_-]*
bool read_bool(const Node& node);
double read_number(const Node& node);  // finite, bare
int read_int(const Node& node);
double read_quantity(const Node& node, const Dimension& expected);  // SI value
Eigen::Vector3d read_vector(const Node& node, const Dimension& expected);
Eigen::Vector3d read_plain_vector(const Node& node);  // three bare numbers
// One of `choices`, with "did you mean" on a miss.
std::string read_choice(const Node& node, std::initializer_list<const char*> choices);

// Every quantity read is within the physical bounds of its dimension (a
// length of at most 10 m, a force of at most 100 kN, ...; the table is in
// yaml_reader.cpp and the folder READMEs), and a positive one at least the
// smallest meaningful value. Readers of new parameters (effects, ...) get
// both by calling read_positive or read_non_negative with the dimension.
//
// Range checks that report at the node's location.
double require_positive(const Node& node, double value);
double require_non_negative(const Node& node, double value);
// A quantity that must be > 0 (or >= 0), SI.
double read_positive(const Node& node, const Dimension& expected);
// A value already read that must be zero or at least its dimension's
// smallest meaningful value (5e-324 N/m is a mistake, not a spring).
double require_at_least_smallest(const Node& node, const Dimension& expected, double value);
double read_non_negative(const Node& node, const Dimension& expected);

}  // namespace afford
