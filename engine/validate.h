// Validating any user file by its kind (the first key names it).
#pragma once

#include <string>
#include <vector>

namespace afford {

// The kinds of file afford reads, by the first key of the file.
std::vector<std::string> file_kinds();

// Loads, validates and compiles what one file defines, without running it.
// Returns "<kind> <name>"; throws DataError on the first mistake.
std::string validate_file(const std::string& path);

}  // namespace afford
