// Two kinds of error, split by who must fix them (as in BehaviorTree.CPP):
// a DataError is a mistake in a user's file and names file:line:col; a
// LogicError is a bug in afford itself.
#pragma once

#include <stdexcept>
#include <string>

namespace afford {

// Where a value came from: 1-based line and column, as editors count;
// line 0 for the file as a whole (missing, too large, not a regular file).
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const;  // "file:line:col", or "file" when line is 0
};

class DataError : public std::runtime_error {
 public:
  DataError(SourceLoc loc, const std::string& message);
  const SourceLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }

 private:
  SourceLoc loc_;
  std::string message_;
};

// "expected X, found Y" is the one shape of every data error message.
[[noreturn]] void fail(const SourceLoc& loc, const std::string& expected,
                       const std::string& found);

// A value quoted in an error: 'abc', or, past kMaxQuoted characters, its
// start and its length ('vvvv…' (1048576 characters)), so that one bad
// value does not flood the terminal.
inline constexpr size_t kMaxQuoted = 60;
std::string shorten(const std::string& value);

class LogicError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace afford
