// Where a session's agent samples come from: a script, a recording, a live
// device (devices/). The session loop knows only this interface.
#pragma once

#include "sample.h"

namespace afford {

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // The sample for time t (s), the frame's time; false when the source has
  // ended (the script is over, the device is gone). Must not allocate.
  virtual bool sample_at(double t, Sample* out) = 0;
  // How long the source runs, s (infinity for a live device).
  virtual double duration() const = 0;
};

}  // namespace afford
