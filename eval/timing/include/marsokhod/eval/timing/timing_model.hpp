// TimingModel: the paper's timings as predictions of the model, over rendered world scenes on
// the shipped PC card and onboard platforms.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/timing/memory_sweep.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace marsokhod::eval {

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
  /// Renders world `seeds` at 128x128; TimingError without seeds.
  explicit TimingModel(const std::vector<std::uint64_t>& seeds);

  const emulator::PlatformSpec& card() const { return card_; }
  const emulator::PlatformSpec& onboard() const { return onboard_; }
  std::size_t scenes() const { return scenes_.size(); }

  /// The card's stereo figure alone (what the fit needs). TimingError when a scene does not
  /// fit the card.
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
  nav_program::Placement card_placement_;
  nav_program::Placement onboard_placement_;
};

/// The stereo reconstruction's end: the last end of a stage of the stereo group (refine handing
/// the seeable disparity on to range), seconds from the cycle's start.
double stereo_end(const nav_program::CycleEmulation& run);

/// The occam style factor that makes the card's stereo take `paper_seconds`, to 3 decimals
/// (secant steps: the figure is affine in the factor but for the links' share).
double fit_occam_style(const TimingModel& model, double paper_seconds);

} // namespace marsokhod::eval
