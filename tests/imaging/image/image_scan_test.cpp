// Scanning image files strip by strip: the same pixels and errors as reading them whole.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/image_scan.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace marsokhod::imaging {
namespace {

using testing::bytes_of;
using testing::expect_image_error;
using testing::TemporaryFolder;

template <class T>
Image<T> patterned(int width, int height, int channels, unsigned modulus) {
  Image<T> image(width, height, channels);
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<T>((i * 7919U + i / 13U) % modulus);
  return image;
}

/// The image put together from the strips of a scan, with each strip's rows checked against
/// the strip limit and every row visited exactly once.
template <class T>
struct Reassembled {
  Image<T> image;
  ImageFileHeader header;
  int strips = 0;
};

template <class T>
Reassembled<T> reassemble(const std::filesystem::path& path, int width, int height, int channels) {
  Reassembled<T> result{Image<T>(width, height, channels), {}, 0};
  std::vector<int> visits(static_cast<std::size_t>(height), 0);
  result.header = scan_image(path, [&](int first_row, const ImageStrip& strip) {
    const auto& view = std::get<ImageView<const T>>(strip);
    const std::size_t row_bytes = static_cast<std::size_t>(width) * channels * sizeof(T);
    EXPECT_LE(static_cast<std::size_t>(view.height()) * row_bytes,
              std::max(kScanStripBytes, row_bytes));
    ++result.strips;
    for (int y = 0; y < view.height(); ++y) {
      ++visits[static_cast<std::size_t>(first_row + y)];
      std::copy(view.row(y), view.row(y) + static_cast<std::size_t>(width) * channels,
                result.image.row(first_row + y));
    }
  });
  for (int y = 0; y < height; ++y)
    EXPECT_EQ(visits[static_cast<std::size_t>(y)], 1) << "row " << y;
  return result;
}

template <class T>
void expect_same_pixels(const Image<T>& a, const Image<T>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(std::equal(a.data(), a.data() + a.size(), b.data()));
}

TEST(ImageScan, AnEightBitPgmComesInStripsThatMakeUpReadImagesPixels) {
  TemporaryFolder folder;
  const auto path = folder / "big.pgm";
  const Image<std::uint8_t> image = patterned<std::uint8_t>(4096, 2048, 1, 256);
  write_image(path, image);
  const Reassembled<std::uint8_t> scan = reassemble<std::uint8_t>(path, 4096, 2048, 1);
  EXPECT_EQ(scan.strips, 2); // 8 MiB of pixels in strips of 4 MiB
  EXPECT_EQ(scan.header.format, "pgm");
  EXPECT_EQ(scan.header.maxval, 255);
  expect_same_pixels(scan.image, std::get<Image<std::uint8_t>>(read_image(path)));
}

TEST(ImageScan, ASixteenBitPpmKeepsItsSamplesAndChannels) {
  TemporaryFolder folder;
  const auto path = folder / "big.ppm";
  const Image<std::uint16_t> image = patterned<std::uint16_t>(1000, 1500, 3, 65536);
  write_image(path, image);
  const Reassembled<std::uint16_t> scan = reassemble<std::uint16_t>(path, 1000, 1500, 3);
  EXPECT_EQ(scan.strips, 3); // 699 rows of 6000 bytes fit in 4 MiB
  EXPECT_EQ(scan.header.channels, 3);
  EXPECT_EQ(scan.header.maxval, 65535);
  expect_same_pixels(scan.image, image);
}

TEST(ImageScan, APfmComesBottomUpAndMakesUpTheSameImage) {
  TemporaryFolder folder;
  const auto path = folder / "big.pfm";
  Image<float> image(1024, 2100, 1);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      image(x, y) = static_cast<float>(y) + 0.001F * static_cast<float>(x);
  write_image(path, image);
  std::vector<int> firsts;
  (void)scan_image(path, [&](int first_row, const ImageStrip&) { firsts.push_back(first_row); });
  EXPECT_EQ(firsts, (std::vector<int>{2100 - 1024, 2100 - 2048, 0}));
  const Reassembled<float> scan = reassemble<float>(path, 1024, 2100, 1);
  EXPECT_EQ(scan.header.format, "pfm");
  expect_same_pixels(scan.image, image);
}

TEST(ImageScan, APngIsOneStrip) {
  TemporaryFolder folder;
  const auto path = folder / "small.png";
  const Image<std::uint8_t> image = patterned<std::uint8_t>(33, 17, 3, 256);
  write_image(path, image);
  const Reassembled<std::uint8_t> scan = reassemble<std::uint8_t>(path, 33, 17, 3);
  EXPECT_EQ(scan.strips, 1);
  EXPECT_EQ(scan.header.format, "png");
  expect_same_pixels(scan.image, image);
}

// Errors found in a later strip read exactly as read_image words them.
TEST(ImageScan, RefusesWhatReadImageRefusesWithTheSameMessage) {
  TemporaryFolder folder;
  const auto ignore = [](int, const ImageStrip&) {};
  const auto cut = folder / "cut.pgm";
  testing::Bytes bytes = bytes_of("P5 4096 2048 255\n");
  bytes.resize(bytes.size() + 4096U * 2048U - 5U, 0);
  testing::write_bytes(cut, bytes);
  const std::string scanned = expect_image_error([&] { (void)scan_image(cut, ignore); },
                                                 cut.string(), {"truncated pixel data"});
  const std::string read = expect_image_error([&] { (void)read_image(cut); }, cut.string(), {});
  EXPECT_EQ(scanned, read);

  const auto over = folder / "over.pgm";
  testing::Bytes high = bytes_of("P5 4096 2048 200\n");
  high.resize(high.size() + 4096U * 2048U, 0);
  high.back() = 201;
  testing::write_bytes(over, high);
  const std::string scanned_over =
      expect_image_error([&] { (void)scan_image(over, ignore); }, over.string(),
                         {"sample value 201 exceeds maxval 200 at pixel (4095, 2047)"});
  EXPECT_EQ(scanned_over, expect_image_error([&] { (void)read_image(over); }, over.string(), {}));

  const auto text = folder / "text.pgm";
  testing::write_bytes(text, bytes_of("hello"));
  EXPECT_EQ(expect_image_error([&] { (void)scan_image(text, ignore); }, text.string(), {}),
            expect_image_error([&] { (void)read_image(text); }, text.string(), {}));
}

} // namespace
} // namespace marsokhod::imaging
