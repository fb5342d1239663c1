// afford_consumer OBJECT SESSION: loads a shipped object and a shipped
// session (paths inside the data folder, found as afford finds them:
// $AFFORD_DATA_DIR or the installed share/afford) through the installed
// headers, prints the object's lever and its best mechanical advantage,
// then runs the session and prints every function inferred and the root
// element of its MuJoCo scene.
#include <afford/base/data_dir.h>
#include <afford/base/errors.h>
#include <afford/load/lever.h>
#include <afford/load/load.h>
#include <afford/model/model.h>
#include <afford/session/run.h>
#include <afford/session/session.h>
#include <afford/devices/scripted_agent.h>
#include <afford/mjcf/mjcf_scene.h>

#include <cstdio>
#include <string>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: afford_consumer OBJECT SESSION (paths in the shipped data)\n");
    return 2;
  }
  try {
    const afford::ObjectSpec object = afford::load_object(afford::shipped_path(argv[1]));
    const afford::Model m = afford::compile(object, nullptr, nullptr, afford::ModelOptions{});
    std::printf("%s: %s, mechanical advantage %.2f (effort at %.3f m, load at %.3f m)\n", object.name.c_str(),
                afford::pattern_name(object.lever.pattern),
                afford::mechanical_advantage(m.emphasis_to, m.application_from), m.emphasis_to, m.application_from);

    const afford::CompiledSession session = afford::load_session(afford::shipped_path(argv[2]));
    afford::ScriptedAgent agent(session.script);
    const afford::RunResult r = afford::run_session(session.model, *session.rules, agent);
    for (const afford::Inference& i : r.inferences) std::printf("%s at %.3f s\n", i.function.c_str(), i.t);

    // The session as a MuJoCo scene (afford::mjcf), as `afford export --mjcf` writes it.
    const std::string scene = afford::export_mjcf(session);
    const std::size_t root = scene.find("<mujoco ");
    std::printf("mjcf: %s\n", root == std::string::npos ? "no <mujoco> element"
                                                          : scene.substr(root, scene.find('>', root) + 1 - root).c_str());
    return 0;
  } catch (const afford::DataError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "afford_consumer: %s\n", e.what());
  }
  return 1;
}
