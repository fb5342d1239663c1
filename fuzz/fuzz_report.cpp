// Fuzzes the device report decoder and the force encoder
// (devices/report_decoder.h) with the shipped device descriptions and the
// shipped hand: the first byte picks the device, the rest is one IN
// report; its first 40 bytes are also five forces (N) for an OUT report.
// Any bytes must decode or be skipped with a status; nothing may throw.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "device_description.h"
#include "load.h"
#include "model.h"
#include "report_decoder.h"

namespace {

struct Rig {
  afford::DeviceDescription device;
  afford::Model model;
  std::unique_ptr<afford::ReportDecoder> decoder;
  std::vector<std::uint8_t> out;
};

std::vector<std::unique_ptr<Rig>>& rigs() {
  static std::vector<std::unique_ptr<Rig>> r;
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  for (const char* file : {"glove.yaml", "force_feedback.yaml"}) {
    auto rig = std::make_unique<Rig>();
    rig->device = afford::load_device_description(std::string(AFFORD_SOURCE_DIR "/devices/") + file);
    rig->model = afford::compile_agent_only(afford::load_agent(AFFORD_SOURCE_DIR "/agents/hand.yaml"));
    rig->decoder = std::make_unique<afford::ReportDecoder>(rig->device, rig->model);
    rig->out.resize(static_cast<size_t>(rig->device.out_size));
    rigs().push_back(std::move(rig));
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Rig& rig = *rigs()[data[0] % rigs().size()];
  afford::Sample sample;
  rig.decoder->decode(std::span<const std::uint8_t>(data + 1, size - 1), 0.001, &sample);
  if (rig.device.has_out && size >= 1 + 8 * afford::kFingers) {
    std::array<double, afford::kFingers> force{};
    std::memcpy(force.data(), data + 1, sizeof force);
    afford::encode_forces(rig.device, force, rig.out);
  }
  return 0;
}
