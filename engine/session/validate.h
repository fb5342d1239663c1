// Validating any user file by its kind (the first key names it).
#pragma once

#include <string>
#include <vector>

namespace afford {

class Node;
struct Warning;

// The kinds of file afford reads, by the first key of the file.
std::vector<std::string> file_kinds();

// A kind defined outside the engine (device descriptions, in devices/),
// added by the program that links it. The check returns "<kind> <name>" or
// throws DataError.
using FileKindCheck = std::string (*)(const Node& root);
void add_file_kind(const std::string& name, FileKindCheck check);

// Loads, validates and compiles what one file defines, without running it.
// Returns "<kind> <name>"; throws DataError on the first mistake. A session
// that loads but that the hand can never work adds its warnings
// (setup_warnings.h) to `warnings`, if given.
std::string validate_file(const std::string& path, std::vector<Warning>* warnings = nullptr);
// The same from a parsed document (the fuzzers): relative paths resolve
// against the folder of the document's name.
std::string validate_node(const Node& root, std::vector<Warning>* warnings = nullptr);

}  // namespace afford
