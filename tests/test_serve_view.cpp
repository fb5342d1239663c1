// `afford view`'s document (serve/recording_view.h): a recording re-run
// into the scene, the states and the events with their explanations; which
// recording a path stands for; the viewer serving it over HTTP.
#include <civetweb.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "recording.h"
#include "recording_view.h"
#include "run.h"
#include "scripted_agent.h"
#include "session.h"
#include "viewer.h"
#include "test_util.h"

namespace afford::serve {
namespace {
using test::kSource;

using ::testing::HasSubstr;
using Json = nlohmann::json;
namespace fs = std::filesystem;


// The paper-tongs script, recorded as `afford run --record` does.
RunResult record_paper_tongs(const std::string& file) {
  const CompiledSession session = load_session(kSource + "/sessions/paper-tongs.yaml");
  RunResult r;
  {
    Recorder recorder(file, session, "script sessions/paper-tongs.yaml");
    Observer* const observers[] = {&recorder};
    ScriptedAgent agent(session.script);
    r = run_session(session.model, *session.rules, agent, observers);
    EXPECT_TRUE(recorder.error().empty()) << recorder.error();
  }
  return r;
}

std::string throws(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ServeView, ARecordingBecomesTheScenesStatesAndEvents) {
  const fs::path dir = test::fresh_dir("serve-view", "doc");
  const std::string file = (dir / "run.afrec").string();
  const RunResult run = record_paper_tongs(file);
  ASSERT_EQ(run.inferences.size(), 4u);

  const RecordingView view = recording_view(file);
  EXPECT_TRUE(view.identical);
  EXPECT_EQ(view.frames, run.frames);
  EXPECT_EQ(view.inferences, 4);
  const Json doc = Json::parse(view.json);
  EXPECT_EQ(doc["type"], "recording");
  EXPECT_EQ(doc["session"], "paper-tongs");
  EXPECT_EQ(doc["identical"], true);
  EXPECT_EQ(doc["scene"]["type"], "scene");
  EXPECT_EQ(doc["scene"]["actee_name"], "egg");
  EXPECT_GT(doc["scene"]["guides"]["guides"].size(), 0u);  // the guides of afford guide, drawn in the view too
  // About 60 states a second of session time, in time order, plus the frames with events.
  const Json& states = doc["states"];
  EXPECT_GE(states.size(), static_cast<size_t>(run.end_time * 58));
  for (size_t i = 1; i < states.size(); ++i) ASSERT_GE(states[i]["t"].get<double>(), states[i - 1]["t"].get<double>());
  EXPECT_EQ(states.back()["condition"], "broken");
  // The inferences, with the explanation `afford run` prints.
  std::vector<Json> inferred;
  for (const Json& e : doc["events"]) {
    if (e["kind"] == "inferred") inferred.push_back(e);
  }
  ASSERT_EQ(inferred.size(), run.inferences.size());
  for (size_t i = 0; i < inferred.size(); ++i) {
    const Inference& inf = run.inferences[i];
    EXPECT_EQ(inferred[i]["function"], inf.function);
    EXPECT_EQ(inferred[i]["t"].get<double>(), inf.t);
    ASSERT_EQ(inferred[i]["explanation"].size(), inf.nodes.size());
    for (size_t n = 0; n < inf.nodes.size(); ++n) EXPECT_EQ(inferred[i]["explanation"][n]["text"], inf.nodes[n].text);
  }
  fs::remove_all(dir);
}

TEST(ServeView, FindsTheRecordingAPathStandsFor) {
  const fs::path dir = test::fresh_dir("serve-view", "find");
  const fs::path one = dir / "run";
  fs::create_directories(one);
  std::ofstream(one / "run.afrec") << "x";
  EXPECT_EQ(find_recording(one.string()), (one / "run.afrec").string());
  EXPECT_EQ(find_recording((one / "run.afrec").string()), (one / "run.afrec").string());
  // A trial's outputs of serve: beside it.
  fs::create_directories(dir / "p01-trial-001");
  std::ofstream(dir / "p01-trial-001.afrec") << "x";
  EXPECT_EQ(find_recording((dir / "p01-trial-001").string()), (dir / "p01-trial-001.afrec").string());
  EXPECT_EQ(find_recording((dir / "p01-trial-001/").string()), (dir / "p01-trial-001.afrec").string());
  // Nothing, or too much.
  fs::create_directories(dir / "empty");
  EXPECT_THAT(throws([&] { find_recording((dir / "empty").string()); }), HasSubstr("no recording (.afrec) in it"));
  EXPECT_THAT(throws([&] { find_recording((dir / "empty").string()); }), HasSubstr("--record"));
  std::ofstream(one / "second.afrec") << "x";
  EXPECT_THAT(throws([&] { find_recording(one.string()); }), HasSubstr("holds 2 recordings"));
  EXPECT_THAT(throws([&] { find_recording((dir / "nowhere").string()); }), HasSubstr("no such recording or folder"));
  // A file that is not a recording is an error naming it.
  EXPECT_THAT(throws([&] { recording_view((one / "run.afrec").string()); }), HasSubstr("run.afrec"));
  fs::remove_all(dir);
}

// civetweb's client: GET path, the body.
std::string http_get(int port, const std::string& path, int* status) {
  char error[256] = "";
  mg_connection* c = mg_download("127.0.0.1", port, 0, error, sizeof error, "GET %s HTTP/1.0\r\n\r\n", path.c_str());
  if (c == nullptr) {
    ADD_FAILURE() << "cannot GET " << path << ": " << error;
    return "";
  }
  *status = mg_get_response_info(c)->status_code;
  std::string body;
  char buf[65536];
  for (int n; (n = mg_read(c, buf, sizeof buf)) > 0;) body.append(buf, static_cast<size_t>(n));
  mg_close_connection(c);
  return body;
}

TEST(ServeView, ServesThePageAndTheRecording) {
  const fs::path dir = test::fresh_dir("serve-view", "http");
  const std::string file = (dir / "run.afrec").string();
  record_paper_tongs(file);
  ViewOptions o;
  o.recording = file;
  o.port = 0;
  o.web_dir = kSource + "/web";
  Viewer viewer(o);
  viewer.start();
  ASSERT_GT(viewer.port(), 0);
  EXPECT_THAT(viewer.url(), HasSubstr("/?view"));
  int status = 0;
  const std::string doc = http_get(viewer.port(), "/recording.json", &status);
  EXPECT_EQ(status, 200);
  EXPECT_EQ(doc, viewer.document());
  EXPECT_THAT(http_get(viewer.port(), "/", &status), HasSubstr("app.js"));
  EXPECT_EQ(status, 200);
  EXPECT_THAT(http_get(viewer.port(), "/player.js", &status), HasSubstr("export async function play"));
  viewer.stop();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace afford::serve
