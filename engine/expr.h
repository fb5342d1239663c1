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
  std::string text;               // the source text of this sub-expression
  SourceLoc loc;                  // where it starts
};

struct ExprTree {
  std::vector<ExprNode> nodes;
  int root = -1;
};

// Parses `text`, which starts at `loc` in its file (a YAML scalar: pass its
// location, and quoted = true when the scalar was written in quotes).
// Throws DataError at the offending token.
ExprTree parse_expression(const std::string& text, const SourceLoc& loc, bool quoted);

}  // namespace afford
