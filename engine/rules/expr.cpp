#include "expr.h"

#include <cctype>
#include <optional>

namespace afford {
namespace {

enum class Tok { number, ident, op, lparen, rparen, comma, dot, end };

struct Token {
  Tok kind = Tok::end;
  std::string text;
  size_t pos = 0;  // offset in the expression text
};

class Parser {
 public:
  Parser(const std::string& text, const SourceLoc& loc, bool quoted)
      : text_(text), loc_(loc), offset_(quoted ? 1 : 0) {
    lex();
  }

  ExprTree parse() {
    tree_.source = text_;
    tree_.root = parse_or();
    if (peek().kind != Tok::end) fail_at(peek(), "an operator or the end of the expression");
    return std::move(tree_);
  }

 private:
  // ---------------------------------------------------------------- lexing
  void lex() {
    size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      Token t;
      t.pos = i;
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && i + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i + 1])))) {
        size_t j = i;
        while (j < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[j])) || text_[j] == '.')) ++j;
        if (j < text_.size() && (text_[j] == 'e' || text_[j] == 'E')) {
          size_t k = j + 1;
          if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
          if (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k]))) {
            j = k;
            while (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
          }
        }
        t.kind = Tok::number;
        t.text = text_.substr(i, j - i);
        i = j;
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        size_t j = i;
        while (j < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[j])) || text_[j] == '_')) ++j;
        t.kind = Tok::ident;
        t.text = text_.substr(i, j - i);
        i = j;
      } else if (c == '(' || c == ')' || c == ',' || c == '.') {
        t.kind = c == '(' ? Tok::lparen : c == ')' ? Tok::rparen : c == ',' ? Tok::comma : Tok::dot;
        t.text = std::string(1, c);
        ++i;
      } else if (c == '<' || c == '>' || c == '=' || c == '!') {
        const bool two = i + 1 < text_.size() && text_[i + 1] == '=';
        t.kind = Tok::op;
        t.text = text_.substr(i, two ? 2 : 1);
        if (t.text == "=" || t.text == "!") {
          tokens_.push_back(t);
          fail_at(t, c == '=' ? "'==' to compare" : "'!=' (or 'not')");
        }
        i += two ? 2 : 1;
      } else if (c == '+' || c == '-' || c == '*' || c == '/' || c == '^') {
        t.kind = Tok::op;
        t.text = std::string(1, c);
        ++i;
      } else {
        t.text = std::string(1, c);
        fail_at(t, "a name, a number, an operator or a parenthesis");
      }
      tokens_.push_back(t);
    }
    Token end;
    end.kind = Tok::end;
    end.pos = text_.size();
    tokens_.push_back(end);
  }

  // ---------------------------------------------------------------- helpers
  const Token& peek(size_t ahead = 0) const { return tokens_[std::min(next_ + ahead, tokens_.size() - 1)]; }
  const Token& take() { return tokens_[next_ < tokens_.size() - 1 ? next_++ : next_]; }
  bool take_op(const char* op) {
    if (peek().kind == Tok::op && peek().text == op) {
      ++next_;
      return true;
    }
    return false;
  }
  bool take_word(const char* word) {
    if (peek().kind == Tok::ident && peek().text == word) {
      ++next_;
      return true;
    }
    return false;
  }

  SourceLoc loc_of(size_t pos) const {
    // Expressions are single-line YAML scalars: columns add up.
    return SourceLoc{loc_.file, loc_.line, loc_.column + offset_ + static_cast<int>(pos)};
  }

  [[noreturn]] void fail_at(const Token& t, const std::string& expected) const {
    const std::string found = t.kind == Tok::end ? "the end of the expression" : "'" + t.text + "'";
    fail(loc_of(t.pos), expected, found);
  }

  void set_span(ExprNode& n, size_t from, size_t to) const {
    while (to > from && std::isspace(static_cast<unsigned char>(text_[to - 1]))) --to;
    n.begin = from;
    n.end = to;
  }

  int add(ExprNode n, size_t from, size_t to) {
    n.loc = loc_of(from);
    set_span(n, from, to);
    tree_.nodes.push_back(std::move(n));
    return static_cast<int>(tree_.nodes.size()) - 1;
  }

  size_t here() const { return peek().pos; }
  size_t start_of(int node) const { return static_cast<size_t>(tree_.nodes[static_cast<size_t>(node)].loc.column - loc_.column - offset_); }

  int binary(const std::string& op, int lhs, int rhs) {
    ExprNode n;
    n.kind = ExprKind::binary;
    n.op = op;
    n.children = {lhs, rhs};
    return add(std::move(n), start_of(lhs), here());
  }

  // ---------------------------------------------------------------- grammar
  int parse_or() {
    int lhs = parse_and();
    while (take_word("or")) lhs = binary("or", lhs, parse_and());
    return lhs;
  }

  int parse_and() {
    int lhs = parse_not();
    while (take_word("and")) lhs = binary("and", lhs, parse_not());
    return lhs;
  }

  // "not not ... x": a loop, not a recursion, however many there are.
  int parse_not() { return prefixed("not", [this] { return take_word("not"); }, &Parser::parse_comparison); }

  template <class Take>
  int prefixed(const char* op, Take take_prefix, int (Parser::*operand)()) {
    std::vector<size_t> starts;
    for (size_t from = here(); take_prefix(); from = here()) starts.push_back(from);
    int inner = (this->*operand)();
    for (size_t i = starts.size(); i-- > 0;) {
      ExprNode n;
      n.kind = ExprKind::unary;
      n.op = op;
      n.children = {inner};
      inner = add(std::move(n), starts[i], here());
    }
    return inner;
  }

  int parse_comparison() {
    const int lhs = parse_sum();
    if (peek().kind == Tok::op) {
      const std::string op = peek().text;
      if (op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=") {
        ++next_;
        const int rhs = parse_sum();
        const int cmp = binary(op, lhs, rhs);
        if (peek().kind == Tok::op && (peek().text[0] == '<' || peek().text[0] == '>' || peek().text == "==" || peek().text == "!=")) {
          fail_at(peek(), "'and' between two comparisons");
        }
        return cmp;
      }
    }
    return lhs;
  }

  int parse_sum() {
    int lhs = parse_product();
    while (peek().kind == Tok::op && (peek().text == "+" || peek().text == "-")) {
      const std::string op = take().text;
      lhs = binary(op, lhs, parse_product());
    }
    return lhs;
  }

  int parse_product() {
    int lhs = parse_unary();
    while (peek().kind == Tok::op && (peek().text == "*" || peek().text == "/")) {
      const std::string op = take().text;
      lhs = binary(op, lhs, parse_unary());
    }
    return lhs;
  }

  int parse_unary() { return prefixed("-", [this] { return take_op("-"); }, &Parser::parse_atom); }

  // A unit after a number binds to it: "5 cm", "0.3 N*m/rad".
  std::optional<std::string> unit_after_number() {
    std::string unit;
    size_t k = next_;
    auto is_unit = [&](const Token& t) {
      std::string error;
      return t.kind == Tok::ident && parse_unit(t.text, &error).has_value();
    };
    if (!is_unit(tokens_[k])) return std::nullopt;
    unit = tokens_[k++].text;
    while (true) {
      if (tokens_[k].kind == Tok::op && tokens_[k].text == "^" && tokens_[k + 1].kind == Tok::number) {
        unit += "^" + tokens_[k + 1].text;
        k += 2;
      } else if (tokens_[k].kind == Tok::op && (tokens_[k].text == "*" || tokens_[k].text == "/") && is_unit(tokens_[k + 1])) {
        unit += tokens_[k].text + tokens_[k + 1].text;
        k += 2;
      } else {
        break;
      }
    }
    next_ = k;
    return unit;
  }

  int parse_atom() {
    const Token& t = peek();
    const size_t from = t.pos;
    if (t.kind == Tok::number) {
      const Token number = take();
      ExprNode n;
      n.kind = ExprKind::number;
      const std::optional<double> v = parse_number(number.text);
      if (!v) fail_at(number, "a finite number");
      n.value = *v;
      if (const std::optional<std::string> unit = unit_after_number()) {
        std::string error;
        const std::optional<Quantity> q = parse_unit(*unit, &error);
        n.value *= q->si;
        n.dimension = q->dimension;
      }
      return add(std::move(n), from, here());
    }
    if (t.kind == Tok::lparen) {
      if (depth_ == kMaxExprNesting) {
        fail_at(t, "at most " + std::to_string(kMaxExprNesting) + " levels of parentheses");
      }
      take();
      ++depth_;
      const int inner = parse_or();
      --depth_;
      if (peek().kind != Tok::rparen) fail_at(peek(), "')'");
      take();
      // Keep the parentheses in the text for explanations.
      ExprNode& n = tree_.nodes[static_cast<size_t>(inner)];
      set_span(n, from, here());
      n.loc = loc_of(from);
      return inner;
    }
    if (t.kind == Tok::ident) {
      const Token name = take();
      if (name.text == "true" || name.text == "false") {
        ExprNode n;
        n.kind = ExprKind::boolean;
        n.value = name.text == "true" ? 1 : 0;
        return add(std::move(n), from, here());
      }
      if (name.text == "and" || name.text == "or" || name.text == "not") {
        fail_at(name, "a value before '" + name.text + "'");
      }
      ExprNode n;
      n.kind = ExprKind::call;
      if (peek().kind == Tok::dot) {  // entity.name reads as name(entity)
        take();
        if (peek().kind != Tok::ident) fail_at(peek(), "a name after '.'");
        n.op = take().text;
        n.args = {name.text};
        return add(std::move(n), from, here());
      }
      n.op = name.text;
      if (peek().kind == Tok::lparen) {
        take();
        if (peek().kind != Tok::rparen) {
          while (true) {
            if (peek().kind != Tok::ident) fail_at(peek(), "agent, object or actee");
            n.args.push_back(take().text);
            if (peek().kind == Tok::comma) {
              take();
              continue;
            }
            break;
          }
        }
        if (peek().kind != Tok::rparen) fail_at(peek(), "',' or ')'");
        take();
      }
      return add(std::move(n), from, here());
    }
    fail_at(t, "a value (a number with its unit, a signal, or '(')");
  }

  const std::string& text_;
  SourceLoc loc_;
  int offset_;
  std::vector<Token> tokens_;
  size_t next_ = 0;
  int depth_ = 0;  // parentheses open around the current token
  ExprTree tree_;
};

}  // namespace

ExprTree parse_expression(const std::string& text, const SourceLoc& loc, bool quoted) {
  return Parser(text, loc, quoted).parse();
}

}  // namespace afford
