#include "yaml_reader.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/eventhandler.h>

#include "did_you_mean.h"

namespace afford {
namespace {

SourceLoc loc_of(const YAML::Mark& mark, const std::string& file) {
  // yaml-cpp counts from 0; editors count from 1.
  return SourceLoc{file, mark.line + 1, mark.column + 1};
}

// Where the second document of a file starts: the first "---" line after
// some content (a "---" before any content only opens the first document).
// line 0 when there is none.
SourceLoc second_document(const std::string& text, const std::string& name) {
  bool content = false;
  int line = 1;
  for (size_t at = 0; at < text.size(); ++line) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string_view l(text.data() + at, end - at);
    const bool marker = l.substr(0, 3) == "---" && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
    if (marker && content) return SourceLoc{name, line, 1};
    const size_t first = l.find_first_not_of(" \t\r");
    if (!marker && first != std::string_view::npos && l[first] != '#' && l[first] != '%') content = true;
    at = end + 1;
  }
  return SourceLoc{name, 0, 0};
}

// Nesting and size limits, checked without recursion so that a deep file
// cannot overflow the stack here either.
void check_shape(const YAML::Node& root, const std::string& name) {
  std::vector<std::pair<YAML::Node, int>> todo{{root, 1}};
  size_t count = 0;
  while (!todo.empty()) {
    auto [node, depth] = todo.back();
    todo.pop_back();
    if (++count > kMaxYamlNodes) {
      fail(loc_of(node.Mark(), name), "at most " + std::to_string(kMaxYamlNodes) + " values in a file",
           "more");
    }
    if (depth > kMaxYamlDepth) {
      fail(loc_of(node.Mark(), name), "at most " + std::to_string(kMaxYamlDepth) + " levels of nesting",
           "a value nested deeper");
    }
    // Children pushed last first, so that they are visited in file order and
    // the error names the first value past the limit. (Never assign or swap
    // YAML::Nodes: assignment writes into the tree.)
    std::vector<YAML::Node> children;
    if (node.IsMap()) {
      for (auto it = node.begin(); it != node.end(); ++it) {
        children.push_back(it->first);
        children.push_back(it->second);
      }
    } else if (node.IsSequence()) {
      for (auto it = node.begin(); it != node.end(); ++it) children.push_back(*it);
    }
    for (size_t i = children.size(); i-- > 0;) todo.emplace_back(children[i], depth + 1);
  }
}

// The start of each document, seen by yaml-cpp's event parser. It ignores
// the nodes: it only counts documents, and stops at the second.
struct DocumentStarts : YAML::EventHandler {
  std::vector<YAML::Mark> starts;
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

// A second document ('...' then more) is an error at its start. yaml-cpp
// 0.7 reads a ',' where no node can start as an empty document without
// moving on, for ever (YAML::LoadAll then fills the memory): a document
// that starts where the one before it did is that ','.
void check_one_document(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts documents;
  while (documents.starts.size() < 2 && parser.HandleNextDocument(documents)) {
  }
  if (documents.starts.size() < 2) return;
  const YAML::Mark& first = documents.starts[0];
  const YAML::Mark& second = documents.starts[1];
  if (second.pos == first.pos) {
    const char found = static_cast<size_t>(second.pos) < text.size() ? text[second.pos] : ' ';
    fail(loc_of(second, name), "valid YAML", std::string("'") + found + "' where no YAML node can start");
  }
  fail(loc_of(second, name), "one YAML document per file", "a second document");
}

// Whether yaml-cpp's first document of text, whose root is `root`, can only
// have ended where the text does, so that check_one_document, a second parse
// of the whole text, has nothing to find. yaml-cpp's scanner ends a block
// mapping whose keys start at column 0 only at a '---', '...' or '%' that
// starts a line (the first, before any content, opens the document; one
// after content is refused before parsing), or at the end of the text.
bool ends_with_the_text(const YAML::Node& root, const std::string& text) {
  if (!root.IsMap() || root.Style() != YAML::EmitterStyle::Block || root.size() == 0) return false;
  if (root.Mark().column != 0 || root.begin()->first.Mark().column != 0) return false;
  // UTF-16 and UTF-32 (which yaml-cpp decodes) hold their '.' after a 0.
  if (text.find('\0') != std::string::npos) return false;
  const size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // after a byte order mark
  for (size_t at = start; at < text.size(); ++at) {
    const bool line_start = at == start || text[at - 1] == '\n' || text[at - 1] == '\r';
    if (line_start && (text[at] == '.' || text[at] == '%')) return false;
  }
  return true;
}

Node parse(const std::string& raw, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  if (raw.size() > kMaxYamlBytes) {
    fail(SourceLoc{name, 1, 1}, "a file of at most " + std::to_string(kMaxYamlBytes) + " bytes",
         std::to_string(raw.size()) + " bytes");
  }
  const std::string text = without_leading_comments(raw);
  // Before parsing: a broken second document must not hide behind its own
  // syntax error.
  if (const SourceLoc second = second_document(text, name); second.line > 0) {
    fail(second, "one YAML document per file", "a second document ('---')");
  }
  try {
    // The first document's own errors are the same from either parse.
    const YAML::Node root = YAML::Load(text);
    if (!ends_with_the_text(root, text)) check_one_document(text, name);
    if (!root.IsDefined() || root.IsNull()) {
      throw DataError(SourceLoc{name, 1, 1}, "expected a YAML mapping, found an empty file");
    }
    check_shape(root, name);
    return Node(root, file);
  } catch (const YAML::ParserException& e) {
    throw DataError(loc_of(e.mark, name), "expected valid YAML, found a syntax error: " + e.msg);
  }
}

std::string quoted(const std::string& s) { return shorten(s); }

// Physically meaningful magnitudes for a hand, a hand tool and what it
// acts on: larger (or, for a value that must be positive, smaller) is a
// typing mistake, and would run to inf in the solver.
struct Bounds {
  Dimension dimension;
  double smallest;  // least positive value
  double largest;   // largest magnitude
};
constexpr Bounds kBounds[] = {
    {dim::length, 1e-6, 10},              // 1 µm .. 10 m
    {dim::mass, 1e-6, 1e3},               // 1 mg .. 1 t
    {dim::time, 1e-9, 3600},              // 1 ns .. 1 h
    {dim::angle, 1e-9, 1e3},              // rad
    {dim::force, 1e-6, 1e5},              // N
    {dim::stiffness, 1e-3, 1e9},          // N/m
    {dim::cubic_stiffness, 1e-3, 1e15},   // N/m^3
    {dim::torque, 1e-9, 1e4},             // N*m
    {dim::rotational_damping, 1e-9, 1e3}, // N*m*s/rad
    {dim::inertia, 1e-12, 10},            // kg*m^2
    {dim::speed, 1e-9, 100},              // m/s
    {dim::angular_speed, 1e-9, 1e4},      // rad/s
};

const Bounds* bounds_of(const Dimension& d) {
  for (const Bounds& b : kBounds) {
    if (b.dimension == d) return &b;
  }
  return nullptr;
}

const char* const kWhy = " (the range that makes sense for a hand tool)";

}  // namespace

Node::Node(YAML::Node node, std::shared_ptr<const std::string> file)
    : node_(std::move(node)), file_(std::move(file)) {}

SourceLoc Node::loc() const { return loc_of(node_.Mark(), *file_); }

Node Node::operator[](size_t i) const { return Node(node_[i], file_); }

Node Node::child(const YAML::Node& node) const { return Node(node, file_); }

Node key_node(const Node& map, std::string_view key) {
  for (auto it = map.yaml().begin(); it != map.yaml().end(); ++it) {
    if (it->first.Scalar() == key) return map.child(it->first);
  }
  return map;
}

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

// yaml-cpp reads a comment a character at a time through its regular
// expressions, some 440 instructions a byte, and the shipped files
// open with their sources and reasons: over half their bytes. The comment lines
// before the first content are emptied, their line ends kept, so that
// every line and column stays where it was; nothing there can be inside a
// scalar. Only lines of spaces and a '#' (yaml-cpp decides what a tab
// means), and not in UTF-16 or UTF-32, whose ASCII holds zeros.
std::string without_leading_comments(const std::string& text) {
  if (text.find('\0') != std::string::npos) return text;
  std::string out;
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find_first_of("\r\n", at);
    if (end == std::string::npos) end = text.size();
    const size_t first = text.find_first_not_of(' ', at);
    const bool blank = first >= end;
    if (!blank && text[first] != '#') break;  // content, or a tab: from here on as it is
    if (blank) out.append(text, at, end - at);
    size_t next = end;
    if (next < text.size() && text[next] == '\r') ++next;
    if (next < text.size() && text[next] == '\n') ++next;
    out.append(text, end, next - end);
    at = next;
  }
  if (at == 0) return text;
  out.append(text, at, std::string::npos);
  return out;
}

