// Validating any user file by its kind (the first key names it).
#pragma once

#include <string>
#include <vector>

namespace afford {

class Node;

// The kinds of file afford reads, by the first key of the file.
std::vector<std::string> file_kinds();

// A kind defined outside the engine (device descriptions, in devices/),
// added by the program that links it. The check returns "<kind> <name>" or
// throws DataError.
using FileKindCheck = std::string (*)(const Node& root);
void add_file_kind(const std::string& name, FileKindCheck check);

// Loads, validates and compiles what one file defines, without running it.
// Returns "<kind> <name>"; throws DataError on the first mistake.
std::string validate_file(const std::string& path);
// The same from a parsed document (the fuzzers): relative paths resolve
// against the folder of the document's name.
std::string validate_node(const Node& root);

}  // namespace afford
