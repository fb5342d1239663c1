// Stepping a session from Python, frame by frame: model.state() gives a
// State; state.step(thumb) runs one frame (engine step, then the rules)
// with the thumb's fingertip at the given target and the rest of the hand
// (its pose, the other fingers, the joints) as the session's script has it
// at that frame's time, and returns the frame's angle, forces and events.
// The same samples give the same frames, bit for bit. A frame allocates
// nothing on the C++ side; on the Python side one Frame object.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"
#include "scripted_agent.h"
#include "usb_live.h"

namespace afford::python {
namespace {

struct FrameEvent {
  std::string kind;      // node_reached, node_lost or inferred
  std::string function;  // the function model's name
  int node = 0;          // 0-based index of the node (inferred: the last node)
  std::string text;      // the node's `when` as written
  double t = 0;          // s
};

// What one frame did.
struct Frame {
  double t = 0;             // s, the frame's time
  double angle = 0;         // rad, the lever's opening angle theta
  double effort_force = 0;  // N, the hand's push at the thumb (F_ag) along the closing direction
  double actee_force = 0;   // N, between the jaws and the actee (F_acr)
  double actee_load = 0;    // N, its component along the actee's axis, compared with its limit
  std::array<double, kFingers> finger_forces{};  // N, the haptic force per finger, thumb first (devices/usb_live.h)
  bool grasped = false, held = false, broken = false;
  std::vector<FrameEvent> events;  // this frame's rule events, in order
};

const char* kind_name(EventKind k) {
  switch (k) {
    case EventKind::node_reached: return "node_reached";
    case EventKind::node_lost: return "node_lost";
    case EventKind::inferred: return "inferred";
  }
  return "?";
}

// A sample's thumb: a tuple, list or NumPy array of three numbers, m.
std::array<double, 3> read_thumb(py::handle sample) {
  std::array<double, 3> p{};
  if (PyTuple_Check(sample.ptr()) && PyTuple_GET_SIZE(sample.ptr()) == 3) {  // the fast path
    for (Py_ssize_t i = 0; i < 3; ++i) {
      p[static_cast<size_t>(i)] = PyFloat_AsDouble(PyTuple_GET_ITEM(sample.ptr(), i));
    }
    if (PyErr_Occurred()) throw py::error_already_set();
  } else {
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(sample);
    if (!a || a.size() != 3) {
      throw py::type_error("a sample is the thumb's target (x, y, z) in m, world: three numbers, found " +
                           std::string(py::str(py::repr(sample))));
    }
    std::copy(a.data(), a.data() + 3, p.begin());
  }
  for (double v : p) {
    if (!std::isfinite(v)) throw py::value_error("the thumb's target must be finite, found " + std::string(py::str(sample)));
  }
  return p;
}

class Stepper {
 public:
  explicit Stepper(SessionPtr session)
      : session_(std::move(session)),
        model_(&session_->model),
        state_(make_state(session_->model)),
        rules_(make_rule_state(*session_->rules)),
        agent_(session_->script) {}

  // The next frame with the thumb at `thumb` (m, world).
  Frame step(const std::array<double, 3>& thumb) {
    const double t = next_time();
    script_sample(t, &sample_);
    sample_.fingertip[0] = Eigen::Vector3d(thumb[0], thumb[1], thumb[2]);
    return advance(t);
  }

  // The next frame as the session's script has it.
  Frame step_script() {
    const double t = next_time();
    script_sample(t, &sample_);
    return advance(t);
  }

  // The script's thumb target at t (s; default the next frame's), m, world.
  std::array<double, 3> script_thumb(double t) {
    Sample s;
    script_sample(t, &s);
    return {s.fingertip[0].x(), s.fingertip[0].y(), s.fingertip[0].z()};
  }

  double next_time() const { return static_cast<double>(state_->frame + 1) * session_->model.timestep; }
  const State& state() const { return *state_; }
  const CompiledSession& session() const { return *session_; }
  std::vector<Inference> inferred() const { return inferences(*session_->rules, *rules_); }

