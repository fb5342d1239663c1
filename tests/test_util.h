// Small helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <string>

namespace afford::test {

// The message of the E a call throws, or "" when it throws none (another
// exception than E passes through and fails the test).
template <class E = std::exception, class F>
std::string thrown(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

// `text` with its one occurrence of `from` replaced by `to`. A `from` that
// is missing or not unique fails the test: the mutation would be unclear.
inline std::string replace_once(const std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    ADD_FAILURE() << "'" << from << "' is not in the document exactly once";
    return text;
  }
  return text.substr(0, at) + to + text.substr(at + from.size());
}

}  // namespace afford::test
