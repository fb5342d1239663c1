// How the diagnosis judges a set of effects on samples its fit never saw:
// its parameters fitted on every block, its errors on each fold's blocks
// by a fit on the others, its floor (the effort's noise and the motion's
// through its prediction), and whether its residual is white. Each set is
// scored once: the selection and the search for the smallest set that
// explains ask for many of the same (gap/README.md).
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "effects.h"
#include "fit.h"
#include "replay.h"
#include "residual_tests.h"

namespace afford {

// A set's parameters on every block, its score on the folds, and its
// squared error at every held-out sample (to tell two sets apart).
struct Scored {
  SetFit fit;
  std::vector<double> sq;  // N^2, weighted, fold by fold, each judged block's fitted samples in order
  // N, over the held-out samples in the actee's contact, each error
  // scaled to the effort sensor's noise (times the root of its weight):
  // pure noise gives the sensor's noise, however little the samples weigh.
  double rmse_contact = 0;
  // Its residual's whiteness test, once asked: the search asks it of
  // the same set at several of its tests.
  mutable std::optional<ResidualTest> residual_test;
};

// What the sets are judged on, built once by diagnose(); the judge keeps
// references to it.
struct JudgedData {
  const std::vector<Replay>& replays;  // the blocks of the traces, weighed
  const Fitter& every;                 // fitted on every block
  const std::vector<Fitter>& folds;    // fold f fitted on the blocks outside judged[f]
  const std::vector<std::vector<size_t>>& judged;
  // The same blocks with as much noise again on the motion, and their fitter.
  const std::vector<Replay>& noisier;
  const Fitter& noisier_every;
  // Per held-out sample, in the order Scored::sq lists them: in the actee's contact.
  const std::vector<bool>& judged_in_contact;
  size_t contact_samples = 0;  // how many are
  double noise = 0;            // N, the effort's own
};

// A runner-up this many standard errors worse than the best is told apart
// from it (the paired test over the held-out samples).
inline constexpr double kSeparated = 3;
// Or one that cuts the mean squared error by less than this share of the
// best's cut.
inline constexpr double kNearlyAsFar = 0.9;

class Judge {
 public:
  explicit Judge(const JudgedData& data) : data_(data) {}

  const Scored& score(const std::vector<EffectKind>& set);
  bool scored(const std::vector<EffectKind>& set) const { return sets_.contains(set); }
  // The set's parameters on every block, fitted once: the search fits a
  // set there before it asks for its score, the look-alikes after.
  const SetFit& fitted(const std::vector<EffectKind>& set);

  // What the model cannot match better than (N): the effort's noise and
  // the motion's, passed through the set's prediction.
  double floor_of(const SetFit& f) const;
  // Within `factor` times the floor over every held-out sample, and over
  // those in the actee's contact.
  bool within(const Scored& f, double factor) const;
  // Matched to the floor within the tolerance of the noise's own estimate.
  bool matched(const Scored& f) const { return within(f, kMatched); }
  // The motion's noise the set passes into its prediction, sample by
  // sample (N times the root of the sample's weight).
  std::vector<std::vector<double>> noise_through(const SetFit& f) const;
  // The set's residual of every block, each sample's in units of the
  // effort sensor's noise (times the root of its weight), as the fits
  // weigh the samples.
  std::vector<std::vector<double>> weighed_residual(const SetFit& f) const;
  // The residual tested for whiteness, the noise its prediction carries
  // by itself taken off (once a set: kept with its score).
  const ResidualTest& whiteness_of(const Scored& f) const;
  // The held-out squared errors of a scored set (as Scored::sq lists
  // them) less the motion's noise its own prediction carries at each
  // (N^2, weighed): what is left of the misfit beyond that noise.
  std::vector<double> beyond_own_noise(const Scored& f) const;
  // Of the held-out squared errors `sq` (as Scored::sq lists them), those
  // in the actee's contact.
  std::vector<double> in_contact_only(const std::vector<double>& sq) const;
  const JudgedData& data() const { return data_; }

 private:
  Scored score_anew(const std::vector<EffectKind>& set, const SetFit& whole) const;

  const JudgedData data_;
  std::map<std::vector<EffectKind>, SetFit> fits_;
  std::map<std::vector<EffectKind>, Scored> sets_;
};

}  // namespace afford