 private:
  // The script's sample at t; after its end, its last (the hand stays).
  void script_sample(double t, Sample* out) {
    agent_.sample_at(std::min(t, agent_.duration()), out);
    out->t = t;
  }

  Frame advance(double t) {
    // A keyframe's actee is on the tool from the first frame at its time (engine/session/run.cpp).
    const auto& changes = session_->actee_changes;
    for (; next_change_ < changes.size() && changes[next_change_].t <= t + 1e-9 * model_->timestep; ++next_change_) {
      model_ = &session_->actee_models[changes[next_change_].actee];
      change_actee(*model_, *state_);
    }
    sample_.t = t;
    afford::step(*model_, *state_, sample_);
    evaluate(*session_->rules, *rules_, *model_, *state_);
    Frame f;
    const State& s = *state_;
    f.t = s.t;
    f.angle = s.theta;
    f.effort_force = s.effort_force;
    f.actee_force = s.actee_force;
    f.actee_load = s.actee_load;
    f.finger_forces = haptic_forces(s);
    f.grasped = s.grasped;
    f.held = s.held;
    f.broken = s.condition == ActeeCondition::broken;
    for (const Event* e = events_begin(*rules_); e != events_end(*rules_); ++e) {
      const RuleSet& r = *session_->rules;
      f.events.push_back({kind_name(e->kind), function_name(r, e->function), e->node,
                          node_text(r, e->function, e->node), e->t});
    }
    return f;
  }

  SessionPtr session_;
  const Model* model_;  // the model of the actee on the tool now
  std::unique_ptr<State> state_;
  RuleStatePtr rules_;
  ScriptedAgent agent_;
  Sample sample_;
  size_t next_change_ = 0;
};

}  // namespace

void bind_stepping(py::module_& m) {
  py::class_<FrameEvent>(m, "FrameEvent")
      .def_readonly("kind", &FrameEvent::kind)
      .def_readonly("function", &FrameEvent::function)
      .def_readonly("node", &FrameEvent::node)
      .def_readonly("text", &FrameEvent::text)
      .def_readonly("t", &FrameEvent::t)
      .def("__repr__", [](const FrameEvent& e) {
        return "<afford.FrameEvent " + e.kind + " " + e.function + " node " + std::to_string(e.node) + ">";
      });
  py::class_<Frame>(m, "Frame")
      .def_readonly("t", &Frame::t)
      .def_readonly("angle", &Frame::angle)
      .def_readonly("effort_force", &Frame::effort_force)
      .def_readonly("actee_force", &Frame::actee_force)
      .def_readonly("actee_load", &Frame::actee_load)
      .def_readonly("finger_forces", &Frame::finger_forces)
      .def_readonly("grasped", &Frame::grasped)
      .def_readonly("held", &Frame::held)
      .def_readonly("broken", &Frame::broken)
      .def_readonly("events", &Frame::events)
      .def("__repr__", [](const Frame& f) {
        return "<afford.Frame t=" + std::to_string(f.t) + " s angle=" + std::to_string(f.angle) +
               " rad effort_force=" + std::to_string(f.effort_force) + " N>";
      });
  py::class_<Stepper>(m, "State")
      .def("step",
           [](Stepper& s, py::handle sample) { return sample.is_none() ? s.step_script() : s.step(read_thumb(sample)); },
           py::arg("sample") = py::none())
      .def("script_thumb",
           [](Stepper& s, std::optional<double> t) { return s.script_thumb(t ? *t : s.next_time()); },
           py::arg("t") = py::none())
      .def_property_readonly("t", [](const Stepper& s) { return s.state().t; })
      .def_property_readonly("frame", [](const Stepper& s) { return s.state().frame; })
      .def_property_readonly("next_t", &Stepper::next_time)
      .def_property_readonly("hash", [](const Stepper& s) { return state_hash(s.state()); })
      .def("functions", [](const Stepper& s) { return functions_of(s.inferred()); });
  m.def("make_state", [](const SessionPtr& s) { return Stepper(s); });
}

}  // namespace afford::python
