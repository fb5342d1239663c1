// afford export --urdf SESSION|OBJECT --out DIR: the tool as a robot
// description, DIR/NAME.urdf and DIR/meshes/PART.stl (modelling/urdf_export.h),
// for robot simulators and as test data for afford model.
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "data_files.h"
#include "files.h"
#include "load.h"
#include "output_file.h"
#include "session.h"
#include "urdf_export.h"
#include "yaml_reader.h"

namespace afford::cli {

namespace fs = std::filesystem;

int export_urdf(const std::string& file, const std::string& out_dir, bool force) {
  if (out_dir.empty()) throw std::invalid_argument("export --urdf: --out DIR, the folder to write the URDF and its meshes into");
  const Node root = load_yaml_file(file);
  std::vector<std::string> inputs{file};
  ObjectSpec object;
  const std::string kind = file_kind(root);
  if (kind == "session") {
    const CompiledSession session = load_session(file);  // the whole session checked, as export --mjcf does
    inputs = session.files;
    std::vector<std::string> read;
    Files files(root, "session", &read);
    MapReader m(root, "a session file", session_schema());
    object = read_object(files.document(root, "object", m.required("object")));
  } else if (kind == "object") {
    object = read_object(root);
  } else {
    fail(root.loc(), "an object file or a session file", "a file of kind '" + kind + "'");
  }
  const OutputScope scope({.writer = "export --urdf", .force = force, .inputs = inputs});  // never over an input
  std::error_code ec;
  fs::create_directories(fs::path(out_dir) / "meshes", ec);
  if (ec) throw std::runtime_error("cannot create " + (fs::path(out_dir) / "meshes").string() + ": " + ec.message());
  for (const modelling::ExportedFile& f : modelling::urdf_export(object)) {
    const std::string path = (fs::path(out_dir) / f.path).string();
    write_file_checked(path, f.text);  // WriteError names the file, exit 1
    std::cout << "wrote " << path << "\n";
  }
  // The files an earlier export --urdf wrote there and this one did not (another tool's meshes).
  clear_stale_outputs(out_dir);
  clear_stale_outputs((fs::path(out_dir) / "meshes").string());
  return 0;
}

}  // namespace afford::cli
