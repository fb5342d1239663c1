// Fuzzes one kind of YAML file (kFuzzFolder, written by CMake per fuzzer
// into a file of one line, so that this file is compiled once for all ten
// of them): the bytes are the file's content, read as `afford check` reads
// a file (parsed, validated, compiled). The document is named in the
// folder of its kind so that relative paths reach the shipped files. A
// DataError is the expected answer to bad input; anything else escaping,
// a crash, a sanitizer report or a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "check_kinds.h"
#include "errors.h"
#include "validate.h"
#include "yaml_reader.h"

namespace afford::fuzz {
extern const char* const kFuzzFolder;  // the shipped folder of this fuzzer's kind
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  afford::fuzz::add_check_kinds();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string name = std::string(afford::fuzz::kFuzzFolder) + "/fuzz.yaml";
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    afford::validate_node(afford::load_yaml_string(text, name));
  } catch (const afford::DataError&) {
  }
  return 0;
}
