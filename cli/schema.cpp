// afford schema KIND [--out DIR] | afford schema --all --out DIR: the JSON
// Schema of each kind of YAML file, for editors (docs/file-kinds.md).
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "option_checks.h"
#include "device_description.h"
#include "did_you_mean.h"
#include "files.h"
#include "grasps.h"
#include "guides.h"
#include "json_schema.h"
#include "output_file.h"
#include "load.h"
#include "measurement.h"
#include "rule_tests.h"
#include "session.h"

namespace afford::cli {
namespace {

struct SchemaKind {
  const char* kind;  // the file is KIND.schema.json
  const MapSchema& (*root)();
};

// Every kind of YAML file afford reads, in the order of docs/file-kinds.md.
constexpr SchemaKind kKinds[] = {
    {"object", object_schema},        {"actee", actee_schema},       {"agent", agent_schema},
    {"functions", functions_schema},  {"grasps", grasps_schema},   {"guides", guides_schema},
    {"session", session_schema},      {"device", device_schema},   {"rule_test", rule_test_schema},
    {"measurement", measurement_schema},
};

void write_schema(const SchemaKind& k, const std::string& dir) {
  write_file_checked((std::filesystem::path(dir) / (std::string(k.kind) + ".schema.json")).string(),
                     json_schema(k.kind, k.root()));
}

struct SchemaOptions {
  std::string kind, out;
  bool all = false;
  bool force = false;  // replace an existing file afford did not write (output_file.h)
};

int schema(const SchemaOptions& o) {
  const std::string& which = o.kind;
  const std::string& out = o.out;
  if (which.empty() && !o.all) return usage_error("schema needs a KIND or --all");
  const OutputScope scope({.writer = "schema", .force = o.force, .inputs = {}});
  if (!out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (!std::filesystem::is_directory(out)) return usage_error("--out " + out + ": not a folder");
  }
  if (o.all) {
    if (out.empty()) return usage_error("schema --all needs --out DIR");
    for (const SchemaKind& k : kKinds) write_schema(k, out);
    return 0;
  }
  std::vector<std::string> names;
  for (const SchemaKind& k : kKinds) {
    names.emplace_back(k.kind);
    if (which != k.kind) continue;
    if (out.empty()) {
      std::cout << json_schema(k.kind, k.root());
    } else {
      write_schema(k, out);
    }
    return 0;
  }
  std::string kinds;
  for (const std::string& n : names) kinds += (kinds.empty() ? "" : ", ") + n;
  return usage_error("unknown kind '" + which + "'" + did_you_mean(which, names) + " (kinds: " + kinds + ")");
}

}  // namespace

void add_schema(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("schema", "the JSON Schema of a kind of YAML file, for editors");
  auto o = std::make_shared<SchemaOptions>();
  std::string kinds;
  for (const SchemaKind& k : kKinds) kinds += (kinds.empty() ? "" : ", ") + std::string(k.kind);
  CLI::Option* kind = cmd->add_option("KIND", o->kind, "the kind of file: " + kinds)->type_name("KIND");
  cmd->add_flag("--all", o->all, "every kind, one KIND.schema.json each (needs --out)")->excludes(kind);
  cmd->add_option("--out", o->out, "write KIND.schema.json into DIR instead of printing it")->type_name(kDir);
  cmd->add_flag("--force", o->force, "replace an existing file that afford did not write");
  cmd->callback([run, o] { *run = [o] { return schema(*o); }; });
}

}  // namespace afford::cli
