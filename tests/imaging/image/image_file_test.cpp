// Tests: image files are read only as far as their header says the image needs.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace marsokhod::imaging {
namespace {

using testing::Bytes;
using testing::bytes_of;
using testing::expect_image_error;
using testing::TemporaryFolder;

constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;
constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

// Bytes this process has read through read(2) so far (Linux /proc/self/io, "rchar").
std::uint64_t bytes_read_so_far() {
  std::ifstream io("/proc/self/io");
  std::string key;
  std::uint64_t value = 0;
  while (io >> key >> value)
    if (key == "rchar:")
      return value;
  return 0;
}

// `bytes`, then a hole up to `padded_size` bytes: a sparse file that costs no disk space.
void write_padded(const std::filesystem::path& path, const Bytes& bytes,
                  std::uint64_t padded_size) {
  testing::write_bytes(path, bytes);
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(padded_size)), 0);
}

// The issue's example: a 1x1 PGM followed by 3 GB of padding used to be read (and held) whole.
TEST(ImageFile, APgmFollowedByGigabytesOfPaddingIsReadWithoutThePadding) {
  TemporaryFolder folder;
  const auto path = folder / "padded.pgm";
  write_padded(path, bytes_of("P5 1 1 255\n", {42}), 3 * kGiB);
  const std::uint64_t before = bytes_read_so_far();
  const Image<std::uint8_t> image = read_gray8(path);
  EXPECT_LT(bytes_read_so_far() - before, kMiB);
  EXPECT_EQ(image.width(), 1);
  EXPECT_EQ(image(0, 0), 42);
}

// The general rule, for every format: what follows the image is neither read nor refused.
TEST(ImageFile, NoFormatReadsBeyondItsImage) {
  TemporaryFolder folder;
  Image<std::uint8_t> grey(3, 2, 1);
  Image<std::uint16_t> rgb(2, 2, 3);
  Image<float> field(2, 3, 1);
  for (std::size_t i = 0; i < grey.size(); ++i)
    grey.data()[i] = static_cast<std::uint8_t>(10 * i);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb.data()[i] = static_cast<std::uint16_t>(1000 * i);
  for (std::size_t i = 0; i < field.size(); ++i)
    field.data()[i] = 0.5F * static_cast<float>(i);
  write_image(folder / "grey.pgm", grey.view());
  write_image(folder / "rgb.ppm", rgb.view());
  write_image(folder / "grey.png", grey.view());
  write_image(folder / "field.pfm", field.view());
  for (const char* name : {"grey.pgm", "rgb.ppm", "grey.png", "field.pfm"}) {
    const auto path = folder / name;
    ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(kGiB)), 0) << name;
    const std::uint64_t before = bytes_read_so_far();
    const AnyImage image = read_image(path);
    EXPECT_LT(bytes_read_so_far() - before, kMiB) << name;
    if (const auto* bytes = std::get_if<Image<std::uint8_t>>(&image))
      EXPECT_TRUE(*bytes == grey) << name;
    else if (const auto* words = std::get_if<Image<std::uint16_t>>(&image))
      EXPECT_TRUE(*words == rgb) << name;
    else
      EXPECT_TRUE(std::get<Image<float>>(image) == field) << name;
  }
}

// A header that goes on past the first 64 KiB (here a long comment) is refused as such, not
// read further and not mistaken for a truncated file.
TEST(ImageFile, AHeaderLongerThan64KiBIsRefused) {
  TemporaryFolder folder;
  const auto path = folder / "chatty.pgm";
  testing::write_bytes(path, bytes_of("P5 1 1 #" + std::string(70000, 'x') + "\n 255\n", {1}));
  expect_image_error([&] { (void)read_image(path); }, path.string(),
                     {"header (comments included) runs past the first 65536 bytes"});
  // The same comment in memory, where nothing is cut, is a valid header.
  const Bytes bytes = bytes_of("P5 1 1 #" + std::string(70000, 'x') + "\n 255\n", {1});
  EXPECT_NO_THROW((void)decode_image(bytes, "memory"));
  // A header that ends inside the window still reads: 65000 bytes of comment.
  const auto fits = folder / "fits.pgm";
  testing::write_bytes(fits, bytes_of("P5 1 1 #" + std::string(65000, 'x') + "\n 255\n", {7}));
  EXPECT_EQ(read_gray8(fits)(0, 0), 7);
}

// A raster shorter than the header promises is still reported with both figures.
TEST(ImageFile, ARasterShorterThanTheHeaderSaysIsTruncated) {
  TemporaryFolder folder;
  const auto path = folder / "short.pfm";
  testing::write_bytes(path, bytes_of("Pf 2 1 -1\n", {0, 0, 0, 0, 0}));
  expect_image_error([&] { (void)read_image(path); }, path.string(),
                     {"truncated pixel data", "expected 8 bytes", "found 5"});
}

// Devices and FIFOs are refused at once instead of being read (or waited on) without end.
TEST(ImageFile, ADeviceOrAFifoIsRefusedWithoutBlocking) {
  TemporaryFolder folder;
  expect_image_error([] { (void)read_image("/dev/zero"); }, "/dev/zero", {"not a regular file"});
  const auto fifo = folder / "fifo.pgm";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_image_error([&] { (void)read_image(fifo); }, fifo.string(), {"not a regular file"});
}

std::uint32_t png_crc(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffU;
  for (const char c : bytes) {
    crc ^= static_cast<std::uint8_t>(c);
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
  }
  return ~crc;
}

std::string big_endian(std::uint32_t value) {
  std::string text;
  for (int shift = 24; shift >= 0; shift -= 8)
    text.push_back(static_cast<char>((value >> shift) & 0xffU));
  return text;
}

// PNG is streamed; what libpng is fed is bounded by the image in the header: a 1x1 grey PNG
// needs 2 raw bytes, so 2 * (2 + 1) + 16 MiB may be read. A 32 MiB ancillary chunk (a hole in
// a sparse file) goes past that and is refused before it is read whole.
TEST(ImageFile, APngFeedsLibpngNoMoreThanItsImageCanNeed) {
  TemporaryFolder folder;
  const auto path = folder / "bloated.png";
  const std::string ihdr_body = std::string("IHDR") + big_endian(1) + big_endian(1) +
                                std::string{'\x08', '\x00', '\x00', '\x00', '\x00'};
  std::string head = "\x89PNG\r\n\x1a\n";
  head += big_endian(13) + ihdr_body + big_endian(png_crc(ihdr_body));
  head += big_endian(static_cast<std::uint32_t>(32 * kMiB)) + "zzZz";
  testing::write_bytes(path, Bytes(head.begin(), head.end()));
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(head.size() + 33 * kMiB)), 0);
  const std::uint64_t before = bytes_read_so_far();
  expect_image_error([&] { (void)read_image(path); }, path.string(),
                     {"corrupt PNG", "more data than the image in its header can need"});
  EXPECT_LT(bytes_read_so_far() - before, 17 * kMiB);
}

} // namespace
} // namespace marsokhod::imaging
