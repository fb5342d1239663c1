// JSON Schemas (draft-07) for editors, written from the key tables of
// schema.h: with the YAML language server an editor completes and checks
// the files (docs/file-kinds.md).
#pragma once

#include <string>

#include "schema.h"

namespace afford {

// The schema of a file of kind `kind` ("object", ...) whose top-level
// mapping is `root`, as indented JSON text ending in a newline.
std::string json_schema(const std::string& kind, const MapSchema& root);

}  // namespace afford
