// The predicate language: parsing text such as
//   force(object, actee) > limit(actee) and contacts(object, actee) >= 2
// into a syntax tree whose every node knows its column, so that a type or
// name error names the exact token.
#pragma once

#include <string>
#include <vector>

#include "errors.h"
#include "units.h"

namespace afford {

enum class ExprKind {
  number,   // a literal, with its unit ("5 cm"): value in SI
  boolean,  // true / false
  call,     // name(args...), name, or entity.name (= name(entity))
  unary,    // - or not
  binary,   // + - * / < <= > >= == != and or
};

struct ExprNode {
  ExprKind kind = ExprKind::number;
  std::string op;                 // operator, or the called name
  std::vector<std::string> args;  // call arguments (entity names)
  std::vector<int> children;      // indices into ExprTree::nodes
  double value = 0;               // number: SI value; boolean: 0 or 1
  Dimension dimension;            // number literal's dimension
  size_t begin = 0, end = 0;      // the source text of this sub-expression: offsets
                                  // into ExprTree::source (a copy each would be
                                  // quadratic in a long chain)
  SourceLoc loc;                  // where it starts
};

// Nodes are stored children first: a node's children have smaller indices,
// so passes over the tree run in index order and never recurse.
struct ExprTree {
  std::vector<ExprNode> nodes;
  int root = -1;
  std::string source;  // the expression as written
  std::string text(const ExprNode& n) const { return source.substr(n.begin, n.end - n.begin); }
  std::string text(int index) const { return text(nodes[static_cast<size_t>(index)]); }
};

// How deeply parentheses may nest in one expression; deeper is a DataError
// at the parenthesis that goes too deep (the parser recurses per level).
inline constexpr int kMaxExprNesting = 64;

// Parses `text`, which starts at `loc` in its file (a YAML scalar: pass its
// location, and quoted = true when the scalar was written in quotes).
// Throws DataError at the offending token.
ExprTree parse_expression(const std::string& text, const SourceLoc& loc, bool quoted);

}  // namespace afford
