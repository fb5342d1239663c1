// The device layer's costs: reports per second through the decoder (the
// glove's 64-byte report into a Sample), with its allocations (must be
// zero); and the latency a report adds between its arrival in the ring
// buffer and the frame that reads it, with a synthetic producer thread in
// place of libusb's reader (usb_device.h).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "alloc_counter.h"
#include "bench_source.h"
#include "load.h"
#include "report_decoder.h"
#include "resample.h"
#include "usb_device.h"

namespace afford {
namespace {

using bench::kSource;

Model hand_model() { return compile_agent_only(load_agent(kSource + "/agents/hand.yaml")); }

std::vector<std::uint8_t> glove_report(int k) {
  std::vector<std::uint8_t> r(64, 0);
  r[0] = 1;
  for (int s = 0; s < 22; ++s) write_raw(&r[1 + 2 * s], 2, false, 1000 + (k + s) % 3000);
  write_raw(&r[45], 4, false, 10000 + k);
  return r;
}

void BM_DecodeGloveReport(benchmark::State& bench) {
  const DeviceDescription glove = load_device_description(kSource + "/devices/glove.yaml");
  const Model m = hand_model();
  ReportDecoder decoder(glove, m);
  std::vector<std::vector<std::uint8_t>> reports;
  for (int k = 0; k < 256; ++k) reports.push_back(glove_report(k));
  Sample s;
  size_t i = 0;
  const long before = allocation_count();
  for (auto _ : bench) {
    benchmark::DoNotOptimize(decoder.decode(reports[i++ & 255], 0, &s));
    benchmark::DoNotOptimize(s);
  }
  bench.counters["allocs_per_report"] =
      static_cast<double>(allocation_count() - before) / static_cast<double>(bench.iterations());
  bench.SetItemsProcessed(bench.iterations());
}
BENCHMARK(BM_DecodeGloveReport);

// Report to frame: a producer thread commits glove reports into the ring at
// `rate` Hz (stamped with their arrival time, as the libusb reader does); the
// frame loop runs at 1 kHz in real time and pulls them through the decoder
// (UsbSampleStream::pull). The latency of each report: from its commit to
// the frame that reads it. At 1 kHz frames it lies in [0, 1 ms] plus the
// hand-off; the mean near 0.5 ms is the frame quantisation, what is above
// is the cost of the ring and the decoder.
void BM_ReportToFrameLatency(benchmark::State& bench) {
  const double rate = static_cast<double>(bench.range(0));
  const DeviceDescription glove = load_device_description(kSource + "/devices/glove.yaml");
  const Model m = hand_model();
  std::vector<double> latencies_us;
  latencies_us.reserve(4096);
  for (auto _ : bench) {
    ReportDecoder decoder(glove, m);
    ReportRing ring;
    std::atomic<bool> ended{false};
    UsbSampleStream stream(ring, ended, decoder);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::uint8_t> bytes = glove_report(0);
    std::thread producer([&] {
      const auto period = std::chrono::duration<double>(1.0 / rate);
      for (int k = 0; k < static_cast<int>(rate); ++k) {  // one second
        std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                  period * (k + 0.37)));
        UsbReport* slot = ring.claim();
        if (slot == nullptr) continue;
        std::copy(bytes.begin(), bytes.end(), slot->bytes.begin());
        slot->size = static_cast<int>(bytes.size());
        slot->arrival_ns = steady_now_ns();
        slot->t = 0;
        ring.commit();
      }
      ended.store(true, std::memory_order_release);
    });
    Sample s;
    for (int frame = 1;; ++frame) {
      std::this_thread::sleep_until(start + std::chrono::microseconds(1000 * frame));
      DeviceStream::Pull p;
      while ((p = stream.pull(&s)) == DeviceStream::Pull::sample) {
        latencies_us.push_back(static_cast<double>(stream.last_latency_ns()) * 1e-3);
      }
      if (p == DeviceStream::Pull::ended) break;
    }
    producer.join();
  }
  std::sort(latencies_us.begin(), latencies_us.end());
  double sum = 0;
  for (double l : latencies_us) sum += l;
  const auto at = [&](double q) {
    return latencies_us.empty() ? 0.0 : latencies_us[std::min(latencies_us.size() - 1, static_cast<size_t>(q * static_cast<double>(latencies_us.size())))];
  };
  bench.counters["reports"] = static_cast<double>(latencies_us.size());
  bench.counters["mean_us"] = latencies_us.empty() ? 0 : sum / static_cast<double>(latencies_us.size());
  bench.counters["p50_us"] = at(0.5);
  bench.counters["p99_us"] = at(0.99);
  bench.counters["max_us"] = latencies_us.empty() ? 0 : latencies_us.back();
}
BENCHMARK(BM_ReportToFrameLatency)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The hand-off alone: the consumer polls the ring continuously (no frame
// pacing), so the latency is the ring's and the decoder's.
void BM_RingHandoffLatency(benchmark::State& bench) {
  const DeviceDescription glove = load_device_description(kSource + "/devices/glove.yaml");
  const Model m = hand_model();
  std::vector<double> latencies_us;
  latencies_us.reserve(20000);
  for (auto _ : bench) {
    ReportDecoder decoder(glove, m);
    ReportRing ring;
    std::atomic<bool> ended{false};
    UsbSampleStream stream(ring, ended, decoder);
    const std::vector<std::uint8_t> bytes = glove_report(0);
    std::thread producer([&] {
      for (int k = 0; k < 10000; ++k) {
        const auto next = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
        while (std::chrono::steady_clock::now() < next) {
        }
        UsbReport* slot = ring.claim();
        if (slot == nullptr) continue;
        std::copy(bytes.begin(), bytes.end(), slot->bytes.begin());
        slot->size = static_cast<int>(bytes.size());
        slot->arrival_ns = steady_now_ns();
        ring.commit();
      }
      ended.store(true, std::memory_order_release);
    });
    Sample s;
    DeviceStream::Pull p;
    while ((p = stream.pull(&s)) != DeviceStream::Pull::ended) {
      if (p == DeviceStream::Pull::sample) {
        latencies_us.push_back(static_cast<double>(stream.last_latency_ns()) * 1e-3);
      } else {
        std::this_thread::yield();
      }
    }
    producer.join();
  }
  std::sort(latencies_us.begin(), latencies_us.end());
  double sum = 0;
  for (double l : latencies_us) sum += l;
  bench.counters["reports"] = static_cast<double>(latencies_us.size());
  bench.counters["mean_us"] = latencies_us.empty() ? 0 : sum / static_cast<double>(latencies_us.size());
  bench.counters["p50_us"] = latencies_us.empty() ? 0 : latencies_us[latencies_us.size() / 2];
  bench.counters["p99_us"] = latencies_us.empty() ? 0 : latencies_us[latencies_us.size() * 99 / 100];
}
BENCHMARK(BM_RingHandoffLatency)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace afford
