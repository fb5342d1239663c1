#include "errors.h"

namespace afford {

std::string SourceLoc::str() const {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

DataError::DataError(SourceLoc loc, const std::string& message)
    : std::runtime_error(loc.str() + ": " + message),
      loc_(std::move(loc)),
      message_(message) {}

void fail(const SourceLoc& loc, const std::string& expected,
          const std::string& found) {
  throw DataError(loc, "expected " + expected + ", found " + found);
}

}  // namespace afford
