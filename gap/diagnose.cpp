#include "diagnose.h"

#include "blocks.h"
#include "derivatives.h"
#include "judge.h"
#include "late_sensor.h"
#include "per_trace.h"
#include "sensor_gain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace afford {
namespace {

constexpr double kRealMargin = 0.05;    // an effect must cut the held-out RMSE by this fraction
constexpr int kMaxEffects = 3;
constexpr double kStructured = 2;       // a residual's whiteness statistic over this many times its 99 % point is a shape
constexpr double kSlightShape = 0.05;   // a shape with less than this share of a matched residual's variance is slight
constexpr size_t kFolds = 5;            // cross-validation folds, at most

// The measurement's own noise, from the second differences of its fitted
// samples (white_noise_of_second_differences: not moved by the few jumps
// where friction changes sign). Never below what the file's printed digits
// resolve: a noise-free trace is still rounded, and an effect that leaves
// only that is explained.
double noise_of(const std::vector<Replay>& replays) {
  std::vector<double> d2;
  double resolution = 0;
  for (const Replay& r : replays) {
    resolution = std::max(resolution, r.resolution);
    for (size_t i = 0; i + 2 < r.t.size(); ++i) {
      if (!r.fitted[i] || !r.fitted[i + 1] || !r.fitted[i + 2]) continue;
      d2.push_back(std::abs(r.measured[i] - 2 * r.measured[i + 1] + r.measured[i + 2]) * r.to_newtons);
    }
  }
  return std::max(white_noise_of_second_differences(d2), resolution);
}

// The measurement replayed with as much noise again added to its angles
// (or displacements), from a fixed seed: the same measurement as the
// model sees it through a second, independent sensor of the motion.
std::vector<Replay> replay_with_input_noise(const Model& model, Measurement m, const std::vector<double>& deviation,
                                           const std::vector<Block>& blocks) {
  std::mt19937 random(20261123);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Signal x = m.rig == Rig::lever ? Signal::angle : Signal::displacement;
  for (size_t i = 0; i < m.traces.size(); ++i) {
    for (double& v : m.traces[i][x]) v += deviation[i] * noise(random);
  }
  return sliced(m.rig == Rig::lever ? replay_lever(model, m) : replay_plates(model, m), blocks);
}

std::string effects_text(const std::vector<EffectKind>& set) {
  std::string s;
  for (EffectKind k : set) s += (s.empty() ? "" : " + ") + std::string(manifest_of(k).name);
  return s.empty() ? "the nominal model" : s;
}

// Sets, one after another: "friction | damping + preload".
std::string sets_text(const std::vector<std::vector<EffectKind>>& sets) {
  std::string s;
  for (const std::vector<EffectKind>& set : sets) s += (s.empty() ? "" : " | ") + effects_text(set);
  return s;
}

// Each trace's residual under the nominal model and under the set fitted
// on the folds that did not judge it, as signals to plot.
std::vector<HeldOutCurve> held_out_curves(const std::vector<Replay>& replays, const Fitter& fitter, const SetFit& nominal,
                                          const std::vector<Fitter>& folds, const std::vector<std::vector<size_t>>& judged,
                                          const std::vector<EffectKind>& chosen) {
  std::vector<HeldOutCurve> curves(replays.size());
  for (size_t f = 0; f < folds.size(); ++f) {
    const SetFit fit = folds[f].fit(chosen);
    for (size_t i : judged[f]) {
      const Replay& r = replays[i];
      const std::vector<double> before = fitter.residual(nominal, i), after = folds[f].residual(fit, i);
      HeldOutCurve& c = curves[i];
      c.file = r.file;
      const auto own = [&](const auto& v) {  // the block's samples, without its history
        return std::decay_t<decltype(v)>(v.begin() + static_cast<long>(r.history), v.end());
      };
      c.t = own(r.t);
      c.x = own(r.x);
      c.phase = own(r.phase);
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (size_t s = r.history; s < r.t.size(); ++s) {
        const double measured = r.measured[s] * r.to_newtons;
        c.measured.push_back(measured);
        c.nominal.push_back(r.fitted[s] ? measured - before[s] : nan);
        c.fitted.push_back(r.fitted[s] ? measured - after[s] : nan);
      }
    }
  }
  return curves;
}

}  // namespace

const char* verdict_name(Verdict v) {
  static const char* const kNames[] = {"none", "explained", "ambiguous", "unexplained"};
  return kNames[static_cast<int>(v)];
}

