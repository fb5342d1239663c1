// The files a data file names (a session's object, a measurement's traces):
// paths relative to the naming file, checked to be readable files, reported
// at the key that names them; and the `actee: {file, at | position}` entry
// that sessions and measurements share.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "model.h"
#include "spec.h"
#include "yaml_reader.h"

namespace afford {

class Files {
 public:
  // Paths resolve against the folder of root's file, a `kind` file
  // ("session"); every file read is appended to *read.
  Files(const Node& root, std::string kind, std::vector<std::string>* read);

  // The path a `key: path` names, resolved against the naming file's folder,
  // checked to be a readable file (reported at the key) and recorded.
  std::string resolve(const Node& map, std::string_view key, const Node& value);

  // A path, or the file's content in place (a mapping).
  Node document(const Node& map, std::string_view key, const Node& value);

 private:
  std::filesystem::path base_;
  std::string kind_;
  std::vector<std::string>* read_;
};

// `actee: {file, at}` (resting on the fixed jaw at a distance) or
// `{file, position, rotation?}` (in the world).
// The keys of that mapping (schema.h).
const MapSchema& actee_entry_schema();
void read_actee_entry(const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options);
// An entry of a session's `actees:`: the same, and an optional `name` by
// which the script takes it (default: the actee file's own name).
const MapSchema& named_actee_entry_schema();
void read_named_actee_entry(const Node& node, Files& files, ActeeSpec* actee, ModelOptions* options,
                            std::string* name);

}  // namespace afford
