// The experimenter's reading of a plates test (reality.h): the curve of
// force against deflection, up to the actee's limit, fitted with the
// actee file's family (actees/README.md). Shared by both realities and
// by case_files.cpp, which writes the law chosen into the actee file.
// The law is fitted to the engine's curve; nothing here plays it.
#pragma once

#include <vector>

namespace gapcheck {

struct PlatesFit {
  double stiffness = 0;   // N/m, K of the law chosen
  double exponent = 0;    // 0: the linear law; else n of the power law
  double reference = 0;   // m, r = limit / K (the power law only)
  double rms_linear = 0;  // N, the linear law's misfit over the curve
  double rms_power = 0;   // N, the best power law's
  double rms_misfit = 0;  // N, the law chosen's
};

// `deflection` (m) and `force` (N), the same length; `thickness` h (m)
// across the plates, `limit` (N). The linear law F = K x h / (h - x),
// least squares through 0; the power law F = K r (x / r)^n h / (h - x),
// r = limit / K, is chosen where it more than halves the RMS misfit.
// Throws std::runtime_error when fewer than 10 points have x > 0.
PlatesFit fit_plates(const std::vector<double>& deflection, const std::vector<double>& force, double thickness,
                     double limit);

}  // namespace gapcheck
