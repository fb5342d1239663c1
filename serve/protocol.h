// The messages between `afford serve` and its page, apart from the socket
// code so that they can be tested without one. Every message is one
// WebSocket text frame holding one JSON object with a "type".
//
// From the page (the driver's are applied at the next frame; a watcher's
// are answered with an error):
//
//   {"type":"thumb","squeeze":0.012}     where the thumb should be: m past
//                                        the rest angle along the rotation
//                                        direction (eq. 1), 0 to max_squeeze
//   {"type":"grasp"}                     close the fingers on the arms
//   {"type":"release"}                   open them (the squeeze goes to 0)
//   {"type":"move","position":[x,y,z]}   where the hand should be, m, world,
//                                        within the scene's hand box
//   {"type":"actee","name":"egg"}        take an actee from the shelf: a new trial
//   {"type":"reset"}                     a new trial with the same actee
//
// Any of them may carry "seq": a non-negative integer that must grow from
// one message of a page to the next; a message whose seq is not above the
// last one accepted from that page is stale and dropped. Unknown keys,
// missing or mistyped fields, numbers out of range, bad JSON, a message
// over kMaxMessageBytes: each is an error saying what was expected and
// what was found, and the message is dropped.
//
// To the page (formatted here; the server decides when):
//
//   {"type":"hello","role":"driver"|"watcher","protocol":1}
//   {"type":"role","role":...}           the driver left, this page drives now
//   {"type":"scene",...}                 once on connect and at each trial (scene_message.h)
//   {"type":"state",...}                 about 60 times a second of session time
//   {"type":"event",...}                 each event of the rules, as it happens
//   {"type":"error","message":"..."}     why a message of this page was dropped
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "rules.h"
#include "state.h"

namespace afford::serve {

inline constexpr int kProtocolVersion = 1;
inline constexpr size_t kMaxMessageBytes = 4096;  // a page's message; larger ones are dropped

enum class CommandKind : std::uint8_t { thumb, grasp, release, move, actee, reset };
const char* command_name(CommandKind kind);

// A checked message from the page. Plain data: queued between threads
// without allocating.
struct Command {
  CommandKind kind = CommandKind::grasp;
  std::int64_t seq = -1;                  // -1: the message gave none
  double squeeze = 0;                     // m (thumb)
  std::array<double, 3> position{};       // m, world (move)
  int actee = -1;                         // index into the shelf (actee)
};

// The commands applied to a trial's hand are kept in its recording, as
// records of type 'P' before the frame that first uses them (readers that
// do not know the type skip them; devices/recording.h): a payload of
// kCommandRecordBytes, little-endian:
//   u8 kind (CommandKind), i64 seq (-1 none), f64 t (s, the frame's time),
//   f64 squeeze (m), f64[3] position (m), i32 actee (shelf index, -1 none)
inline constexpr std::uint8_t kRecordPageCommand = 'P';
inline constexpr size_t kCommandRecordBytes = 1 + 8 + 8 + 8 + 24 + 4;
void encode_command(const Command& c, double t, unsigned char* out);
Command decode_command(const unsigned char* in, double* t);

// What a message may ask for.
struct CommandLimits {
  double max_squeeze = 0.05;                // m
  std::array<double, 3> hand_min{-1, -1, -1};  // m, world: the box the hand may be moved in
  std::array<double, 3> hand_max{1, 1, 1};
};

// Parses and checks one message. False with *error set ("'squeeze' must be
// a number from 0 m to 0.05 m, found \"x\"") when it is not a valid command;
// `shelf` names the actees a page may take. Never throws.
bool parse_command(std::string_view text, const CommandLimits& limits, std::span<const std::string> shelf,
                   Command* out, std::string* error);

// The "seq" rule of one page: true (and remembered) when the command may
// be applied, false when it is stale.
class SeqCheck {
 public:
  bool accept(const Command& c);
  std::int64_t last() const { return last_; }

 private:
  std::int64_t last_ = -1;
};

// The state of one frame, as the page draws it. Filled from the engine's
// State without allocating (state_message below).
struct StateMessage {
  int trial = 0;
  double t = 0;                  // s
  std::int64_t frame = 0;
  double angle = 0;              // rad, the lever's opening angle
  double squeeze = 0;            // m, the page's hand: the thumb's advance now
  double squeeze_target = 0;     // m, where the page asked it to go
  bool gripping = false;         // the page's hand closes its fingers on the arms
  bool grasped = false;          // the engine's grasp (thumb and another finger on the arms)
  double reaction = 0;           // N, eq. 5's F_agr: what the thumb feels (the effort force)
  double max_force = 0;          // N, the hand's largest effort force now
  double actee_force = 0;        // N, F_acr
  double actee_load = 0;         // N, its part along A_d, against the limit
  double actee_limit = 0;        // N, A_pv (0: no actee)
  double peak_actee_load = 0;    // N
  const char* condition = "intact";  // condition_name()
  bool held = false;
  std::array<double, 16> object{};      // world from the object frame, column-major 4x4
  std::array<double, 16> moving_arm{};  // world from the moving arm's frame
  std::array<double, 16> actee{};       // world from the actee's frame
  std::array<double, 16> hand{};        // world from the hand frame
  std::array<std::array<double, 3>, 5> fingertip{};  // m, world, thumb first
  std::int64_t deadline_misses = 0;     // frames served more than one timestep late so far
  std::int64_t applied_seq = -1;        // the seq of the last command applied (-1 none): a page
                                        // times its input to the state that shows it
};

// Copies what the page shows out of a frame's state.
void fill_state_message(const State& state, const Model& model, StateMessage* out);

// Writes m as JSON into buf (no allocation); returns the length, or 0 when
// it does not fit. Non-finite numbers are written as null.
size_t format_state(const StateMessage& m, char* buf, size_t size);
inline constexpr size_t kStateMessageBytes = 4096;  // always enough for format_state

// The small messages to the page.
std::string hello_message(bool driver);
std::string role_message(bool driver);
std::string error_message(std::string_view message);

// An event of the rules: {"type":"event","kind":"inferred","t":1.234,
// "function":"pinch","node":1,"text":"..."}, and for an inference its
// explanation, node by node, as `afford run` prints it:
// "explanation":[{"t":1.1,"text":"...","detail":"..."}]. `inference` is
// the inference for an inferred event (nullptr otherwise).
std::string event_message(const RuleSet& rules, const Event& e, const Inference* inference);
// The same for an event of the frame whose rule state is rs: an inference
// is looked up in rs for its explanation.
std::string frame_event_message(const RuleSet& rules, const RuleState& rs, const Event& e);

}  // namespace afford::serve