Node load_yaml_file(const std::string& path) { return parse(read_regular_file(path, kMaxYamlBytes), path); }

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
      key.fail(expected + ")", shorten(name) + did_you_mean(name, keys_));
    }
  }
}

MapReader::MapReader(const Node& node, std::string what, const MapSchema& schema)
    : MapReader(node, std::move(what), schema.key_names()) {}

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
  if (const Bounds* b = bounds_of(expected); b && !at_most(std::abs(q->si), b->largest)) {
    node.fail(describe_dimension(expected) + " of at most " + format_quantity(b->largest, expected) + " in size" + kWhy);
  }
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
  node.fail(expected, shorten(s) + did_you_mean(s, names));
}

double require_positive(const Node& node, double value) {
  if (!(value > 0)) node.fail("a value greater than zero");
  return value;
}

double require_at_least_smallest(const Node& node, const Dimension& expected, double value) {
  if (const Bounds* b = bounds_of(expected); b && value > 0 && !at_least(value, b->smallest)) {
    node.fail(describe_dimension(expected) + " of at least " + format_quantity(b->smallest, expected) + kWhy);
  }
  return value;
}

double read_positive(const Node& node, const Dimension& expected) {
  const double v = require_positive(node, read_quantity(node, expected));
  return require_at_least_smallest(node, expected, v);
}

double read_non_negative(const Node& node, const Dimension& expected) {
  const double v = require_non_negative(node, read_quantity(node, expected));
  return require_at_least_smallest(node, expected, v);
}

double require_non_negative(const Node& node, double value) {
  if (!(value >= 0)) node.fail("a value of zero or more");
  return value;
}

}  // namespace afford
