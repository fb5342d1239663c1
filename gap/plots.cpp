#include "plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "files.h"
#include "png.h"

namespace afford {
namespace {

constexpr render::Rgb kMeasured{110, 110, 118}, kNominal{52, 101, 164}, kFitted{230, 120, 10};

render::Rgb phase_colour(Phase p) {
  static constexpr render::Rgb kColours[kPhases] = {
      {226, 238, 250}, {232, 246, 232}, {253, 230, 214}, {246, 232, 246},
      {236, 232, 250}, {240, 240, 240}, {250, 246, 214}, {250, 222, 222}};
  return kColours[static_cast<int>(p)];
}

std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::string title(const Diagnosis& d, const std::string& what) {
  return d.measurement + ": " + what + " (verdict " + verdict_name(d.verdict) + ")";
}

bool has_fit(const Diagnosis& d) { return !d.effects.empty(); }

}  // namespace

render::Chart residual_chart(const Diagnosis& d) {
  render::Chart ch;
  ch.title = title(d, "residual, measured - predicted, on held-out traces");
  ch.x_label = d.curves.size() > 1 ? "time [s], the judged traces one after another" : "time [s]";
  ch.y_label = d.rig == Rig::lever ? "effort force residual [N]" : "force residual [N]";
  ch.zero_line = true;
  render::ChartCurve before{"nominal model", kNominal, 1.5, {}, {}};
  render::ChartCurve after{"fitted, held out", kFitted, 1.5, {}, {}};
  std::vector<bool> phase_seen(kPhases, false);
  double offset = 0;
  for (const HeldOutCurve& c : d.curves) {
    if (c.t.empty()) continue;
    const double start = offset - c.t.front();
    if (d.curves.size() > 1) ch.markers.push_back({offset, base_name(c.file)});
    // Bands: each run of one phase, from its first sample to the next run's.
    size_t run = 0;
    for (size_t s = 1; s <= c.t.size(); ++s) {
      if (s < c.t.size() && c.phase[s] == c.phase[run]) continue;
      const double end = s < c.t.size() ? c.t[s] : c.t.back();
      ch.bands.push_back({start + c.t[run], start + end, phase_colour(c.phase[run])});
      phase_seen[static_cast<size_t>(c.phase[run])] = true;
      run = s;
    }
    for (size_t s = 0; s < c.t.size(); ++s) {
      before.x.push_back(start + c.t[s]);
      before.y.push_back(c.measured[s] - c.nominal[s]);
      after.x.push_back(start + c.t[s]);
      after.y.push_back(c.measured[s] - c.fitted[s]);
    }
    // A break between traces, so that no line joins them.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    before.x.push_back(nan), before.y.push_back(nan), after.x.push_back(nan), after.y.push_back(nan);
    offset = start + c.t.back() + 0.04 * (c.t.back() - c.t.front());
  }
  ch.curves.push_back(std::move(before));
  if (has_fit(d)) ch.curves.push_back(std::move(after));
  for (int p = 0; p < kPhases; ++p) {
    if (phase_seen[static_cast<size_t>(p)]) ch.band_legend.push_back({phase_name(static_cast<Phase>(p)), phase_colour(static_cast<Phase>(p))});
  }
  return ch;
}

render::Chart loop_chart(const Diagnosis& d) {
  const bool lever = d.rig == Rig::lever;
  render::Chart ch;
  ch.title = title(d, lever ? "effort force against angle" : "force against displacement");
  ch.x_label = lever ? "lever angle [deg]" : "plate displacement [mm]";
  ch.y_label = lever ? "effort force [N]" : "force [N]";
  const double scale = lever ? 180 / std::numbers::pi : 1000;
  for (const HeldOutCurve& c : d.curves) {
    render::ChartCurve measured{"measured", kMeasured, 1.5, {}, {}};
    render::ChartCurve nominal{"nominal model", kNominal, 1.5, {}, {}};
    render::ChartCurve fitted{"fitted, held out", kFitted, 1.5, {}, {}};
    for (size_t s = 0; s < c.t.size(); ++s) {
      const double x = c.x[s] * scale;
      measured.x.push_back(x), measured.y.push_back(c.measured[s]);
      nominal.x.push_back(x), nominal.y.push_back(c.nominal[s]);
      fitted.x.push_back(x), fitted.y.push_back(c.fitted[s]);
    }
    ch.curves.push_back(std::move(measured));
    ch.curves.push_back(std::move(nominal));
    if (has_fit(d)) ch.curves.push_back(std::move(fitted));
  }
  return ch;
}

std::vector<std::string> write_gap_plots(const Diagnosis& d, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir + ": " + ec.message());
  std::vector<std::string> written;
  for (const auto& [name, chart] : {std::pair{"residual", residual_chart(d)}, std::pair{"loop", loop_chart(d)}}) {
    const std::string stem = (std::filesystem::path(dir) / name).string();
    write_file_checked(stem + ".svg", render::chart_svg(chart));
    written.push_back(stem + ".svg");
    render::write_png(stem + ".png", render::chart_png(chart));
    written.push_back(stem + ".png");
  }
  return written;
}

}  // namespace afford
