// afford.load / afford.compile -> Model; Model.run() -> the inferred
// functions with their explanations (as `afford run --json`) and the trace
// (the columns of trace.csv, engine/session/trace.h) as NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "data_dir.h"
#include "scripted_agent.h"
#include "session.h"
#include "yaml_reader.h"

namespace afford::python {
namespace {

// The trace of a run, column by column as trace.csv has them, each filled
// by moving values into vectors sized once (before the first frame).
class TraceColumns : public Observer {
 public:
  explicit TraceColumns(std::int64_t frames) {
    const auto n = static_cast<size_t>(std::max<std::int64_t>(frames, 0));
    for (auto* v : {&t, &angle, &effort_force, &actee_force, &effort_pos, &actee_load}) v->reserve(n);
    for (auto* v : {&broken, &grasped, &held}) v->reserve(n);
    contacts.reserve(n);
  }
  void on_frame(const Model& m, const State& s, const RuleSet&, const RuleState&) override {
    // As TraceWriter::on_frame computes them (engine/session/trace.cpp).
    t.push_back(s.t);
    angle.push_back(s.theta);
    effort_force.push_back(s.effort_force);
    actee_force.push_back(s.actee_force);
    effort_pos.push_back(s.grasped ? std::abs(s.effort_distance) * (m.theta_rest - s.theta_command) : 0.0);
    broken.push_back(static_cast<std::uint8_t>(s.condition == ActeeCondition::broken));
    grasped.push_back(static_cast<std::uint8_t>(s.grasped));
    held.push_back(static_cast<std::uint8_t>(s.held));
    contacts.push_back(s.object_actee.count);
    actee_load.push_back(s.actee_load);
  }

  py::dict take() {
    py::dict d;
    d["t"] = as_array(std::move(t));
    d["angle"] = as_array(std::move(angle));
    d["effort_force"] = as_array(std::move(effort_force));
    d["actee_force"] = as_array(std::move(actee_force));
    d["effort_pos"] = as_array(std::move(effort_pos));
    d["broken"] = as_bool_array(std::move(broken));
    d["grasped"] = as_bool_array(std::move(grasped));
    d["held"] = as_bool_array(std::move(held));
    d["contacts_object_actee"] = as_array(std::move(contacts));
    d["actee_load"] = as_array(std::move(actee_load));
    return d;
  }

 private:
  std::vector<double> t, angle, effort_force, actee_force, effort_pos, actee_load;
  std::vector<std::uint8_t> broken, grasped, held;
  std::vector<std::int32_t> contacts;
};

}  // namespace

py::list functions_of(const std::vector<Inference>& inferences) {
  py::list functions;
  for (const Inference& inf : inferences) {
    py::list explanation;
    for (size_t i = 0; i < inf.nodes.size(); ++i) {
      py::dict node;
      node["t"] = inf.nodes[i].t;
      node["text"] = inf.nodes[i].text;
      if (i < inf.node_details.size() && !inf.node_details[i].empty()) node["detail"] = inf.node_details[i];
      explanation.append(node);
    }
    py::dict f;
    f["name"] = inf.function;
    f["t"] = inf.t;
    f["explanation"] = explanation;
    functions.append(f);
  }
  return functions;
}

namespace {

py::dict run(const SessionPtr& s) {
  RunResult result;
  const std::int64_t frames = static_cast<std::int64_t>(std::floor(s->script.duration() / s->model.timestep + 1e-9));
  TraceColumns trace(frames);
  {
    py::gil_scoped_release unlocked;  // the run touches no Python object
    ScriptedAgent agent(s->script);
    Observer* observers[] = {&trace};
    result = run_session(*s, *s->rules, agent, observers);
  }
  py::dict out;
  out["session"] = s->name;
  out["functions"] = functions_of(result.inferences);
  out["frames"] = result.frames;
  out["trace"] = trace.take();
  return out;
}

py::list warnings_of(const CompiledSession& s) {
  py::list out;
  for (const Warning& w : s.warnings) out.append(w.str());
  return out;
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<CompiledSession, SessionPtr>(m, "Model")
      .def_property_readonly("name", [](const CompiledSession& s) { return s.name; })
      .def_property_readonly("description", [](const CompiledSession& s) { return s.description; })
      .def_property_readonly("file", [](const CompiledSession& s) { return s.file; })
      .def_property_readonly("files", [](const CompiledSession& s) { return s.files; })
      .def_property_readonly("timestep", [](const CompiledSession& s) { return s.model.timestep; })
      .def_property_readonly("duration", [](const CompiledSession& s) { return s.script.duration(); })
      .def_property_readonly("functions", [](const CompiledSession& s) {
        std::vector<std::string> names;
        for (int f = 0; f < function_count(*s.rules); ++f) names.push_back(function_name(*s.rules, f));
        return names;
      })
      .def_property_readonly("warnings", &warnings_of)
      .def("run", &run)
      .def("__repr__", [](const CompiledSession& s) { return "<afford.Model " + s.name + ">"; });

  m.def("data_dir", [] { return data_dir(); });  // std::runtime_error listing where it looked
  m.def("load", [](const std::string& path) {
    py::gil_scoped_release unlocked;
    return std::make_shared<CompiledSession>(load_session(path));
  });
  // The session document afford.compile() writes (as YAML's JSON subset).
  m.def("compile_text", [](const std::string& text, const std::string& name) {
    py::gil_scoped_release unlocked;
    return std::make_shared<CompiledSession>(read_session(load_yaml_string(text, name)));
  });
}

}  // namespace afford::python
