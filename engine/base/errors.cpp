#include "errors.h"

namespace afford {

std::string SourceLoc::str() const {
  if (line <= 0) return file;  // the file as a whole: no line to point at
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

DataError::DataError(SourceLoc loc, const std::string& message)
    : std::runtime_error(loc.str() + ": " + message),
      loc_(std::move(loc)),
      message_(message) {}

std::string shorten(const std::string& value) {
  if (value.size() <= kMaxQuoted) return "'" + value + "'";
  size_t cut = kMaxQuoted;  // not inside a UTF-8 sequence
  while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;
  return "'" + value.substr(0, cut) + "\u2026' (" + std::to_string(value.size()) + " characters)";
}

void fail(const SourceLoc& loc, const std::string& expected,
          const std::string& found) {
  throw DataError(loc, "expected " + expected + ", found " + found);
}

}  // namespace afford
