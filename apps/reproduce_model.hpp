// The paper's timings as predictions of the model: the scenes, the fit of its one constant,
// the three figures, the sensitivity to the parameters the paper does not give, the sweep.
#pragma once

#include "emulate_sweep.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/occam_port/navigation/placement.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// The paper's figures (Kolesnik 1995, Conclusions), seconds.
inline constexpr double kPaperStereoSeconds = 8.0;
inline constexpr double kPaperCardCycleSeconds = 10.0;
inline constexpr double kPaperOnboardCycleSeconds = 78.0; // "1.3 min"

/// One rendered world scene at the paper's 128x128.
struct ReproductionScene {
  std::uint64_t seed = 0;
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  std::unique_ptr<imaging::StereoRig> rig;
  imaging::Attitude attitude;
};

/// A figure of the model over the scenes: their mean, least and greatest, seconds.
struct SceneSpread {
  double mean = 0.0;
  double least = 0.0;
  double greatest = 0.0;
};

/// The model's three figures for one choice of platforms and occam style.
struct ModelFigures {
  SceneSpread stereo;        ///< the card: cycle start to the seeable disparity handed on
  SceneSpread card_cycle;    ///< the card: the whole cycle
  SceneSpread onboard_cycle; ///< the onboard modules: the whole cycle
};

/// The shipped PC card and onboard platforms with their placements, and the scenes.
class TimingModel {
public:
  explicit TimingModel(const std::vector<std::uint64_t>& seeds);

  const emulator::PlatformSpec& card() const { return card_; }
  const emulator::PlatformSpec& onboard() const { return onboard_; }
  std::size_t scenes() const { return scenes_.size(); }

  /// The card's stereo figure alone (what the fit needs).
  SceneSpread stereo(const emulator::PlatformSpec& card, double occam_style) const;
  ModelFigures figures(const emulator::PlatformSpec& card, const emulator::PlatformSpec& onboard,
                       double occam_style) const;
  /// The onboard cycle at each external memory size: the mean over the scenes, or the first
  /// scene's memory fault if any scene cannot run.
  std::vector<SweepPoint> onboard_sweep(const std::vector<std::uint64_t>& external_kb,
                                        double occam_style,
                                        const std::function<void(std::size_t)>& progress) const;

private:
  std::vector<ReproductionScene> scenes_;
  emulator::PlatformSpec card_;
  emulator::PlatformSpec onboard_;
  occam_port::Placement card_placement_;
  occam_port::Placement onboard_placement_;
};

/// The occam style factor that makes the card's stereo take `paper_seconds`, to 3 decimals
/// (secant steps: the figure is affine in the factor but for the links' share).
double fit_occam_style(const TimingModel& model, double paper_seconds);

/// One row of the sensitivity table: a parameter the paper does not give, at one value.
struct SensitivityRow {
  std::string parameter;
  std::string value;
  bool shipped = false; ///< the value the platforms ship with
  ModelFigures figures;
};

/// The three figures as each unsourced-by-the-paper parameter moves over its period range,
/// the others as shipped and the fitted constant held; `shipped` is the model's figures as
/// shipped at that constant, given to every shipped value's row rather than run again.
std::vector<SensitivityRow> sensitivity(const TimingModel& model, double occam_style,
                                        const ModelFigures& shipped);

} // namespace marsokhod::apps
