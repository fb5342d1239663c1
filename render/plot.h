// The timeline plot of a session: the lever angle, the effort force, the
// actee force and the actee's limit over time, the inferred functions as
// labelled lines, and per function a lane with its nodes reached and lost.
// Written as SVG (text) and as PNG (rasterised here, no OpenGL), from the
// same layout.
#pragma once

#include <string>
#include <vector>

#include "image.h"
#include "observer.h"

namespace afford::render {

struct TimelineSample {
  double t = 0;       // s
  double angle = 0;   // rad
  double effort = 0;  // N, effort force at the emphasis
  double actee = 0;   // N, force between the jaws and the actee
};

struct TimelineMark {
  double t = 0;  // s
  EventKind kind = EventKind::node_reached;
  int function = 0;
  int node = 0;
  std::string text;  // the node's `when` as written
};

struct Timeline {
  std::string title;                   // "paper-nutcracker"
  bool has_actee = false;
  double limit = 0;                    // N, the actee's limit
  std::string actee_name;
  std::vector<std::string> functions;  // every function of the rules, in order
  std::vector<TimelineSample> samples;
  std::vector<TimelineMark> marks;
  double end_time = 0;                 // s
};

// Records a Timeline while a session runs (every frame's sample and every
// rule event).
class TimelineRecorder : public Observer {
 public:
  explicit TimelineRecorder(std::string title) { timeline_.title = std::move(title); }
  void on_start(const Model& model, const State& state, const RuleSet& rules) override;
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  const Timeline& timeline() const { return timeline_; }

 private:
  Timeline timeline_;
};

std::string plot_svg(const Timeline& timeline, int width = 1100);
Image plot_png(const Timeline& timeline, int width = 1100);
// The plot's height for a timeline at a width (the lanes grow with the functions).
int plot_height(const Timeline& timeline);

// A colour per function (the plot's, the contact sheet's), by index.
Rgb function_colour(int function);

}  // namespace afford::render
