// Active modelling (paper Sec. 3.2, steps 5-7): a force pushed at the
// emphasis and the rotation observed give the tool's lever and spring:
// the angle limits, the rest angle, the torsion spring S_k * S_p^2 and its
// preload (and the pivot's friction, which the same motion shows). What
// the data does not show is the nominal file's, kept, and said so.
#pragma once

#include <string>

#include "measurement.h"

namespace afford {

struct ProbeResult {
  // What write_probed_object writes (SI): found in the data, or the nominal
  // file's value kept where the data does not show it.
  double theta_min = 0, theta_max = 0;  // rad
  // A limit is found where the arm stays still (within its angle noise)
  // while the effort pushes it against the stop past what friction holds.
  bool min_found = false, max_found = false;
  size_t min_samples = 0, max_samples = 0;  // still samples pressed against each stop
  double theta_rest = 0;  // rad, the rest angle written (where the untouched tool sits)
  // The untouched arm seen still (effort within its noise of 0), and where.
  bool rest_seen = false;
  double rest_seen_at = 0;  // rad, median angle
  size_t rest_samples = 0;
  std::string rest_why;     // how the written rest follows from the data or the file

  double torsion = 0, torsion_sigma = 0;  // N*m/rad, S_k * S_p^2
  double spring_constant = 0;             // N/m, written: torsion / S_p^2 with the nominal file's S_p
  double spring_position = 0;             // m, |S_p| of the nominal file
  // Preload and friction are told apart only by motion both ways:
  // closing, friction adds to the spring's torque, opening it takes away.
  bool told_apart = false;
  size_t closing_samples = 0, opening_samples = 0;  // moving, used for the spring
  double preload_torque = 0, preload_sigma = 0;  // N*m at the written rest angle: fitted (the file's if not told apart)
  double preload = 0;        // N, written: the spring's push at the rest angle (the file's if not told apart)
  double friction = 0, friction_sigma = 0;  // N*m, fitted (0 if not told apart)
  double friction_written = 0;  // N*m: the fitted one where told from zero, else the file's
  bool friction_fitted = false; // friction_written is the fitted value
  // Moving one way only: the spring's torque plus friction (closing) or
  // minus it (opening), at the rest angle, N*m.
  double combined_torque = 0, combined_sigma = 0;
  size_t free_samples = 0;   // samples moving between the limits, used for the spring
  std::string object_file;   // the nominal object, whose S_p and geometry are kept
  // The nominal file's values, for what is kept (SI).
  double file_theta_min = 0, file_theta_max = 0, file_rest = 0, file_preload = 0, file_friction = 0;
};

// From every trace of a lever measurement (its `object` gives S_p).
ProbeResult probe_lever(const Measurement& m);

// Text for people: every value as written, with where it comes from. And
// the nominal object file with the probed values in place of its lever
// limits, rest, spring constant and preload, and pivot_friction (the file's
// own values where the probe did not see them), written to `path`.
std::string probe_text(const ProbeResult& p);
void write_probed_object(const ProbeResult& p, const std::string& path);

}  // namespace afford
