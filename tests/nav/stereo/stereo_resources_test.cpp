// Tests: the stereo matcher's work metering, memory resources and input refusals.
// What the matcher reports and takes: the work counted by a meter follows the work done, every
// buffer comes from the caller's memory resource, and bad input is refused clearly.
#include "nav/stereo_test_support.hpp"

#include "marsokhod/nav/stereo/stereo.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <memory_resource>
#include <new>
#include <span>
#include <stdexcept>
#include <string>

// Counts the global allocations, to show that the matcher makes none of its own.
namespace {
std::atomic<long> global_allocations{0};
} // namespace

void* operator new(std::size_t size) {
  global_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace marsokhod::nav {
namespace {

using testing::DotPair;
using testing::DotScene;
using testing::make_dot_pair;

// A meter behind the virtual interface, as the emulator will plug in.
class RecordingMeter final : public DynamicMeter {
public:
  void operator()(Work kind, std::uint64_t count) override { counts(kind, count); }
  CountingMeter counts;
};

TEST(StereoWork, AWiderBandReportsTheExtraCandidatesItEvaluates) {
  // A plane at 8 px, two layers: every window the coarse layer guides widens by (5 - 1)
  // candidates on each side, for each of the 256 x 96 pixels of the fine layer, except where
  // a window would pass the image's left edge (x - d >= 0): a few of the first columns.
  DotScene scene;
  scene.width = 256;
  scene.background = 8;
  scene.square_size = 0;
  const DotPair pair = make_dot_pair(scene);
  StereoOptions options = testing::dot_scene_options();
  options.pyramid_levels = 2;
  options.search_band = 1;
  CountingMeter narrow;
  match_stereo(pair.left.view(), pair.right.view(), options, narrow);
  options.search_band = 5;
  CountingMeter wide;
  match_stereo(pair.left.view(), pair.right.view(), options, wide);
  const double guided_pixels = 256.0 * 96.0;
  const double extra = static_cast<double>(wide.count(Work::match_candidate)) -
                       static_cast<double>(narrow.count(Work::match_candidate));
  EXPECT_GT(extra, 0.95 * 8.0 * guided_pixels);
  EXPECT_LE(extra, 8.0 * guided_pixels);
  // The matcher's other per-candidate work follows: two passes of the programme, a choice for
  // the left view and, on the layers that are checked, another for the right view over the
  // candidates that reach a right pixel.
  EXPECT_EQ(wide.count(Work::dp_transition), 2 * wide.count(Work::match_candidate));
  EXPECT_GT(wide.count(Work::disparity_choice), wide.count(Work::match_candidate));
  EXPECT_LE(wide.count(Work::disparity_choice), 2 * wide.count(Work::match_candidate));
  EXPECT_GT(wide.count(Work::disparity_choice) - narrow.count(Work::disparity_choice),
            static_cast<std::uint64_t>(extra));
}

TEST(StereoWork, TheDynamicMeterSeesWhatTheCountingMeterSees) {
  const DotPair pair = make_dot_pair(DotScene{});
  CountingMeter counting;
  match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options(), counting);
  RecordingMeter recording;
  DynamicMeter& dynamic = recording;
  match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options(), dynamic);
  for (std::size_t kind = 0; kind < kWorkKinds; ++kind)
    EXPECT_EQ(recording.counts.count(static_cast<Work>(kind)),
              counting.count(static_cast<Work>(kind)))
        << to_string(static_cast<Work>(kind));
  // Every pixel of both images is transformed once per layer (three layers here).
  EXPECT_EQ(counting.count(Work::feature_pixel), 2U * (128 * 96 + 64 * 48 + 32 * 24));
}

TEST(StereoMemory, EveryBufferComesFromTheCallersResource) {
  const DotPair pair = make_dot_pair(DotScene{});
  auto arena = std::make_unique<std::byte[]>(std::size_t{16} << 20);
  std::pmr::monotonic_buffer_resource memory(arena.get(), std::size_t{16} << 20,
                                             std::pmr::null_memory_resource());
  const long before = global_allocations.load();
  const StereoResult result = match_stereo(pair.left.view(), pair.right.view(),
                                           testing::dot_scene_options(), null_meter, &memory);
  EXPECT_EQ(global_allocations.load() - before, 0);
  EXPECT_GT(result.valid_pixels, 0U);
  EXPECT_EQ(result.disparity.get_allocator().resource(), &memory);
}

TEST(StereoMemory, TooLittleMemoryThrowsBadAlloc) {
  const DotPair pair = make_dot_pair(DotScene{});
  auto arena = std::make_unique<std::byte[]>(20000);
  std::pmr::monotonic_buffer_resource memory(arena.get(), 20000, std::pmr::null_memory_resource());
  EXPECT_THROW(match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options(),
                            null_meter, &memory),
               std::bad_alloc);
}

