// The pair an emulated cycle runs on: two image files with their rig, or a rendered scene.
#pragma once

#include "navigation/pair_inputs.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// What the command line chose: LEFT and RIGHT with their rig, attitude and calibration, or
/// neither and a world seed and size to render.
struct PairChoice {
  std::vector<std::filesystem::path> pair;
  std::optional<std::uint64_t> seed;
  std::optional<int> size;
  PairOptions given;
};

/// The cycle's pair, rig and attitude, from files or rendered.
struct CyclePair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  std::unique_ptr<imaging::StereoRig> rig;
  imaging::Attitude attitude;
  std::string description; ///< "world seed 1 at 128x128" or the left image's path
};

/// The pair `choice` names (world seed 1 at 128x128 by default); UsageError for options that
/// do not go together, CommandError for files that cannot be read. Says on stderr what it
/// renders unless `quiet`.
CyclePair cycle_pair(const PairChoice& choice, bool quiet);

} // namespace marsokhod::apps
