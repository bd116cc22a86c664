// The pair an emulated cycle runs on: two image files, or a rendered world scene.

#include "emulation/cycle_pair.hpp"

#include "cli/command.hpp"

#include "marsokhod/world/scene/rendered_site.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

CyclePair files_pair(const PairChoice& cli) {
  CyclePair pair;
  pair.left = read_grey(cli.pair[0]);
  imaging::Image<std::uint8_t> right = read_grey(cli.pair[1]);
  if (pair.left.width() != right.width() || pair.left.height() != right.height())
    throw CommandError(fmt::format("{} is {}x{} but {} is {}x{}; a stereo pair has one size",
                                   cli.pair[0].string(), pair.left.width(), pair.left.height(),
                                   cli.pair[1].string(), right.width(), right.height()));
  pair.rig = std::make_unique<imaging::StereoRig>(
      rig_for(cli.given.rig_file, cli.pair[0], pair.left.width(), pair.left.height()));
  pair.right = aligned_right(cli.given.calibration_file, std::move(right));
  pair.attitude = pair_attitude(cli.given);
  pair.description = cli.pair[0].string();
  return pair;
}

CyclePair rendered_pair(const PairChoice& cli, bool quiet) {
  if (cli.given.rig_file || cli.given.scene_file || cli.given.calibration_file)
    throw UsageError("--rig, --scene and --calibration describe a given pair: name LEFT and RIGHT, "
                     "or leave them out to emulate a rendered scene");
  const std::uint64_t seed = cli.seed.value_or(1);
  world::SceneDescription scene = world::default_scene(seed, cli.size.value_or(128));
  if (!quiet)
    fmt::print(stderr, "rendering world seed {} at {}x{}...\n", seed, scene.rig.width_px,
               scene.rig.height_px);
  world::RenderedFrame frame = world::render_site(scene);
  CyclePair pair{
      std::move(frame.images.left), std::move(frame.images.right),
      std::make_unique<imaging::StereoRig>(scene.rig), scene.placement.attitude,
      fmt::format("world seed {} at {}x{}", seed, scene.rig.width_px, scene.rig.height_px)};
  return pair;
}

} // namespace

CyclePair cycle_pair(const PairChoice& cli, bool quiet) {
  if (cli.pair.empty())
    return rendered_pair(cli, quiet);
  if (cli.pair.size() != 2)
    throw UsageError("give both LEFT and RIGHT, or neither to emulate a rendered scene");
  if (cli.seed || cli.size)
    throw UsageError(
        "--seed and --size choose a rendered scene; they do not apply to a given pair");
  return files_pair(cli);
}

} // namespace marsokhod::apps