// Expects std::invalid_argument whose message contains `fragment`.
template <class Action>
void expect_refused(Action action, const std::string& fragment) {
  try {
    action();
    ADD_FAILURE() << "expected std::invalid_argument mentioning \"" << fragment << "\"";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(StereoInput, ImagesOfDifferentSizesAreRefused) {
  const imaging::Image<std::uint8_t> left = testing::random_dots(64, 48, 1);
  const imaging::Image<std::uint8_t> right = testing::random_dots(64, 40, 2);
  expect_refused([&] { match_stereo(left.view(), right.view(), testing::dot_scene_options()); },
                 "64x40");
}

TEST(StereoInput, ImagesTooSmallForThePyramidAreRefused) {
  const imaging::Image<std::uint8_t> image = testing::random_dots(30, 30, 3);
  StereoOptions options = testing::dot_scene_options();
  options.max_disparity = 8;
  options.pyramid_levels = 3;
  expect_refused([&] { match_stereo(image.view(), image.view(), options); }, "too small");
  options.pyramid_levels = 1;
  options.max_disparity = 30;
  expect_refused([&] { match_stereo(image.view(), image.view(), options); }, "does not fit");
}

TEST(StereoInput, BadOptionsAndColourImagesAreRefused) {
  const imaging::Image<std::uint8_t> image = testing::random_dots(64, 48, 4);
  StereoOptions options = testing::dot_scene_options();
  options.min_disparity = -1;
  expect_refused([&] { match_stereo(image.view(), image.view(), options); }, "min_disparity");
  options = testing::dot_scene_options();
  options.penalties.large_step = 300;
  expect_refused([&] { match_stereo(image.view(), image.view(), options); }, "penalties");
  const imaging::Image<std::uint8_t> colour(64, 48, 3);
  expect_refused([&] { match_stereo(colour.view(), colour.view(), testing::dot_scene_options()); },
                 "grey");
}

TEST(StereoInput, UnseenColumnsMustGiveOneCountPerRow) {
  const imaging::Image<std::uint8_t> image = testing::random_dots(64, 48, 6);
  StereoOptions options = testing::dot_scene_options();
  // Arrays, not vectors: this file replaces the global allocation functions.
  const std::array<std::int16_t, 48> counts{};
  options.unseen_columns = std::span<const std::int16_t>(counts).first(47);
  expect_refused([&] { match_stereo(image.view(), image.view(), options); }, "unseen_columns");
  options.unseen_columns = counts;
  EXPECT_GT(match_stereo(image.view(), image.view(), options).valid_pixels, 0U);
}

TEST(StereoInput, UniformImagesGiveNoValidPixelAndSayWhy) {
  const imaging::Image<std::uint8_t> dots = testing::random_dots(64, 48, 5);
  for (std::uint8_t grey : {std::uint8_t{0}, std::uint8_t{255}}) {
    const imaging::Image<std::uint8_t> uniform(64, 48, 1, grey);
    for (const auto& [left, right] : {std::pair{&uniform, &dots}, std::pair{&dots, &uniform}}) {
      const StereoResult result =
          match_stereo(left->view(), right->view(), testing::dot_scene_options());
      EXPECT_EQ(result.valid_pixels, 0U);
      EXPECT_NE(result.reason.find("uniform"), std::string::npos) << result.reason;
      EXPECT_TRUE(std::isinf(result.disparity(10, 10)));
      EXPECT_EQ(result.disparity.width(), 64);
    }
  }
}

} // namespace
} // namespace marsokhod::nav
