// afford export --mjcf SESSION [--out FILE]: the session's tool, actee and
// hand as a MuJoCo scene (mjcf/mjcf_scene.h), written to FILE (default
// out/<session>.xml). The file's header comment says what a harness must
// apply that MJCF cannot say. afford export --urdf: export_urdf.cpp.
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "files.h"
#include "mjcf_scene.h"
#include "option_checks.h"
#include "output_file.h"
#include "session.h"

namespace afford::cli {
namespace {

namespace fs = std::filesystem;

}  // namespace

int export_urdf(const std::string& file, const std::string& out_dir, bool force);  // export_urdf.cpp

namespace {

struct ExportOptions {
  std::string file, out;
  bool mjcf = false;
  bool urdf = false;  // the tool as URDF + STL meshes (export_urdf.cpp)
  bool force = false;  // replace an existing file afford did not write (engine/base/output_file.h)
};

int export_command(const ExportOptions& o) {
  if (o.urdf) {
    if (o.out.empty()) return usage_error("export: --urdf writes into a folder: give --out DIR");
    return export_urdf(o.file, o.out, o.force);
  }
  if (!o.mjcf) return usage_error("export: give the format, --mjcf or --urdf");
  const CompiledSession session = load_session(o.file);  // DataError: file:line:col, exit 1
  const OutputScope scope({.writer = "export", .force = o.force, .inputs = session.files});  // never over an input
  // A scene holds the bodies of one moment: which actee would it hold?
  if (!session.actee_models.empty()) {
    throw std::runtime_error(o.file + ": export --mjcf takes a session with one actee; this one lists " +
                             std::to_string(session.actee_models.size()) +
                             " ('actees:'): export a session with each alone");
  }
  const fs::path out = o.out.empty() ? fs::path("out") / (session.name + ".xml") : fs::path(o.out);
  if (out.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(out.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create " + out.parent_path().string() + ": " + ec.message());
  }
  write_file_checked(out.string(), mjcf_scene(session));  // WriteError names the file, exit 1
  std::cout << "wrote " << out.string() << "\n";
  return 0;
}

}  // namespace

void add_export(CLI::App& app, Run* run) {
  CLI::App* cmd = app.add_subcommand("export", "a session as a MuJoCo scene (MJCF XML) for MuJoCo 2.2.2, or a tool as URDF + STL");
  auto o = std::make_shared<ExportOptions>();
  auto* mjcf = cmd->add_flag("--mjcf", o->mjcf, "write MJCF (a session: its tool, actee and hand as a scene)");
  cmd->add_flag("--urdf", o->urdf, "write the tool of a session or an object file as URDF + STL meshes into --out DIR")
      ->excludes(mjcf);
  cmd->add_option("SESSION", o->file, "a session file (sessions/*.yaml); with --urdf also an object file")->required()->type_name(kFile);
  cmd->add_option("--out", o->out, "the scene file to write (default out/<session>.xml); with --urdf the folder")->type_name(kFile);
  cmd->add_flag("--force", o->force, "replace an existing file that afford did not write");
  cmd->callback([run, o] { *run = [o] { return export_command(*o); }; });
}

}  // namespace afford::cli
