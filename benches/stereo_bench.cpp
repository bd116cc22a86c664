// Benchmark: stereo reconstruction speed against OpenCV and the navigation budget.
// Stereo reconstruction speed. Targets (docs/navigation.md): tsukuba at least 3x faster than
// OpenCV StereoSGBM measured in the same run (one thread), and a 256 x 256 rover pair fast
// enough for the whole navigation chain to fit in 5 ms. The NullMeter figures must equal the
// figures of a build with metering compiled out (-DMARSOKHOD_NAV_UNMETERED); the CountingMeter
// and DynamicMeter figures show what metering costs when it is on.
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <benchmark/benchmark.h>

#ifdef MARSOKHOD_HAVE_OPENCV
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#endif

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <memory_resource>
#include <optional>
#include <string>
#include <type_traits>

namespace {

using namespace marsokhod;

struct Pair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  int max_disparity = 0;
};

// Tsukuba, searched up to its largest ground-truth disparity (14 px), as `eval stereo` does.
const std::optional<Pair>& tsukuba() {
  static const std::optional<Pair> pair = []() -> std::optional<Pair> {
    const std::filesystem::path dir = std::filesystem::path(MARSOKHOD_SHARED_DATA) / "stereo";
    if (!std::filesystem::exists(dir / "tsukuba_left.pgm"))
      return std::nullopt;
    return Pair{imaging::read_gray8(dir / "tsukuba_left.pgm"),
                imaging::read_gray8(dir / "tsukuba_right.pgm"), 14};
  }();
  return pair;
}

// A 256 x 256 pair of the synthetic world (default terrain, high sun, paper rig), searched up
// to the rig's ground disparity at the bottom row plus a margin for rocks.
const Pair& rover_pair() {
  static const Pair pair = [] {
    world::TerrainSettings settings;
    settings.size_m = 32.0;
    const world::Terrain terrain = world::Terrain::generate(settings);
    const world::LitSurface surface(terrain, world::lighting_preset(world::LightPreset::high_sun));
    const world::Renderer renderer(terrain);
    const imaging::StereoRig rig{imaging::RigParameters{}};
    const world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
    world::StereoImages images = renderer.render(rig, placement, surface);
    const double bottom = rig.ground_disparity(rig.cx(), rig.height() - 1);
    return Pair{std::move(images.left), std::move(images.right),
                static_cast<int>(std::ceil(bottom)) + 8};
  }();
  return pair;
}

nav::StereoOptions options_for(const Pair& pair, bool ground_prior,
                               nav::FeatureKind feature = nav::StereoOptions{}.feature) {
  nav::StereoOptions options;
  options.feature = feature;
  options.max_disparity = pair.max_disparity;
  options.ground_prior = ground_prior;
  return options;
}

// A meter behind a virtual call that counts, as the emulator's would.
class VirtualCountingMeter final : public nav::DynamicMeter {
public:
  void operator()(nav::Work kind, std::uint64_t count) override { counts_(kind, count); }
  std::uint64_t total() const { return counts_.total(); }

private:
  nav::CountingMeter counts_;
};

// match_stereo is instantiated for DynamicMeter, not for each class derived from it.
template <class Meter>
auto& instantiated(Meter& meter) {
  if constexpr (std::is_base_of_v<nav::DynamicMeter, Meter>)
    return static_cast<nav::DynamicMeter&>(meter);
  else
    return meter;
}

// Memory from the caller (contract 2), as an emulated node would give it: one arena, reused by
// every run, so the figures measure matching rather than the host's page faults.
class Arena {
public:
  Arena() : bytes_(std::make_unique<std::byte[]>(kBytes)) {}
  std::pmr::monotonic_buffer_resource fresh() const {
    return std::pmr::monotonic_buffer_resource(bytes_.get(), kBytes,
                                               std::pmr::null_memory_resource());
  }

private:
  static constexpr std::size_t kBytes = std::size_t{64} << 20;
  std::unique_ptr<std::byte[]> bytes_;
};

template <class Meter>
void run_stereo(benchmark::State& state, const Pair& pair, bool ground_prior,
                nav::FeatureKind feature = nav::StereoOptions{}.feature) {
  const nav::StereoOptions options = options_for(pair, ground_prior, feature);
  Meter meter;
  const Arena arena;
  for (auto _ : state) {
    std::pmr::monotonic_buffer_resource memory = arena.fresh();
    nav::StereoResult result = nav::match_stereo(pair.left.view(), pair.right.view(), options,
                                                 instantiated(meter), &memory);
    benchmark::DoNotOptimize(result.disparity.data());
  }
  state.counters["pixels"] = static_cast<double>(pair.left.width() * pair.left.height());
  if constexpr (!std::is_same_v<Meter, nav::NullMeter>)
    state.counters["work_per_run"] =
        static_cast<double>(meter.total()) / static_cast<double>(state.iterations());
}

