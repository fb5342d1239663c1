#include "resample.h"

namespace afford {

DeviceStream::Pull SpanStream::pull(Sample* out) {
  if (next_ >= samples_.size()) return Pull::ended;
  *out = samples_[next_++];
  return Pull::sample;
}

ResampledSource::ResampledSource(DeviceStream& stream, Resample mode, double delay, double duration)
    : stream_(stream), mode_(mode), delay_(delay), duration_(duration) {}

void interpolate_samples(const Sample& a, const Sample& b, double w, Sample* out) {
  out->t = a.t + (b.t - a.t) * w;
  out->hand.translation() = a.hand.translation() + (b.hand.translation() - a.hand.translation()) * w;
  const Eigen::Quaterniond qa(a.hand.linear()), qb(b.hand.linear());
  out->hand.linear() = qa.slerp(w, qb).toRotationMatrix();
  for (size_t f = 0; f < out->fingertip.size(); ++f) {
    out->fingertip[f] = a.fingertip[f] + (b.fingertip[f] - a.fingertip[f]) * w;
    for (size_t j = 0; j < out->joint[f].size(); ++j) {
      out->joint[f][j] = a.joint[f][j] + (b.joint[f][j] - a.joint[f][j]) * w;
    }
  }
}

bool ResampledSource::sample_at(double t, Sample* out) {
  const double target = t - delay_;
  // Advance: prev_ is the latest sample at or before target (or the first
  // sample), next_ the one after it, when it has arrived.
  while (!ended_) {
    if (!have_next_) {
      const DeviceStream::Pull p = stream_.pull(&next_);
      if (p == DeviceStream::Pull::ended) {
        ended_ = true;
        break;
      }
      if (p == DeviceStream::Pull::empty) break;
      have_next_ = true;
    }
    if (!have_prev_ || next_.t <= target) {
      prev_ = next_;
      have_prev_ = true;
      have_next_ = false;
      continue;
    }
    break;  // next_ is after target: keep it for interpolation
  }
  if (!have_prev_) return false;
  if (ended_ && !have_next_ && target > prev_.t) return false;
  if (mode_ == Resample::interpolate && have_next_ && target > prev_.t && next_.t > prev_.t) {
    interpolate_samples(prev_, next_, (target - prev_.t) / (next_.t - prev_.t), out);
  } else {
    *out = prev_;
  }
  device_time_ = out->t;
  out->t = t;
  return true;
}

}  // namespace afford
