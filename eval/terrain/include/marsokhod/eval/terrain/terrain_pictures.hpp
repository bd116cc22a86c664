// The three-panel comparison picture of one site: left image, judged zones, ground-truth zones.
#pragma once

#include "marsokhod/eval/terrain/footprint_judge.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/render/ground_truth.hpp"

#include <cstdint>
#include <optional>

namespace marsokhod::eval {

/// What `eval terrain --pictures` draws of one site: the left image, the navigation's zones
/// judged against ground truth, and the ground-truth zones, side by side (docs/navigation.md,
/// "Synthetic terrain" gives the colours).
struct TerrainComparison {
  const imaging::Image<std::uint8_t>& left;
  const nav::ZoneMap& zones;
  const nav::PathPlan& plan;
  const nav::ZoneMap& truth_zones;
  const nav::PathPlan& truth_plan;
  const world::GroundTruth& truth;
  const imaging::StereoRig& rig;
  imaging::Attitude attitude;
  /// Where the footprint judge found the drive over an obstacle, when it did.
  const std::optional<FootprintHit>& unsafe_hit;
};

/// An RGB picture three panels wide. The middle panel colours each pixel both cameras see by
/// the verdict: free ground left open black, falsely prohibited as unknown blue, as a step or
/// slope orange, as margin yellow; obstacles prohibited white and missed red; pixels inside
/// the truth's margin (not scored) dark grey, or mid grey when prohibited. The navigation's
/// path is drawn green on the first two panels, the ground-truth path cyan on the third. When
/// the footprint judge found the drive unsafe, the first two panels show the footprint where
/// it first covered an obstacle (magenta outline) and that obstacle (a red cross).
imaging::Image<std::uint8_t> terrain_comparison_picture(const TerrainComparison& site);

} // namespace marsokhod::eval