template <class Meter>
void BM_MarsokhodStereo_tsukuba(benchmark::State& state) {
  if (!tsukuba()) {
    state.SkipWithError("the tsukuba pair is missing from MARSOKHOD_SHARED_DATA/stereo");
    return;
  }
  run_stereo<Meter>(state, *tsukuba(), false);
}
BENCHMARK(BM_MarsokhodStereo_tsukuba<nav::NullMeter>)
    ->Name("BM_MarsokhodStereo_tsukuba")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MarsokhodStereo_tsukuba<nav::CountingMeter>)
    ->Name("BM_MarsokhodStereo_tsukuba_CountingMeter")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MarsokhodStereo_tsukuba<VirtualCountingMeter>)
    ->Name("BM_MarsokhodStereo_tsukuba_DynamicMeter")
    ->Unit(benchmark::kMillisecond);

template <class Meter>
void BM_MarsokhodStereo_rover256(benchmark::State& state) {
  run_stereo<Meter>(state, rover_pair(), true);
}
BENCHMARK(BM_MarsokhodStereo_rover256<nav::NullMeter>)
    ->Name("BM_MarsokhodStereo_rover256")
    ->Unit(benchmark::kMillisecond);
// The feature with the best accuracy, for the speed it costs (docs/navigation.md).
void BM_MarsokhodStereo_rover256_census5x5(benchmark::State& state) {
  run_stereo<nav::NullMeter>(state, rover_pair(), true, nav::FeatureKind::census5x5);
}
BENCHMARK(BM_MarsokhodStereo_rover256_census5x5)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_MarsokhodStereo_rover256<nav::CountingMeter>)
    ->Name("BM_MarsokhodStereo_rover256_CountingMeter")
    ->Unit(benchmark::kMillisecond);

#ifdef MARSOKHOD_HAVE_OPENCV

cv::Mat as_mat(const imaging::Image<std::uint8_t>& image) {
  return cv::Mat(image.height(), image.width(), CV_8UC1, const_cast<std::uint8_t*>(image.data()));
}

// OpenCV needs a multiple of 16 disparities: 14 rounds up to 16.
int opencv_disparities(int max_disparity) {
  return (max_disparity + 16) / 16 * 16;
}

void BM_OpenCvStereoSGBM_tsukuba(benchmark::State& state) {
  if (!tsukuba()) {
    state.SkipWithError("the tsukuba pair is missing from MARSOKHOD_SHARED_DATA/stereo");
    return;
  }
  cv::setNumThreads(1);
  const Pair& pair = *tsukuba();
  // The peer settings of the data README: block 5, P1 200, P2 800, uniqueness 5, no speckle.
  cv::Ptr<cv::StereoSGBM> sgbm =
      cv::StereoSGBM::create(0, opencv_disparities(pair.max_disparity), 5, 200, 800, 0, 0, 5, 0, 0,
                             cv::StereoSGBM::MODE_SGBM);
  cv::Mat disparity;
  for (auto _ : state) {
    sgbm->compute(as_mat(pair.left), as_mat(pair.right), disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}
BENCHMARK(BM_OpenCvStereoSGBM_tsukuba)->Unit(benchmark::kMillisecond);

void BM_OpenCvStereoBM_tsukuba(benchmark::State& state) {
  if (!tsukuba()) {
    state.SkipWithError("the tsukuba pair is missing from MARSOKHOD_SHARED_DATA/stereo");
    return;
  }
  cv::setNumThreads(1);
  const Pair& pair = *tsukuba();
  cv::Ptr<cv::StereoBM> bm = cv::StereoBM::create(opencv_disparities(pair.max_disparity), 9);
  cv::Mat disparity;
  for (auto _ : state) {
    bm->compute(as_mat(pair.left), as_mat(pair.right), disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}
BENCHMARK(BM_OpenCvStereoBM_tsukuba)->Unit(benchmark::kMillisecond);

#else

void BM_OpenCvStereoSGBM_tsukuba(benchmark::State& state) {
  state.SkipWithError("OpenCV was not found at configure time: no peer to compare with");
}
BENCHMARK(BM_OpenCvStereoSGBM_tsukuba);

#endif

} // namespace
