// Fuzzes afford model's two-part path (modelling/): the bytes are a URDF,
// written to a file (urdfdom reads files) in a folder of this process, read
// into a tool with its meshes (read_urdf_tool), its lever found from the
// shape (lever_geometry) and the tool modelled and written as an object
// file (model_tool, object_yaml). A DataError is the expected answer to
// bad input, and so is the std::invalid_argument of an option the shape
// makes impossible (a spring at the pivot); anything else escaping, a
// crash, a sanitizer report or a hang is a bug.
//
// The meshes a URDF names are read relative to it: the folder holds a link
// to each hand-made tool of tests/data (PartNet-Mobility's layout), and the
// seeds, written here at start, are those tools' URDFs with their meshes
// named through those links.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "errors.h"
#include "tool_model.h"
#include "urdf_tool.h"

namespace {

namespace fs = std::filesystem;

// The tools whose URDFs seed the fuzzer: their folder under tests/data.
constexpr const char* kTools[] = {"partnet/scissors", "partnet/stapler", "partnet/garlic-press", "urdf/two-arms"};

fs::path work_folder() {
  static const fs::path folder = fs::temp_directory_path() / ("afford_fuzz_urdf_" + std::to_string(::getpid()));
  return folder;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

void remove_work_folder() {
  std::error_code ignored;
  fs::remove_all(work_folder(), ignored);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const fs::path data = fs::path(AFFORD_SOURCE_DIR) / "tests" / "data";
  fs::create_directories(work_folder());
  std::atexit(remove_work_folder);
  fs::create_directories(AFFORD_FUZZ_SEEDS);
  for (const char* tool : kTools) {
    const std::string name = fs::path(tool).filename().string();
    fs::create_directory_symlink(data / tool, work_folder() / name);
    std::ifstream in(data / tool / "mobility.urdf", std::ios::binary);
    const std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(fs::path(AFFORD_FUZZ_SEEDS) / (name + ".urdf"), std::ios::binary)
        << replace_all(urdf, "filename=\"textured_objs/", "filename=\"" + name + "/textured_objs/");
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = (work_folder() / "fuzz.urdf").string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  try {
    const afford::modelling::UrdfTool tool = afford::modelling::read_urdf_tool(path);
    afford::modelling::ToolModelOptions options;
    options.name = "fuzz";
    options.density = 1000;
    options.spring = afford::modelling::SpringGiven{0.1, 1.0, std::nullopt};
    (void)afford::modelling::object_yaml(afford::modelling::model_tool(tool, options));
  } catch (const afford::DataError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
