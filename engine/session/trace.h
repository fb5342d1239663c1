// Observers that write a session to files (DESIGN.md "Traces").
//
// TraceWriter: the trace CSV, one format for simulation and measurement. A
// comment line with the units (`# units: t s, angle rad, ...`, which CSV
// readers skip as a comment), a header row, then one row per frame, SI units:
//   t                      s, the frame's time
//   angle                  rad, the lever's opening angle theta
//   effort_force           N, F_ag at the emphasis along the rotation direction
//   actee_force            N, F_acr between the jaws and the actee (0 without contact)
//   effort_pos             m, the thumb's advance along the rotation direction past
//                          the rest angle, |D_ag| * (theta_rest - theta_command)
//                          (the script's `squeeze`); 0 while not grasped
//   broken                 0/1, the actee has broken
//   grasped                0/1, the agent grasps the tool
//   held                   0/1, the jaws hold the actee
//   contacts_object_actee  count, contact points between the tool and the actee
//   actee_load             N, the jaws' force along the actee's A_d
// Readers keep and ignore columns they do not know.
//
// TimelineWriter: one JSON object per line for each rule event:
//   {"t":1.234,"event":"node_reached","function":"pinch","node":1,"text":"contacts(object, actee) >= 2"}
// event is node_reached, node_lost or inferred; node is the node's index
// (for inferred, the last node) and text its `when` as written.
//
// Both write into a FILE* they do not own and allocate nothing per frame;
// the trace's numbers are the same bytes as printf's "%.6f" (t) and "%.9g"
// (the rest), written without printf (number_format.h).
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "observer.h"

namespace afford {

class TraceWriter : public Observer {
 public:
  explicit TraceWriter(std::FILE* out) : out_(out) {}
  void on_start(const Model& model, const State& state, const RuleSet& rules) override;
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  void on_end(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  static const char* units();   // the comment line with the units, without the newline
  static const char* header();  // the header row, without the newline
  // One row, newline included, into buf; returns its length. buf holds
  // kMaxRow characters.
  static constexpr size_t kMaxRow = 512;
  size_t format_row(char* buf, size_t size, double t, double angle, double effort_force, double actee_force,
                    double effort_pos, int broken, int grasped, int held, int contacts, double actee_load);

 private:
  // The text of the last value written in each %.9g column: most values do
  // not change from one row to the next (two thirds in paper-tongs), and a
  // copy is cheaper than formatting them again.
  struct Written {
    double value = 0;
    bool valid = false;
    std::uint8_t size = 0;
    char text[24] = {};
  };
  char* put_general9(char* p, char* end, double v, Written& last);

  std::FILE* out_;
  Written angle_, effort_force_, actee_force_, effort_pos_, actee_load_;
};

class TimelineWriter : public Observer {
 public:
  explicit TimelineWriter(std::FILE* out) : out_(out) {}
  void on_start(const Model& model, const State& state, const RuleSet& rules) override;
  void on_frame(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;
  void on_end(const Model& model, const State& state, const RuleSet& rules, const RuleState& rs) override;

 private:
  std::FILE* out_;
  const Model* model_ = nullptr;           // the model of the last frame: another is another actee
  std::array<bool, kFingers> out_of_reach_{};  // per finger, beyond its reach at the last frame
  // Escaped JSON strings, built once in on_start: per function its name,
  // per function and node its text.
  std::vector<std::string> function_json_;
  std::vector<std::vector<std::string>> node_json_;
};

// s as a JSON string literal, quotes included.
std::string json_string(const std::string& s);

}  // namespace afford
