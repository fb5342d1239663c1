// Resampling: a device gives samples at its own rate (a 100 Hz glove), the
// session asks at its frame rate (1 kHz). ResampledSource turns a stream of
// timestamped device samples into a SampleSource by hold or linear
// interpolation, chosen per device (device_description.h `resample`).
#pragma once

#include <limits>
#include <span>

#include "device_description.h"
#include "sample_source.h"

namespace afford {

// Timestamped device samples in time order (their t, s, on the session's
// clock).
class DeviceStream {
 public:
  enum class Pull { sample, empty, ended };
  virtual ~DeviceStream() = default;
  // The next sample into *out: `sample`; none yet (a live device between
  // reports): `empty`; never again (end of data, device gone): `ended`.
  // Must not allocate.
  virtual Pull pull(Sample* out) = 0;
};

// A stream over samples in memory (tests, recordings).
class SpanStream : public DeviceStream {
 public:
  explicit SpanStream(std::span<const Sample> samples) : samples_(samples) {}
  Pull pull(Sample* out) override;

 private:
  std::span<const Sample> samples_;
  size_t next_ = 0;
};

class ResampledSource : public SampleSource {
 public:
  // Frame time t reads the device at t - delay (s): with interpolate, a
  // live device needs one device period of delay to have the sample after
  // that time. `duration`: how long the source runs (s).
  ResampledSource(DeviceStream& stream, Resample mode, double delay = 0,
                  double duration = std::numeric_limits<double>::infinity());

  // Hold: the latest device sample at or before t - delay. Interpolate:
  // linear between the samples around t - delay (the hand's rotation by
  // slerp), the latest one when the next has not arrived. Before the first
  // device sample, the first. out->t is the frame time t; the device time
  // used is device_time(). False once the stream has ended and t - delay
  // is past its last sample, or when no sample ever came. No allocation.
  bool sample_at(double t, Sample* out) override;
  double duration() const override { return duration_; }

  double device_time() const { return device_time_; }  // s, the device timestamp of the last answer
  bool ended() const { return ended_; }

 private:
  DeviceStream& stream_;
  Resample mode_;
  double delay_, duration_;
  Sample prev_{}, next_{};
  bool have_prev_ = false, have_next_ = false, ended_ = false;
  double device_time_ = 0;
};

// a + (b - a) * w, every part of a sample (t too).
void interpolate_samples(const Sample& a, const Sample& b, double w, Sample* out);

}  // namespace afford