bool same_effects(std::vector<EffectKind> a, std::vector<EffectKind> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

Measurement with_effects(const Measurement& m, const std::vector<EffectFit>& effects) {
  Measurement with = m;
  for (const EffectFit& e : effects) {
    EffectSpec spec;
    spec.kind = e.kind;
    spec.name = manifest_of(e.kind).name;
    spec.param = e.value;
    // A fitted delay is searched on top of the measurement's own (the
    // replay has delayed the nominal by it already): the sensor's is both.
    if (e.kind == EffectKind::sensor_latency) {
      for (const EffectSpec& own : m.options.effects) {
        if (own.kind == EffectKind::sensor_latency && own.enabled) spec.param[0] += own.param[0];
      }
    }
    with.options.effects.push_back(spec);
    if (e.kind == EffectKind::actee_compliance && with.actee) with.actee->stiffness *= e.stiffness_factor;
  }
  return with;
}

Model compile_with(const Measurement& m, const std::vector<EffectFit>& effects) {
  const Measurement with = with_effects(m, effects);
  return m.rig == Rig::lever ? compile_measurement(with) : compile_actee_only(*with.actee, with.options);
}

Diagnosis diagnose(const Measurement& m, const DiagnoseOptions& options) {
  Diagnosis d;
  d.measurement = m.name;
  const Model model = m.rig == Rig::lever ? compile_measurement(m) : compile_actee_only(*m.actee, m.options);
  // The traces whole, and cut into blocks for cross-validation: each fold's
  // blocks are judged by a fit on the others; the parameters reported come
  // from a fit on every trace.
  std::vector<Replay> whole = m.rig == Rig::lever ? replay_lever(model, m) : replay_plates(model, m);
  auto asked = [&](EffectKind k) {
    return options.library.empty() || std::find(options.library.begin(), options.library.end(), k) != options.library.end();
  };
  std::vector<size_t> every(whole.size());
  for (size_t i = 0; i < every.size(); ++i) every[i] = i;
  // Squeezed samples all but still are fitted where the file's friction
  // is small against the actee's noise; the friction the data shows (a
  // fit of friction alone) may not be, and then they are left out for
  // every set alike. Only where friction is in the library: withheld, it
  // takes nothing out.
  if (m.rig == Rig::lever && asked(EffectKind::pivot_friction)) {
    const SetFit alone = Fitter(model, whole, every, {}).fit({EffectKind::pivot_friction});
    if (!alone.effects.empty()) release_held(whole, alone.effects.front().value[0]);
  }
  // Where a sensor may read late, its readings after a stretch the model
  // cannot predict are left out for every set alike: the delay fitted on
  // the whole traces (late_sensor.h) decides how long after.
  const bool latency_asked = m.rig == Rig::lever && asked(EffectKind::sensor_latency);
  const double delay = latency_asked ? late_readings_left_out(model, whole, asked) : 0.0;  // s (0: none left out)
  std::vector<double> x_noise;  // each trace's motion sensor's
  for (const Replay& r : whole) x_noise.push_back(r.x_noise);
  const std::vector<Block> blocks = blocks_of(whole);
  std::vector<Replay> replays = sliced(whole, blocks);
  d.noise = noise_of(replays);
  // Weighed whole, then cut again: a late reading's weight comes from
  // `delay` before it, which may lie in the block before.
  weigh(whole, d.noise, delay);
  replays = sliced(whole, blocks);
  const size_t folds = std::min<size_t>(replays.size(), kFolds);
  std::vector<size_t> all(replays.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  SumsCache sums;  // shared by the fitters of `replays`
  std::vector<Fitter> fold_fitters;
  std::vector<std::vector<size_t>> judged(folds);
  for (size_t f = 0; f < folds; ++f) {
    std::vector<size_t> train;
    for (size_t i : all) (i % folds == f ? judged[f] : train).push_back(i);
    fold_fitters.emplace_back(model, replays, train, judged[f], &sums);
  }
  for (const Replay& r : replays) d.judged_on.push_back(r.file);
  d.folds = folds;
  d.traces = whole.size();
  for (size_t f = 0; f < folds; ++f) {
    FoldSize fs;
    for (size_t i : judged[f]) {
      ++fs.blocks;
      fs.fitted += static_cast<size_t>(std::count(replays[i].fitted.begin(), replays[i].fitted.end(), true));
    }
    d.fold_sizes.push_back(fs);
  }
  const Fitter fitter(model, replays, all, {}, &sums);
  std::vector<Replay> noisier = replay_with_input_noise(model, m, x_noise, blocks);
  for (size_t i = 0; i < noisier.size(); ++i) noisier[i].weight = replays[i].weight;
  const Fitter noisier_fitter(model, noisier, all, {});
  std::vector<EffectKind> library = options.library.empty() ? fitter.candidates() : options.library;
  const std::vector<EffectKind> applicable = fitter.candidates();
  std::erase_if(library, [&](EffectKind k) { return std::find(applicable.begin(), applicable.end(), k) == applicable.end(); });
  // Which held-out samples have the actee deflected, in the order a set's
  // score lists them (judge.h). An actee's stiffness passes the angle's
  // noise into its prediction, so its samples weigh little: a gap there,
  // many times their noise, would be lost in the RMSE over every sample.
  // The actee's part is judged on its own. Between plates the actee is
  // all there is.
  std::vector<bool> judged_in_contact;
  size_t contact_samples = 0;
  for (size_t k = 0; k < folds; ++k) {
    for (size_t i : judged[k]) {
      const Replay& r = replays[i];
      for (size_t s = 0; s < r.t.size(); ++s) {
        if (!r.fitted[s]) continue;
        const bool contact = m.rig == Rig::lever && r.deflection[s] > 0;
        judged_in_contact.push_back(contact);
        if (contact) ++contact_samples;
      }
    }
  }
  // A contact of fewer than kMinBlock samples is too little to judge on
  // its own, as nothing is: over 4 samples an RMSE 1.6 times the noise
  // comes one time in 25 by chance alone (an effect-free tongs' crack
  // read `unexplained` so, report seed 1,001,713, in both engines; over
  // 90 samples 1.18 times, an effect-free nutcracker's in MuJoCo,
  // development seed 3232). Its samples count among every sample, as a
  // brush at a crack does in the blocks.
  if (contact_samples < kMinBlock) {
    std::fill(judged_in_contact.begin(), judged_in_contact.end(), false);
    contact_samples = 0;
  }
  Judge judge({replays, fitter, fold_fitters, judged, noisier, noisier_fitter, judged_in_contact, contact_samples,
               d.noise});
  const Scored nominal_scored = judge.score({});
  const SetFit& nominal = nominal_scored.fit;
  d.rmse_before = nominal.rmse_test;
  const std::vector<std::vector<double>> before = judge.weighed_residual(nominal);
  // The nominal model matches to the noise when its held-out RMSE is at
  // the noise, or within kMatched of it (the noise's own estimate is not
  // exact) with a white residual. Within kMatched but structured is a
  // small effect over many samples, its RMSE near the noise but its shape
  // plain: the search asks whether a candidate explains it.
  const bool nominal_within = judge.matched(nominal_scored);
  const bool nominal_matched =
      judge.within(nominal_scored, 1.0) || (nominal_within && judge.whiteness_of(nominal_scored).white);
  // Effects added match once at the floor, or within the tolerance with
  // a white residual, where the nominal model was not. Where it was, the
  // gap is its structure, and what explains it leaves a white residual: a
  // look-alike that trims a gap to the floor and leaves its shape (a
  // weight's cosine standing in for a force sensor's gain) has explained
  // nothing.
  // Clearly structured: over twice the whiteness test's 99 % point. A
  // coloured noise's lags are correlated, so the statistic's tail is
  // heavier than chi-square's: just over the point is not yet a shape (a
  // force sensor's gain error one way up is 1434 against 37.6).
  auto white_under = [&](const Scored& f) {
    const ResidualTest& t = judge.whiteness_of(f);
    return t.q <= kStructured * t.threshold;
  };
  auto effects_match = [&](const Scored& f) {
    return !nominal_within && (judge.within(f, 1.0) || (judge.matched(f) && white_under(f)));
  };
  // Where the nominal model was off, a set of one effect or two within
  // the noise's tolerance whose residual keeps a slight shape has
  // explained the gap (as the verdict judges it, below):
  // over thousands of samples the whiteness test finds a shape far
  // smaller than the tolerance allows (the right damping and latency, 2 %
  // off, left 4.5 % of the variance shaped at 7 times the test's point,
  // development seed 3427, both engines). A shape a look-alike leaves is
  // most often a larger share (a backlash read as friction and an
  // inertia, 14 %; a viscoelastic actee as an actee's law, 10 %). Three
  // effects can trim a far gap to a slight shape (a sensor reading 80 %
  // high one way up, taken up by a weight, a preload and friction:
  // 4.4 %), and so can any set where the nominal model was already within
  // the tolerance, where the shape is the gap: there only a white
  // residual explains it.
  auto leaves_a_slight_shape = [&](const Scored& f, size_t effects) {
    return !nominal_within && effects <= 2 && judge.matched(f) && judge.whiteness_of(f).share < kSlightShape;
  };
  // Each candidate is judged where it acts: an effect of the actee where
  // the jaws deflect it, the others over every sample.
  auto in_contact = [&](EffectKind k) { return contact_samples > 0 && manifest_of(k).home == EffectHome::actee; };
  // An effect earns its place in a set when the set with it cuts the
  // held-out error where the effect acts by kRealMargin against the set
  // without it, and the training AICc by kAiccMargin. Near the floor an
  // effect can cut only what lies above it (a heavy arm beside a damping
  // that leaves 3 % over the floor, plain in shape): there it earns its
  // place too where it completes the explanation (the set with it
  // explains the gap, the set without it does not) and the held-out
  // samples tell the two apart.
  // An actee's law must also find a gap in the contact: its errors there
  // are scaled to the sensor's noise, so pure noise reads that noise, and
  // a contact within kMatched of it shows nothing for a law to explain. A
  // law measured on plates over the whole squeeze misfits the little a
  // light squeeze presses by a shade, and a changed exponent took 3 to 6
  // % of it where the contact read 1.04 to 1.09 times the noise.
  auto earns_place = [&](const Scored& with, const Scored& without, bool contact, EffectKind added) {
    const double was = contact ? without.rmse_contact : without.fit.rmse_test;
    const double now = contact ? with.rmse_contact : with.fit.rmse_test;
    if (!(was > 0) || with.fit.aicc > without.fit.aicc - kAiccMargin) return false;
    if (contact && was <= kMatched * d.noise) return false;
    if (1 - now / was >= kRealMargin) return true;
    auto where = [&](const std::vector<double>& sq) { return contact ? judge.in_contact_only(sq) : sq; };
    std::vector<EffectKind> others;
    for (const EffectFit& e : without.fit.effects) others.push_back(e.kind);
    return judge.matched(with) && white_under(with) && !effects_match(without) &&
           paired_t(where(with.sq), where(without.sq)) >= kSeparated && !adds_nothing_to(fitter, added, others);
  };
  Scored current_scored = nominal_scored;
  const SetFit& current = current_scored.fit;
  std::vector<EffectKind> chosen;
  bool ambiguous = false;
  char line[256];
  // Each step's held-out RMSE, and in the actee's contact where there is one.
  auto step_line = [&](const std::string& what, const Scored& f) {
    char text[160];
    std::snprintf(text, sizeof text, " held-out RMSE %.4g N", f.fit.rmse_test);
    std::string out = what + text;
    if (contact_samples > 0) {
      std::snprintf(text, sizeof text, " (in the actee's contact %.4g N, each error scaled to the sensor's noise)",
                    f.rmse_contact);
      out += text;
    }
    return out;
  };
  std::snprintf(line, sizeof line, " (noise %.3g N)", d.noise);
  d.steps.push_back(step_line("nominal:", nominal_scored) + line);
  // The sets as good as the best so far: where the data cannot tell two
  // candidates apart at one step, the next step decides between them
  // (friction or damping alone, then only friction with a progressive
  // spring), so each is carried on and extended.
  std::vector<std::vector<EffectKind>> branches = {{}};
  if (!nominal_matched) {
    for (int step = 0; step < kMaxEffects; ++step) {
      struct Tried {
        Scored scored;
        std::vector<EffectKind> set;  // a branch and the effect added to it, last
      };
      std::vector<Tried> tried;
      for (const std::vector<EffectKind>& branch : branches) {
        for (EffectKind k : library) {
          if (std::find(branch.begin(), branch.end(), k) != branch.end()) continue;
          std::vector<EffectKind> set = branch;
          set.push_back(k);
          auto tried_before = [&](const Tried& t) { return same_effects(t.set, set); };
          if (std::any_of(tried.begin(), tried.end(), tried_before)) continue;
          Scored f = judge.score(set);
          if (f.fit.valid) tried.push_back({std::move(f), set});
        }
      }
      if (tried.empty()) break;
      // The best cuts the held-out RMSE where it acts by the largest share.
      auto rmse_in = [](const Scored& f, bool contact) { return contact ? f.rmse_contact : f.fit.rmse_test; };
      auto share_cut = [&](const Tried& t) {
        const bool contact = in_contact(t.set.back());
        const double was = rmse_in(current_scored, contact);
        return was > 0 ? 1 - rmse_in(t.scored, contact) / was : 0.0;
      };
      std::stable_sort(tried.begin(), tried.end(), [&](const Tried& a, const Tried& b) { return share_cut(a) > share_cut(b); });
      // Only a candidate that earns its place where it acts competes: one
      // that cuts a share where it is judged (the contact) but not the
      // training AICc must not stop another that earns both.
      auto earns = [&](const Tried& t) {
        return earns_place(t.scored, current_scored, in_contact(t.set.back()), t.set.back());
      };
      std::stable_partition(tried.begin(), tried.end(), earns);
      const Tried& best = tried.front();
      const bool contact = in_contact(best.set.back());
      if (!earns(best)) {
        d.steps.push_back(step_line(std::string("no further effect: the best, ") + manifest_of(best.set.back()).name +
                                        ", would give",
                                    best.scored));
        break;
      }
      // As good: a runner-up that cuts the held-out error nearly as far as
      // the best, where the best acts, and that the held-out samples there
      // do not tell apart from it (not significantly worse, sample by
      // sample). The first alone is not enough where the best's cut lies
      // in a few samples: batch means that are mostly zero make a weak test.
      // Sample by sample beyond the motion's noise each prediction carries
      // (Judge::beyond_own_noise, as for the smallest set that explains,
      // below): a tongs' true damping beside friction, on an uneven
      // triangle where a weight reads as it, left 0.0823 N held out at its
      // floor of 0.0826 N against the weight's 0.0789 N at 0.0798 N, and
      // was judged worse by the angle's rate noise alone (development seed
      // 9434, ODE).
      auto where = [&](const std::vector<double>& sq) { return contact ? judge.in_contact_only(sq) : sq; };
      const double was = rmse_in(current_scored, contact);
      auto cut_of = [&](const Scored& f) { return was * was - rmse_in(f, contact) * rmse_in(f, contact); };  // N^2
      const double cut = cut_of(best.scored);
      const std::vector<double> best_sq = where(judge.beyond_own_noise(best.scored));
      // Where the best explains the gap, a runner-up that does not (over
      // the tolerance, or within it with a clear shape) is not as good,
      // however the paired test's batches weigh a misfit that comes back
      // each cycle (a friction leaving 1.54 times the floor held out
      // beside the true damping at it, on a sine: development seed 6039,
      // both engines). The converse of a runner-up that explains where
      // the best does not, below.
      const bool best_explains = effects_match(best.scored);
      std::vector<const Tried*> good = {&best};
      for (size_t j = 1; j < tried.size(); ++j) {
        const Scored& runner_up = tried[j].scored;
        if (cut_of(runner_up) >= kNearlyAsFar * cut && (!best_explains || effects_match(runner_up)) &&
            paired_t(best_sq, where(judge.beyond_own_noise(runner_up))) < kSeparated) {
          good.push_back(&tried[j]);
        }
      }
      // A set as good as the best that already explains the gap, where the
      // best does not, ends the search with it: the next step extends the
      // best's set and judges every extension against the best's error, so
      // any effect added to the set that explains would seem to earn its
      // place (a late sensor, at the floor, with a progressive spring added
      // against an actee's law that had cut more in the contact alone).
      bool runner_up_explains = false;
      if (good.size() > 1 && !best_explains) {
        std::vector<const Tried*> explaining;
        for (const Tried* t : good) {
          if (earns(*t) && effects_match(t->scored)) explaining.push_back(t);
        }
        if (!explaining.empty()) {
          good = explaining;
          runner_up_explains = true;
        }
      }
      const Tried& pick = *good.front();
      branches.clear();
      for (const Tried* t : good) branches.push_back(t->set);
      const bool on_chosen = std::equal(chosen.begin(), chosen.end(), pick.set.begin());
      chosen = pick.set;
      std::string added = std::string("+ ") + manifest_of(chosen.back()).name;
      if (!on_chosen) added += " (to " + effects_text({chosen.begin(), chosen.end() - 1}) + ")";
      d.steps.push_back(step_line(added + ":", pick.scored));
      if (runner_up_explains) {
        d.steps.push_back("  as good as " + effects_text(best.set) + ", which cut more where it acts, and it explains the gap");
      }
      if (branches.size() > 1) d.steps.push_back("  as good: " + sets_text({branches.begin() + 1, branches.end()}));
      current_scored = pick.scored;
      // A set that explains ends the search, unless it lies over the floor
      // with a shape the whiteness test finds (short of twice its point):
      // then a further effect may still earn its place by the plain test
      // (a preload within the tolerance left a weight's shape following
      // the angle: development seed 6531, ODE). effects_match with the
      // residual white, its whiteness tested once: white is under twice
      // the point too.
      if (!nominal_within && (judge.within(current_scored, 1.0) ||
                              (judge.matched(current_scored) && judge.whiteness_of(current_scored).white))) {
        break;
      }
    }
  }
  // Forward selection adds one effect at a time, each for what it cuts
  // alone: where two effects together explain the gap and neither alone
  // cuts much (a weight and a damping on closing-only strokes, each alone
  // all but a constant torque), or a first choice stands in for two (a
  // preload for an inertia and a progressive spring), it ends short of
  // explaining. Then the smallest set that explains is looked for among
  // every single effect and pair, each of its effects earning its place
  // against the set without it; sets of that size as good as the best
  // are its look-alikes. Where it ends with three that explain, a pair
  // that explains too is the answer: the data do not ask for the third
  // (a clean acceleration through closing strokes that are pure cosines
  // is the angle again, and an inertia took a weight's place beside a
  // preload that stood in for it).
  // Every single effect and pair of the library.
  std::vector<std::vector<EffectKind>> sets;
  for (size_t a = 0; a < library.size(); ++a) {
    sets.push_back({library[a]});
    for (size_t b = a + 1; b < library.size(); ++b) sets.push_back({library[a], library[b]});
  }
  auto each_earns = [&](const std::vector<EffectKind>& set) {
    for (EffectKind k : set) {
      std::vector<EffectKind> without = set;
      std::erase(without, k);
      if (!earns_place(judge.score(set), judge.score(without), in_contact(k), k)) return false;
    }
    return true;
  };
  // The sets of `size` effects that explain the gap, each of their
  // effects earning its place against the set without it, the least
  // held-out error first. `short_of`: the held-out squared errors of a
  // forward selection that ended short of explaining, less its own
  // prediction's noise (Judge::beyond_own_noise), or null;
  // `slight_shape_explains`: whether a slight shape may be left (below).
  // A set explains where its held-out error is at its own floor, and a
  // large damping passes the angle's rate noise on into its prediction,
  // raising its floor with it. Where the forward selection ended short
  // of explaining, a set that predicts the held-out samples clearly
  // worse than its set, beyond the motion's noise each prediction
  // carries, has not explained the gap (a damping alone left 0.61 N
  // under its floor of 0.65 N where friction alone left 0.31 N, and the
  // truth was both: development seeds 5031 and 5082, a tongs in ODE,
  // which the forward selection names now). Beyond that noise: worse by
  // it alone is no misfit. A nutcracker's true arm inertia, the angle's
  // noise differentiated twice, left 0.084 N at its floor of 0.085 N,
  // white, where a progressive spring left 0.070 N with a shape, and
  // read `unexplained` (development seed 9356, ODE).
  // Where the forward selection ended short of explaining, or with three
  // effects, the smallest set that explains is judged as a verdict is:
  // one or two effects may leave a slight shape. Asked for a white
  // residual only, a press turned, its truth a weight and a progressive
  // spring, where the selection took a preload 1.7 standard errors from
  // zero beside them, read `unexplained`: the pair left a shape of 3 %
  // (development seed 6976, MuJoCo). Its cost is the verdict's: a
  // look-alike that leaves a slight shape explains as well (a force
  // sensor reading 6 % high one way up, taken to 1.02 times the floor by
  // a progressive spring and an arm's inertia, 3.9 %: the gain is told
  // beside them, tested). Where the selection's pair left a white
  // residual, a pair that leaves a shape is not as good as it: a tongs'
  // preload and damping, cracked in the first cycle, got two such pairs
  // as look-alikes, four sets in all (development seed 8259, ODE).
  auto explains = [&](const Scored& f, size_t effects, bool slight_shape_explains) {
    return effects_match(f) || (slight_shape_explains && leaves_a_slight_shape(f, effects));
  };
  auto explaining_sets = [&](size_t size, const std::vector<double>* short_of, bool slight_shape_explains) {
    std::vector<const std::vector<EffectKind>*> explaining;
    for (const std::vector<EffectKind>& set : sets) {
      if (set.size() != size) continue;
      // A set that misses the floor on every sample it is fitted to
      // misses it held out: only those that may explain are scored on
      // the folds (a sixth of the fits for the others).
      if (!judge.scored(set)) {
        const SetFit& in_sample = judge.fitted(set);
        if (!in_sample.valid || in_sample.rmse_train > kMatched * judge.floor_of(in_sample)) continue;
      }
      const Scored& f = judge.score(set);
      if (short_of && paired_t(*short_of, judge.beyond_own_noise(f)) >= kSeparated) continue;
      if (f.fit.valid && explains(f, set.size(), slight_shape_explains) && each_earns(set)) explaining.push_back(&set);
    }
    auto error_of = [&](const std::vector<EffectKind>* set) {
      const Scored& f = judge.score(*set);
      return std::max(f.fit.rmse_test, f.rmse_contact);
    };
    std::stable_sort(explaining.begin(), explaining.end(),
                     [&](const auto* a, const auto* b) { return error_of(a) < error_of(b); });
    return explaining;
  };
  // As good as `best`: cuts the nominal's held-out error nearly as far,
  // and the held-out samples do not tell the two apart.
  auto as_good_as = [&](const Scored& best, const Scored& other) {
    const double was = nominal.rmse_test * nominal.rmse_test;
    const double cut = was - best.fit.rmse_test * best.fit.rmse_test;
    return was - other.fit.rmse_test * other.fit.rmse_test >= kNearlyAsFar * cut && paired_t(best.sq, other.sq) < kSeparated;
  };
  if (!nominal_matched && (!effects_match(current_scored) || chosen.size() > 2)) {
    const bool forward_short = !effects_match(current_scored);
    const std::vector<double> forward_sq = forward_short ? judge.beyond_own_noise(current_scored) : std::vector<double>{};
    for (size_t size = 1; size <= 2; ++size) {
      const std::vector<const std::vector<EffectKind>*> explaining =
          explaining_sets(size, forward_short ? &forward_sq : nullptr, true);
      if (explaining.empty()) continue;
      const Scored& best = judge.score(*explaining.front());
      branches = {*explaining.front()};
      for (size_t j = 1; j < explaining.size(); ++j) {
        if (as_good_as(best, judge.score(*explaining[j]))) branches.push_back(*explaining[j]);
      }
      chosen = branches.front();
      current_scored = best;
      d.steps.push_back(step_line("smallest set that explains, " + effects_text(chosen) + ":", best));
      if (branches.size() > 1) d.steps.push_back("  as good: " + sets_text({branches.begin() + 1, branches.end()}));
      break;
    }
  } else if (!nominal_matched && chosen.size() == 2) {
    // A pair the forward selection explained the gap with may have a
    // look-alike pair that no step compared it with: each effect of the
    // other pair alone cut less than a third effect that stood in for
    // both (a progressive spring and a preload on one trace's closing-only
    // strokes, taken up by a weight and then a late sensor: development
    // seed 6560, ODE). Every pair that explains as well is as good.
    std::vector<std::vector<EffectKind>> more;
    for (const std::vector<EffectKind>* set : explaining_sets(2, nullptr, false)) {
      auto same = [&](const std::vector<EffectKind>& b) { return same_effects(b, *set); };
      const bool listed = std::any_of(branches.begin(), branches.end(), same);
      if (!listed && as_good_as(current_scored, judge.score(*set))) more.push_back(*set);
    }
    if (!more.empty()) d.steps.push_back("  as good, among every pair that explains: " + sets_text(more));
    branches.insert(branches.end(), more.begin(), more.end());
  }
  if (branches.size() > 1) {
    ambiguous = true;
    d.ambiguous = branches;
  }
  // Before naming: can the fitted samples tell the chosen effects from
  // the other effects at all? If not, every look-alike set is as good,
  // and the report says which measurement would separate them. Every
  // effect that applies is asked, also those left out of the library: a
  // look-alike of what was left out is no more named than any other.
  if (!chosen.empty()) {
    d.look_alikes = look_alikes(fitter, chosen, applicable);
    // Where one effect has one look-alike, the two at once fit as well as
    // either (their columns all but parallel): the data cannot tell a
    // weight from a preload one way up, nor from both. Listed only where
    // the two make a pair: beside a second chosen effect they would make
    // three, and where a pair explains the data do not ask for a third
    // (the smallest set that explains, above). Where it has several, each
    // pair is listed only where none of them takes its part alone: then
    // the pairs are all the data cannot tell from it (a snips' weight and
    // lower preload on closing-only strokes one way up, read as a weight
    // with a friction and a preload each outside its range alone, named
    // the weight alone: development seed 9374, ODE); where some do, the
    // singles already say the data cannot tell them apart.
    // Physics tells what the data cannot: in the chosen effect's place the
    // look-alike must take its part within its physical range (one way up
    // a weight reads as a preload only where the spring that pushes the
    // tool open would pull it shut: development seed 6404, a press in
    // ODE). Where its search stops at the range's edge (a delay at 0 s),
    // it takes none. Where it alone leaves its range, both at once still
    // split the part they share if its file value has room to move its way.
    // A set is listed once, in whatever order its effects came: a
    // look-alike put in its effect's place reorders a pair the search
    // among every pair had listed already (a press's preload and
    // progressive spring cracked in the first cycle, development seed
    // 9079, ODE: three sets listed as four).
    auto list_once = [&](const std::vector<EffectKind>& set) {
      auto same = [&](const std::vector<EffectKind>& a) { return same_effects(a, set); };
      if (std::none_of(d.ambiguous.begin(), d.ambiguous.end(), same)) d.ambiguous.push_back(set);
    };
    std::vector<Standing> standings;
    for (LookAlike& l : d.look_alikes) {
      std::vector<EffectKind> set = chosen;
      std::replace(set.begin(), set.end(), l.chosen, l.alike);
      Standing& standing = standings.emplace_back(standing_in(l, judge.fitted(set), model, kSeparated));
      // Parallel columns say the two fit alike only up to a share of the
      // effect's own part (a hundredth at the cosine's bound): an effect
      // many times the noise over thousands of samples can leave that
      // share well over it. So the look-alike does not stand in alone
      // where the held-out samples tell it apart: in the chosen effect's
      // place it predicts them worse, sample by sample, and by as much as
      // an effect must cut to earn its place. A tongs' friction and
      // progressive spring in a light squeeze had been given four sets, a
      // preload and a weight in the spring's place leaving 0.113 and 0.117
      // N held out against the pair's 0.106 N, t 5.0 and 5.4 (development
      // seed 7391, MuJoCo). Not by the paired test alone: over 20,000
      // samples it finds a 0.6 % difference.
      if (standing.alone) {
        const Scored& swapped = judge.score(set);
        const double t = paired_t(current_scored.sq, swapped.sq);
        const bool worse = 1 - current_scored.fit.rmse_test / swapped.fit.rmse_test >= kRealMargin;
        if (swapped.fit.valid && worse && t >= kSeparated) {
          standing.alone = false;
          std::snprintf(line, sizeof line, "%s in its place predicts them worse: %.4g N against %.4g N, paired t %.1f",
                        manifest_of(l.alike).name, swapped.fit.rmse_test, current_scored.fit.rmse_test, t);
          l.told_apart = line;
        }
      }
    }
    const bool none_alone = std::none_of(standings.begin(), standings.end(), [](const Standing& s) { return s.alone; });
    for (size_t j = 0; j < d.look_alikes.size(); ++j) {
      const LookAlike& l = d.look_alikes[j];
      const Standing& standing = standings[j];
      std::vector<EffectKind> set = chosen;
      std::replace(set.begin(), set.end(), l.chosen, l.alike);
      const bool both_too = chosen.size() == 1 && (d.look_alikes.size() == 1 || none_alone) && standing.beside;
      d.steps.push_back("  " + look_alike_text(l, both_too));
      if (!standing.alone && !both_too) continue;
      if (d.ambiguous.empty()) d.ambiguous.push_back(chosen);
      if (standing.alone) list_once(set);
      if (both_too) {
        std::vector<EffectKind> with = chosen;
        with.push_back(l.alike);
        list_once(with);
      }
      ambiguous = true;
    }
  }
  // Before naming, too: could a force sensor's gain error (outside the
  // library) explain the gap as well? Judged as a runner-up is judged: it
  // cuts the held-out error where the chosen set acts nearly as far, and
  // the held-out samples there do not tell it from the chosen set. Then
  // nothing the library holds is named.
  bool gain_alike = false;
  if (!chosen.empty()) {
    const bool contact = contact_samples > 0 && std::any_of(chosen.begin(), chosen.end(), [](EffectKind k) {
                           return manifest_of(k).home == EffectHome::actee;
                         });
    const GainAlike gain = gain_alike_of(judge, nominal_scored, current_scored, contact);
    gain_alike = gain.as_good;
    if (gain_alike) {
      d.gain_alike = gain.gain;
      std::snprintf(line, sizeof line,
                    "  the data cannot tell %s from a force sensor reading %+.3g %% (a gain error, outside the library): ",
                    effects_text(chosen).c_str(), 100 * gain.gain);
      d.steps.push_back(line + std::string("weigh a known force at the effort, or drive it where they differ"));
    }
  }
  d.effects = current.effects;
  d.noise_through_model = judge.floor_of(current);
  d.rmse_after = current.rmse_test;
  d.contact_samples = contact_samples;
  d.contact_before = nominal_scored.rmse_contact;
  d.contact_after = current_scored.rmse_contact;
  // The shrink of the part in which the gap is the largest against its noise.
  d.shrink_in_contact = contact_samples > 0 && d.contact_before > d.rmse_before;
  const double was = d.shrink_in_contact ? d.contact_before : d.rmse_before;
  const double now = d.shrink_in_contact ? d.contact_after : d.rmse_after;
  d.shrink = was > 0 ? 1 - now / was : 0.0;

  const std::vector<std::vector<double>> after = judge.weighed_residual(current);
  d.residual = judge.whiteness_of(current_scored);
  d.rig = m.rig;
  d.curves = held_out_curves(replays, fitter, nominal, fold_fitters, judged, chosen);
  what_it_follows(replays, after, &d.residual.follows, &d.residual.correlation);
  // What the turns, left out of every fit, say of an arm's inertia beyond
  // the adopted set's (named below where the fits saw none).
  if (m.rig == Rig::lever) {
    std::vector<std::vector<double>> left_over;  // N*m
    for (size_t i = 0; i < replays.size(); ++i) {
      left_over.push_back(fitter.residual(current, i, true));
      for (double& e : left_over.back()) e /= replays[i].to_newtons;
    }
    d.turns = turn_impulse(replays, left_over);
  }

  const bool slight_shape = leaves_a_slight_shape(current_scored, chosen.size());
  // A residual white on the samples fitted explains too where the
  // held-out ones are predicted beyond the tolerance (a late sensor's
  // delay fitted on fewer samples misses by more), but not for a third
  // effect: one is asked for only where a pair fell short, and white in
  // sample it has chased what the pair left (an inertia added to a spring
  // and a late sensor, 1.29 times the floor held out: development seed
  // 6293, both engines). Nor where the held-out samples over every
  // sample are missed by more than the tolerance again (kMatched
  // squared, 1.32 times the floor): a damping and a late sensor fitted to
  // three blocks of 250 samples, white in sample, left 1.97 times the
  // floor held out where friction had been withheld from the library,
  // and were named (development seed 6291, both engines). The contact is
  // not held to it: an actee's law measured on plates misfits a foreign
  // engine's contact by more than that where the rest is at the floor
  // (report seeds 1,004,730, 1,004,742 and 1,004,956, ODE, were
  // `unexplained` when it was).
  const bool white_explains = d.residual.white && (judge.matched(current_scored) || chosen.size() <= 2) &&
                              current.rmse_test <= kMatched * kMatched * d.noise_through_model;
  // The actee's contact is judged on its own. Within the noise's tolerance
  // there, no law of the actee may take up what it holds (earns_place), so
  // its shape is the measured law's, not the tool's: a law measured on
  // plates misfits a foreign engine's contact by a shade, slow over a
  // squeeze, as it does where nothing else differs (an effect-free
  // nutcracker's light squeeze, 8 % of the contact's variance shaped,
  // development seed 6309, ODE, `none`). The tool's effects are then
  // judged by the residual out of the contact: white there, one or two
  // of them within the tolerance have explained the gap (a damping fitted
  // 0.1 % from the truth, white out of the contact, Q 7.6 times the
  // test's point in it, development seed 6807, ODE, `unexplained` before).
  // Out of the contact there must be samples to judge, as anywhere.
  // So too where the nominal model was within the tolerance and nothing
  // took up its shape, clear and more than slight: white out of the
  // contact, the tool is its nominal self and the shape is the measured
  // law's (an effect-free nutcracker's light squeeze, 5.4 % of the
  // variance shaped, the contact 1.07 times the noise, development seed
  // 7316, MuJoCo, `unexplained` before).
  // With nothing chosen, current_scored is the nominal's.
  const bool nominal_shape_clear = chosen.empty() && !white_under(current_scored) && d.residual.share >= kSlightShape;
  const bool asks_contact = nominal_within ? !nominal_matched && nominal_shape_clear : chosen.size() <= 2;
  bool shape_only_in_contact = false;
  if (contact_samples > 0 && asks_contact && judge.matched(current_scored) && !d.residual.white &&
      current_scored.rmse_contact <= kMatched * d.noise) {
    const std::vector<std::vector<double>> noise = judge.noise_through(current);
    d.out_of_contact = {true, whiteness(replays, after, all, &noise, Samples::out_of_contact)};
    const ResidualTest& t = d.out_of_contact.test;
    shape_only_in_contact = t.samples >= kMinBlock && t.q <= kStructured * t.threshold;
  }

  // Samples the model predicts (free motion, a squeeze) are what anything
  // is judged on: a trace all reversals, rests and unresolved motion
  // matches any model, and says nothing of which.
  size_t judged_samples = 0;
  for (const FoldSize& f : d.fold_sizes) judged_samples += f.fitted;
  // Unexplained, for nothing could be judged: why, and what to measure.
  auto unjudged = [&](const std::string& why, const char* measure) {
    d.verdict = Verdict::unexplained;
    d.steps.push_back("  " + why + "; " + measure);
  };
  const std::string predicted = std::to_string(judged_samples) + " the model predicts";
  if (judged_samples < kMinBlock) {
    unjudged("too few samples to judge anything on: " + predicted + " (at least " + std::to_string(kMinBlock) +
                 "), the rest reversals, rests, limits or motion the samples do not resolve",
             "measure longer, or slower, or more traces");
  } else if (nominal_matched) {
    d.verdict = Verdict::none;
  } else if (chosen.empty() && nominal_within && (!nominal_shape_clear || shape_only_in_contact)) {
    // The nominal model's residual was within the tolerance but over the
    // whiteness test's point, so the library was searched, and nothing in
    // it took the structure up. Judged as any set's residual is judged at
    // the end (no clear shape under kStructured times the point, a slight
    // shape, or a shape in the actee's contact alone), it shows no gap:
    // `none`, not a gap nobody can name
    // (MuJoCo's effect-free nutcrackers at 1.01 and 1.05 times the floor,
    // Q 1.45 times the point, development seeds 3219 and 3225; an
    // effect-free press at 1.0 times the floor, its actee's law misfitting
    // the contact by a shape of 1.7 % of the variance at 2.005 times the
    // point, 3316, both engines). With nothing chosen, d.residual is the
    // nominal's, judged as white_under judges a set's.
    d.verdict = Verdict::none;
    if (d.residual.q <= kStructured * d.residual.threshold) {
      d.steps.push_back("  nothing cuts it, and the nominal's residual is within the noise's tolerance with no clear "
                        "shape (under twice the whiteness test's point): no gap shown");
    } else if (d.residual.share < kSlightShape) {
      std::snprintf(line, sizeof line,
                    "  nothing cuts it, and the nominal's residual is within the noise's tolerance, keeping a slight "
                    "shape: %.1f %% of its variance (under %.0f %%): no gap shown",
                    100 * d.residual.share, 100 * kSlightShape);
      d.steps.push_back(line);
    } else {
      std::snprintf(line, sizeof line,
                    "  nothing cuts it, and the nominal's residual is within the noise's tolerance, its shape in the "
                    "actee's contact, %.3g times the sensor's noise there; out of the contact Q = %.1f, under twice "
                    "the point %.1f: no gap shown",
                    d.contact_after / d.noise, d.out_of_contact.test.q, d.out_of_contact.test.threshold);
      d.steps.push_back(line);
    }
  } else if (d.folds < 2) {
    // One block: every fit would be judged on the samples it was fitted
    // to, which no set can fail. Nothing is fitted, and the report says so
    // (not a bare shrink of 0).
    unjudged("one block of " + predicted + ": no fit can be judged on samples it was not fitted to (two blocks of " +
                 std::to_string(kMinBlock) + " at least)",
             "measure longer, or more traces");
  } else if (chosen.empty() || gain_alike) {
    d.verdict = Verdict::unexplained;
    // Where only the gain stood in the way, what is unexplained is which
    // of the two, not a gap left.
    d.gain_alike_explains =
        gain_alike && (effects_match(current_scored) || white_explains || slight_shape || shape_only_in_contact);
  } else if (effects_match(current_scored) || white_explains) {
    d.verdict = ambiguous ? Verdict::ambiguous : Verdict::explained;
  } else if (slight_shape) {
    d.verdict = ambiguous ? Verdict::ambiguous : Verdict::explained;
    std::snprintf(line, sizeof line,
                  "  the residual keeps a slight shape: %.1f %% of its variance (under %.0f %%), %.3g times the floor",
                  100 * d.residual.share, 100 * kSlightShape, d.rmse_after / d.noise_through_model);
    d.steps.push_back(line);
  } else if (shape_only_in_contact) {
    d.verdict = ambiguous ? Verdict::ambiguous : Verdict::explained;
    std::snprintf(line, sizeof line,
                  "  the residual's shape lies in the actee's contact, %.3g times the sensor's noise there (no law of "
                  "the actee is asked to explain it); out of the contact Q = %.1f, under twice the point %.1f",
                  d.contact_after / d.noise, d.out_of_contact.test.q, d.out_of_contact.test.threshold);
    d.steps.push_back(line);
  } else {
    d.verdict = Verdict::unexplained;
  }

  // An inertia the turns ask for where the strokes between them run at an
  // even speed: no fit sees it (the acceleration between the turns, read
  // through the angle's noise, is all noise, and its coefficient is
  // pulled to nothing: 0.00023 +- 0.00011 kg*m^2 fitted there, 0.0019
  // from the turns, the truth 0.002, development seed 7488, ODE, which
  // read `none`; 7628, an inertia and a preload read as the preload).
  const bool inertia_asked = std::find(library.begin(), library.end(), EffectKind::arm_inertia) != library.end();
  const bool inertia_chosen = std::find(chosen.begin(), chosen.end(), EffectKind::arm_inertia) != chosen.end();
  const bool turns_ask = inertia_asked && !inertia_chosen && d.turns.inertia > kTurnsAsk * d.turns.sigma &&
                         halves_agree(d.turns) && d.turns.force > d.noise;
  std::vector<PhaseShare> folded_phases;  // where the gap lies after, with the turns' inertia in the model
  if (turns_ask) {
    EffectFit from_turns;
    from_turns.kind = EffectKind::arm_inertia;
    from_turns.value[0] = nominal_value(model, EffectKind::arm_inertia) + d.turns.inertia;
    from_turns.sigma[0] = d.turns.sigma;
    char turns_text[384];
    std::snprintf(turns_text, sizeof turns_text,
                  "  the turns ask for an arm inertia of %+.3g +- %.2g kg*m^2 beyond the model's, %.1f standard errors "
                  "(over %.0f), slowing into them and speeding out alike, %.3g N at the effort across them (over the "
                  "noise), and the fits between them named none",
                  d.turns.inertia, d.turns.sigma, d.turns.inertia / d.turns.sigma, kTurnsAsk, d.turns.force);
    const std::string turns_line = turns_text;
    if (d.verdict != Verdict::unexplained) {
      // Named beside what the fits explained.
      d.effects.push_back(from_turns);
      d.turns.adopted = true;
      if (d.verdict == Verdict::none) d.verdict = Verdict::explained;
      d.steps.push_back(turns_line + ": named");
    } else if (library.size() > 1) {
      // Where the fits left a gap, the turns' inertia may be what left
      // it: the fits between the turns cannot take it up, yet the
      // samples at their edges carry it (an inertia of 0.0019 kg*m^2 the
      // turns asked for at 27 standard errors, the fitted one cutting
      // 4.9 % where 5 is needed, the nominal's residual within the
      // tolerance but shaped, development seed 7343, ODE). The
      // measurement is judged again with it in the model and the rest of
      // the library; named only if that explains the gap. A detent's or
      // a backlash's turns ask for an inertia too (6 of 335 development
      // cases without one, ODE), and with it in the model the residual
      // still says something else is at work: judged so, no case outside
      // the library was named on development seeds (ODE 7300-7699, 70 of
      // 71 `unexplained` before and after).
      DiagnoseOptions rest;
      for (EffectKind k : library) {
        if (k != EffectKind::arm_inertia) rest.library.push_back(k);
      }
      Diagnosis folded = diagnose(with_effects(m, {from_turns}), rest);
      if (folded.verdict != Verdict::unexplained) {
        d.steps.push_back(turns_line + ", and the fits left a gap; judged again with it in the model:");
        for (const std::string& s : folded.steps) d.steps.push_back("  " + s);
        // What the second judgement found after; what was before stays
        // the file's nominal.
        d.verdict = folded.verdict == Verdict::none ? Verdict::explained : folded.verdict;
        d.effects = folded.effects;
        d.effects.push_back(from_turns);
        d.turns.adopted = true;
        d.ambiguous = folded.ambiguous;
        d.look_alikes = folded.look_alikes;
        d.gain_alike = folded.gain_alike;
        d.gain_alike_explains = folded.gain_alike_explains;
        d.noise_through_model = folded.noise_through_model;
        d.rmse_after = folded.rmse_after;
        d.contact_after = folded.contact_after;
        d.shrink = was > 0 ? 1 - (d.shrink_in_contact ? d.contact_after : d.rmse_after) / was : 0.0;
        d.residual = folded.residual;
        d.out_of_contact = folded.out_of_contact;
        for (HeldOutCurve& c : folded.curves) {
          for (const HeldOutCurve& own : d.curves) {
            if (own.file == c.file && own.nominal.size() == c.nominal.size()) c.nominal = own.nominal;
          }
        }
        d.curves = folded.curves;
        folded_phases = folded.phases;
      }
    }
  }

  // Unexplained over several traces: would each trace, fitted alone, be?
  if (d.verdict == Verdict::unexplained && m.traces.size() > 1 && !library.empty()) {
    auto floor_of = [&judge](const SetFit& f) { return judge.floor_of(f); };
    d.per_trace = per_trace_fits(model, whole, library, fitter, floor_of, d.noise);
    // Each alone wants a power law: is its shape shared, with each
    // specimen's stiffness its own?
    if (d.per_trace.computed && d.per_trace.effect == EffectKind::actee_compliance) {
      d.specimens = specimen_shape(Fitter(model, whole, every, {}), whole);
    }
  }

  // By force: what the effort makes of the angle and the actee, nominal
  // and with the effects adopted.
  if (m.rig == Rig::lever) {
    d.by_force_before = replay_force(model, m);
    d.by_force_after = d.effects.empty() ? d.by_force_before : replay_force(compile_with(m, d.effects), m);
  }

  // Where: each phase's share of the squared residual; after, as the
  // second judgement with the turns' inertia found it where there was one.
  d.phases = phase_shares(replays, before, after);
  for (PhaseShare& ps : d.phases) {
    for (const PhaseShare& f : folded_phases) {
      if (f.phase == ps.phase) ps.after = f.after;
    }
  }
  std::string follows;
  double corr = 0;
  what_it_follows(replays, before, &follows, &corr);
  if (!d.phases.empty()) {
    std::snprintf(line, sizeof line, "%.0f %% of the gap lies in %s; it follows %s most (correlation %.2f)",
                  100 * d.phases.front().before, phase_name(d.phases.front().phase), follows.c_str(), corr);
    d.where = line;
  }
  return d;
}

}  // namespace afford
