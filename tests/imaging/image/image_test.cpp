// Tests: Image<T> and ImageView<T> layout, sub-views, limits and memory resources.

#include "marsokhod/imaging/image/image.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory_resource>
#include <new>
#include <stdexcept>
#include <type_traits>

namespace marsokhod::imaging {
namespace {

// A 4x3 RGB image whose sample at (x, y, c) is 100*y + 10*x + c: every value tells its place.
Image<int> numbered_image() {
  Image<int> image(4, 3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c)
        image(x, y, c) = 100 * y + 10 * x + c;
  return image;
}

TEST(Image, StoresInterleavedRowsWithoutPadding) {
  const Image<int> image = numbered_image();
  EXPECT_EQ(image.size(), 4U * 3U * 3U);
  // Row 1 starts after 4 pixels x 3 channels of row 0; pixel (2, 1) channel 1 is at 12 + 7.
  EXPECT_EQ(image.data()[12 + 2 * 3 + 1], 121);
  EXPECT_EQ(image.row(2)[3 * 3 + 2], 232);
}

TEST(Image, RejectsSidesAndChannelsOutsideTheLimits) {
  EXPECT_THROW(Image<std::uint8_t>(kMaxImageSide + 1, 1), std::invalid_argument);
  EXPECT_THROW(Image<std::uint8_t>(1, -1), std::invalid_argument);
  EXPECT_THROW(Image<std::uint8_t>(1, 1, 0), std::invalid_argument);
  EXPECT_THROW(Image<std::uint8_t>(1, 1, 5), std::invalid_argument);
  EXPECT_NO_THROW(Image<std::uint8_t>(kMaxImageSide, 1));
}

TEST(ImageView, SubViewAddressesTheSameSamplesWithTheParentStride) {
  Image<int> image = numbered_image();
  const ImageView<int> window = image.view().sub(1, 1, 2, 2);
  EXPECT_EQ(window.width(), 2);
  EXPECT_EQ(window.height(), 2);
  EXPECT_EQ(window.channels(), 3);
  EXPECT_EQ(window.stride(), 4 * 3);
  EXPECT_EQ(window(0, 0, 0), 110);
  EXPECT_EQ(window(1, 1, 2), 222);
  window(1, 0, 1) = -7; // writes through to the image
  EXPECT_EQ(image(2, 1, 1), -7);
}

TEST(ImageView, SubViewOfASubViewComposesOffsets) {
  Image<int> image = numbered_image();
  const ImageView<int> inner = image.view().sub(1, 0, 3, 3).sub(1, 1, 2, 2);
  EXPECT_EQ(inner(0, 0, 0), 120);
  EXPECT_EQ(inner(1, 1, 0), 230);
}

TEST(ImageView, SubViewOutsideTheImageThrows) {
  Image<int> image = numbered_image();
  EXPECT_THROW((void)image.view().sub(3, 0, 2, 1), std::out_of_range);
  EXPECT_THROW((void)image.view().sub(0, 2, 1, 2), std::out_of_range);
  EXPECT_THROW((void)image.view().sub(-1, 0, 1, 1), std::out_of_range);
  EXPECT_THROW((void)image.view().sub(0, 0, -1, 1), std::out_of_range);
  EXPECT_THROW((void)image.view().sub(1, 0, 2147483647, 1), std::out_of_range);
  EXPECT_NO_THROW((void)image.view().sub(4, 3, 0, 0));
}

TEST(ImageView, ExternalBufferWithRowPaddingIsAddressedByStride) {
  // Two 3-sample rows stored 5 apart: the two padding samples must never be visited.
  std::array<std::uint8_t, 10> buffer = {1, 2, 3, 99, 99, 4, 5, 6, 99, 99};
  const ImageView<std::uint8_t> view(buffer.data(), 3, 2, 1, 5);
  EXPECT_EQ(view(2, 0), 3);
  EXPECT_EQ(view(0, 1), 4);
  const Image<std::uint8_t> copy = to_image(ImageView<const std::uint8_t>(view));
  const Image<std::uint8_t> expected = [] {
    Image<std::uint8_t> image(3, 2);
    const std::uint8_t values[] = {1, 2, 3, 4, 5, 6};
    std::copy(std::begin(values), std::end(values), image.data());
    return image;
  }();
  EXPECT_EQ(copy, expected);
}

TEST(ImageView, MutableViewConvertsToConstButNotBack) {
  static_assert(std::is_convertible_v<ImageView<int>, ImageView<const int>>);
  static_assert(!std::is_convertible_v<ImageView<const int>, ImageView<int>>);
  static_assert(std::is_convertible_v<Image<int>&, ImageView<const int>>);
  static_assert(std::is_convertible_v<const Image<int>&, ImageView<const int>>);
  static_assert(!std::is_convertible_v<const Image<int>&, ImageView<int>>);
  static_assert(!std::is_convertible_v<ImageView<int>, ImageView<const float>>);

  Image<int> image = numbered_image();
  const ImageView<const int> read_only = image.view();
  EXPECT_EQ(read_only.data(), image.data());
  EXPECT_EQ(read_only(3, 2, 1), 231);
  EXPECT_EQ(read_only.stride(), image.view().stride());
}

TEST(Image, PixelsComeFromTheCallersMemoryResource) {
  alignas(std::max_align_t) std::array<std::byte, 4096> arena{};
  // No upstream: anything the arena cannot serve fails instead of silently using the heap.
  std::pmr::monotonic_buffer_resource resource(arena.data(), arena.size(),
                                               std::pmr::null_memory_resource());
  Image<std::uint16_t> image(32, 16, 1, std::uint16_t{7}, &resource);
  const auto* first = reinterpret_cast<const std::byte*>(image.data());
  EXPECT_GE(first, arena.data());
  EXPECT_LE(first + image.size() * sizeof(std::uint16_t), arena.data() + arena.size());
  EXPECT_EQ(image.get_allocator().resource(), &resource);
  EXPECT_EQ(image(31, 15), 7);
  // 32*16*2 = 1 KiB taken; 4 KiB more cannot come from the 4 KiB arena.
  EXPECT_THROW(Image<std::uint8_t>(64, 64, 1, 0, &resource), std::bad_alloc);
}

TEST(Image, ToImageCopiesIntoTheGivenResource) {
  alignas(std::max_align_t) std::array<std::byte, 1024> arena{};
  std::pmr::monotonic_buffer_resource resource(arena.data(), arena.size(),
                                               std::pmr::null_memory_resource());
  const Image<int> source = numbered_image();
  const Image<int> copy = to_image(source.view().sub(1, 1, 3, 2), &resource);
  EXPECT_EQ(copy.get_allocator().resource(), &resource);
  EXPECT_EQ(copy(0, 0, 0), 110);
  EXPECT_EQ(copy(2, 1, 2), 232);
}

TEST(Image, EqualityComparesShapeAndPixels) {
  Image<std::uint8_t> a(2, 3, 1, 5);
  Image<std::uint8_t> b(3, 2, 1, 5); // same samples, other shape
  EXPECT_FALSE(a == b);
  Image<std::uint8_t> c(2, 3, 1, 5);
  EXPECT_TRUE(a == c);
  c(1, 2) = 6;
  EXPECT_FALSE(a == c);
}

} // namespace
} // namespace marsokhod::imaging
