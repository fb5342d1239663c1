// Small helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace afford::test {

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
