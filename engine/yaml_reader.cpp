#include "yaml_reader.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "did_you_mean.h"

namespace afford {
namespace {

SourceLoc loc_of(const YAML::Mark& mark, const std::string& file) {
  // yaml-cpp counts from 0; editors count from 1.
  return SourceLoc{file, mark.line + 1, mark.column + 1};
}

Node parse(const std::string& text, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  try {
    YAML::Node root = YAML::Load(text);
    if (!root.IsDefined() || root.IsNull()) {
      throw DataError(SourceLoc{name, 1, 1}, "expected a YAML mapping, found an empty file");
    }
    return Node(root, file);
  } catch (const YAML::ParserException& e) {
    throw DataError(loc_of(e.mark, name), "expected valid YAML, found a syntax error: " + e.msg);
  }
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

Node::Node(YAML::Node node, std::shared_ptr<const std::string> file)
    : node_(std::move(node)), file_(std::move(file)) {}

SourceLoc Node::loc() const { return loc_of(node_.Mark(), *file_); }

Node Node::operator[](size_t i) const { return Node(node_[i], file_); }

Node Node::child(const YAML::Node& node) const { return Node(node, file_); }

std::string Node::found() const {
  switch (node_.Type()) {
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Sequence: return "a sequence of " + std::to_string(node_.size());
    case YAML::NodeType::Scalar: return quoted(node_.Scalar());
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Undefined: break;
  }
  return "nothing";
}

void Node::fail(const std::string& expected) const { afford::fail(loc(), expected, found()); }

void Node::fail(const std::string& expected, const std::string& found) const {
  afford::fail(loc(), expected, found);
}

Node load_yaml_file(const std::string& path) {
  std::error_code ec;  // a directory opens, then reads as an empty file
  if (std::filesystem::is_directory(path, ec)) {
    throw DataError(SourceLoc{path, 0, 0}, "expected a readable file, found a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(SourceLoc{path, 0, 0}, "expected a readable file, found none");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

Node load_yaml_string(const std::string& text, const std::string& name) { return parse(text, name); }

MapReader::MapReader(const Node& node, std::string what, std::vector<std::string> keys)
    : node_(node), what_(std::move(what)), keys_(std::move(keys)) {
  if (!node.is_map()) node.fail("a mapping for " + what_);
  std::vector<std::string> seen;
  for (auto it = node.yaml().begin(); it != node.yaml().end(); ++it) {
    const Node key = node.child(it->first);
    if (!key.is_scalar()) key.fail("a plain key in " + what_);
    const std::string& name = it->first.Scalar();
    for (const std::string& s : seen) {
      if (s == name) key.fail("each key once in " + what_, "'" + name + "' again");
    }
    seen.push_back(name);
    bool known = false;
    for (const std::string& k : keys_) known = known || k == name;
    if (!known) {
      std::string expected = "one of the keys of " + what_ + " (";
      for (size_t i = 0; i < keys_.size(); ++i) expected += (i ? ", " : "") + keys_[i];
      key.fail(expected + ")", "'" + name + "'" + did_you_mean(name, keys_));
    }
  }
}

Node MapReader::required(std::string_view key) {
  std::optional<Node> n = optional(key);
  if (!n) node_.fail("key '" + std::string(key) + "' in " + what_, "no such key");
  return *n;
}

std::optional<Node> MapReader::optional(std::string_view key) {
  bool declared = false;
  for (const std::string& k : keys_) declared = declared || k == key;
  if (!declared) throw LogicError("MapReader for " + what_ + " asked for undeclared key " + std::string(key));
  for (auto it = node_.yaml().begin(); it != node_.yaml().end(); ++it) {
    if (it->first.Scalar() == key) {
      // A key with no value ("spring:") reads as null: report it at the key.
      if (it->second.IsNull()) {
        node_.child(it->first).fail("a value for '" + std::string(key) + "'", "nothing");
      }
      return node_.child(it->second);
    }
  }
  return std::nullopt;
}

bool MapReader::has(std::string_view key) const {
  for (auto it = node_.yaml().begin(); it != node_.yaml().end(); ++it) {
    if (it->first.Scalar() == key) return true;
  }
  return false;
}

std::vector<std::pair<std::string, Node>> MapReader::entries() const {
  std::vector<std::pair<std::string, Node>> out;
  for (auto it = node_.yaml().begin(); it != node_.yaml().end(); ++it) {
    out.emplace_back(it->first.Scalar(), node_.child(it->second));
  }
  return out;
}

std::string read_string(const Node& node) {
  if (!node.is_scalar()) node.fail("a text");
  return node.yaml().Scalar();
}

std::string read_name(const Node& node) {
  const std::string s = read_string(node);
  bool ok = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
  for (char c : s) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (!ok) node.fail("a name of letters, digits, '_' and '-'");
  return s;
}

bool read_bool(const Node& node) {
  const std::string s = node.is_scalar() ? node.yaml().Scalar() : "";
  if (s == "true") return true;
  if (s == "false") return false;
  node.fail("true or false");
}

double read_number(const Node& node) {
  if (!node.is_scalar()) node.fail("a number");
  const std::optional<double> v = parse_number(node.yaml().Scalar());
  if (!v) node.fail("a finite number");
  return *v;
}

int read_int(const Node& node) {
  const double v = read_number(node);
  if (v != std::floor(v) || std::abs(v) > 1e9) node.fail("a whole number");
  return static_cast<int>(v);
}

double read_quantity(const Node& node, const Dimension& expected) {
  if (!node.is_scalar()) node.fail(describe_dimension(expected));
  std::string error;
  const std::optional<Quantity> q = parse_quantity(node.yaml().Scalar(), &error);
  if (!q) node.fail(describe_dimension(expected) + " (" + error + ")");
  if (!(q->dimension == expected)) {
    const std::string found_dim =
        q->dimension == dim::none ? "a number without a unit" : describe_dimension(q->dimension);
    node.fail(describe_dimension(expected), "'" + node.yaml().Scalar() + "', " + found_dim);
  }
  if (!std::isfinite(q->si)) node.fail("a finite value");
  return q->si;
}

Eigen::Vector3d read_vector(const Node& node, const Dimension& expected) {
  if (!node.is_sequence() || node.size() != 3) {
    node.fail("a sequence of three, each " + describe_dimension(expected));
  }
  return {read_quantity(node[0], expected), read_quantity(node[1], expected),
          read_quantity(node[2], expected)};
}

Eigen::Vector3d read_plain_vector(const Node& node) {
  if (!node.is_sequence() || node.size() != 3) node.fail("a sequence of three numbers");
  return {read_number(node[0]), read_number(node[1]), read_number(node[2])};
}

std::string read_choice(const Node& node, std::initializer_list<const char*> choices) {
  const std::string s = read_string(node);
  std::vector<std::string> names(choices.begin(), choices.end());
  for (const std::string& c : names) {
    if (c == s) return s;
  }
  std::string expected = "one of ";
  for (size_t i = 0; i < names.size(); ++i) expected += (i ? ", " : "") + names[i];
  node.fail(expected, "'" + s + "'" + did_you_mean(s, names));
}

double require_positive(const Node& node, double value) {
  if (!(value > 0)) node.fail("a value greater than zero");
  return value;
}

double read_positive(const Node& node, const Dimension& expected) {
  return require_positive(node, read_quantity(node, expected));
}

double read_non_negative(const Node& node, const Dimension& expected) {
  return require_non_negative(node, read_quantity(node, expected));
}

double require_non_negative(const Node& node, double value) {
  if (!(value >= 0)) node.fail("a value of zero or more");
  return value;
}

}  // namespace afford
