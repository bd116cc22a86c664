// Tests: the PNG codec's decoding and refusals, on files assembled chunk by chunk.
// PNG decoding against files assembled here chunk by chunk with zlib (PNG specification,
// ISO/IEC 15948), so the expected pixels do not depend on any PNG writer.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <string>
#include <zlib.h>

namespace marsokhod::imaging {
namespace {

using testing::Bytes;
using testing::expect_decode_error;

constexpr int kGrey = 0, kRgb = 2, kPalette = 3, kGreyAlpha = 4, kRgba = 6;

void put_u32(Bytes& bytes, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    bytes.push_back(static_cast<std::uint8_t>((value >> shift) & 0xff));
}

void put_chunk(Bytes& png, std::string_view type, const Bytes& data) {
  put_u32(png, static_cast<std::uint32_t>(data.size()));
  Bytes typed(type.begin(), type.end());
  typed.insert(typed.end(), data.begin(), data.end());
  png.insert(png.end(), typed.begin(), typed.end());
  put_u32(png, static_cast<std::uint32_t>(crc32(0, typed.data(), static_cast<uInt>(typed.size()))));
}

struct PngSpec {
  std::uint32_t width = 1;
  std::uint32_t height = 1;
  int bit_depth = 8;
  int colour_type = kGrey;
  int interlace = 0;
  Bytes scanlines = {}; // filter byte 0 + raw samples, per row (or per pass row when interlaced)
  Bytes palette = {};
  Bytes transparency = {};
};

Bytes make_png(const PngSpec& spec) {
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes header;
  put_u32(header, spec.width);
  put_u32(header, spec.height);
  header.insert(header.end(), {static_cast<std::uint8_t>(spec.bit_depth),
                               static_cast<std::uint8_t>(spec.colour_type), 0, 0,
                               static_cast<std::uint8_t>(spec.interlace)});
  put_chunk(png, "IHDR", header);
  if (!spec.palette.empty())
    put_chunk(png, "PLTE", spec.palette);
  if (!spec.transparency.empty())
    put_chunk(png, "tRNS", spec.transparency);
  uLongf packed_size = compressBound(static_cast<uLong>(spec.scanlines.size()));
  Bytes packed(packed_size);
  EXPECT_EQ(compress2(packed.data(), &packed_size, spec.scanlines.data(),
                      static_cast<uLong>(spec.scanlines.size()), 9),
            Z_OK);
  packed.resize(packed_size);
  put_chunk(png, "IDAT", packed);
  put_chunk(png, "IEND", {});
  return png;
}

template <class T>
const Image<T>& as(const AnyImage& image) {
  EXPECT_TRUE(std::holds_alternative<Image<T>>(image));
  return std::get<Image<T>>(image);
}

TEST(PngDecode, Grey8) {
  const AnyImage decoded = decode_image(
      make_png({.width = 3, .height = 2, .scanlines = {0, 1, 2, 3, 0, 250, 251, 252}}), "g.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.width(), 3);
  ASSERT_EQ(image.height(), 2);
  ASSERT_EQ(image.channels(), 1);
  EXPECT_EQ(image(2, 0), 3);
  EXPECT_EQ(image(0, 1), 250);
}

TEST(PngDecode, Grey16IsBigEndianInTheFile) {
  const AnyImage decoded = decode_image(
      make_png({.width = 2, .bit_depth = 16, .scanlines = {0, 0x12, 0x34, 0xff, 0x01}}), "g16.png");
  const auto& image = as<std::uint16_t>(decoded);
  EXPECT_EQ(image(0, 0), 0x1234);
  EXPECT_EQ(image(1, 0), 0xff01);
}

TEST(PngDecode, OneBitGreyExpandsToFullRange) {
  // 1011 packed into the high bits of one byte; 1-bit white is 255 in 8 bits.
  const AnyImage decoded =
      decode_image(make_png({.width = 4, .bit_depth = 1, .scanlines = {0, 0b1011'0000}}), "b.png");
  const auto& image = as<std::uint8_t>(decoded);
  EXPECT_EQ(image(0, 0), 255);
  EXPECT_EQ(image(1, 0), 0);
  EXPECT_EQ(image(2, 0), 255);
  EXPECT_EQ(image(3, 0), 255);
}

TEST(PngDecode, FourBitGreyScalesBy17) {
  const AnyImage decoded =
      decode_image(make_png({.width = 2, .bit_depth = 4, .scanlines = {0, 0x3f}}), "n.png");
  EXPECT_EQ(as<std::uint8_t>(decoded)(0, 0), 3 * 17);
  EXPECT_EQ(as<std::uint8_t>(decoded)(1, 0), 15 * 17);
}

TEST(PngDecode, GreyAlphaDropsAlpha) {
  const AnyImage decoded = decode_image(
      make_png({.width = 2, .colour_type = kGreyAlpha, .scanlines = {0, 40, 255, 80, 0}}),
      "ga.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 1);
  EXPECT_EQ(image(0, 0), 40);
  EXPECT_EQ(image(1, 0), 80);
}

TEST(PngDecode, Rgb8) {
  const AnyImage decoded = decode_image(
      make_png({.width = 2, .colour_type = kRgb, .scanlines = {0, 1, 2, 3, 4, 5, 6}}), "rgb.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 3);
  EXPECT_EQ(image(0, 0, 2), 3);
  EXPECT_EQ(image(1, 0, 0), 4);
}

TEST(PngDecode, Rgba16DropsAlphaAndKeepsSixteenBits) {
  const AnyImage decoded =
      decode_image(make_png({.bit_depth = 16,
                             .colour_type = kRgba,
                             .scanlines = {0, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0xff, 0xff}}),
                   "rgba.png");
  const auto& image = as<std::uint16_t>(decoded);
  ASSERT_EQ(image.channels(), 3);
  EXPECT_EQ(image(0, 0, 0), 0x0102);
  EXPECT_EQ(image(0, 0, 2), 0x0506);
}

TEST(PngDecode, PaletteExpandsToRgb) {
  const AnyImage decoded = decode_image(make_png({.width = 3,
                                                  .colour_type = kPalette,
                                                  .scanlines = {0, 1, 0, 1},
                                                  .palette = {10, 20, 30, 200, 210, 220}}),
                                        "pal.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 3);
  EXPECT_EQ(image(0, 0, 0), 200);
  EXPECT_EQ(image(1, 0, 1), 20);
  EXPECT_EQ(image(2, 0, 2), 220);
}

TEST(PngDecode, PaletteWithTransparencyStillGivesRgb) {
  const AnyImage decoded = decode_image(make_png({.width = 2,
                                                  .bit_depth = 2,
                                                  .colour_type = kPalette,
                                                  .scanlines = {0, 0b0100'0000},
                                                  .palette = {1, 2, 3, 4, 5, 6},
                                                  .transparency = {0, 128}}),
                                        "tp.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 3);
  // Two 2-bit indices packed high bits first: 01 then 00.
  EXPECT_EQ(image(0, 0, 0), 4);
  EXPECT_EQ(image(1, 0, 2), 3);
}

TEST(PngDecode, GreyWithTransparentColourStaysGrey) {
  const AnyImage decoded = decode_image(
      make_png({.width = 2, .scanlines = {0, 7, 9}, .transparency = {0, 7}}), "tg.png");
  const auto& image = as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 1);
  EXPECT_EQ(image(0, 0), 7);
  EXPECT_EQ(image(1, 0), 9);
}

TEST(PngDecode, Adam7InterlacedPassesAreReassembled) {
  // 3x3 grey, pixel (x, y) = 10*y + x + 1. Adam7 passes that are not empty for 3x3:
  // 1: (0,0); 4: (2,0); 5: (0,2) (2,2); 6: (1,0) and (1,2) on two rows; 7: row 1.
  const Bytes passes = {0, 1, 0, 3, 0, 21, 23, 0, 2, 0, 22, 0, 11, 12, 13};
  const AnyImage decoded = decode_image(
      make_png({.width = 3, .height = 3, .interlace = 1, .scanlines = passes}), "i.png");
  const auto& image = as<std::uint8_t>(decoded);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_EQ(image(x, y), 10 * y + x + 1) << x << "," << y;
}

TEST(PngMalformed, Truncated) {
  Bytes png = make_png({.width = 8, .height = 8, .scanlines = Bytes(8 * 9, 0)});
  png.resize(png.size() / 2);
  expect_decode_error(png, "half.png", {"corrupt PNG", "truncated"});
  png.resize(20); // inside IHDR
  expect_decode_error(png, "head.png", {"corrupt PNG", "truncated"});
  expect_decode_error(Bytes{0x89, 'P', 'N', 'G'}, "sig.png", {"corrupt PNG"});
}

TEST(PngMalformed, MissingEndChunkIsTruncation) {
  Bytes png = make_png({.width = 2, .scanlines = {0, 1, 2}});
  png.resize(png.size() - 12); // IEND is 12 bytes
  expect_decode_error(png, "noend.png", {"corrupt PNG", "truncated"});
}

TEST(PngMalformed, CorruptCrc) {
  Bytes png = make_png({.width = 2, .scanlines = {0, 1, 2}});
  png[8 + 8 + 13 + 3] ^= 0x01; // last byte of the IHDR CRC
  expect_decode_error(png, "crc.png", {"corrupt PNG", "CRC"});
}

TEST(PngMalformed, CorruptImageData) {
  Bytes png = make_png({.width = 2, .scanlines = {0, 1, 2}});
  // Find IDAT and break its zlib header, then fix the chunk CRC so that only zlib complains.
  const std::string_view text(reinterpret_cast<const char*>(png.data()), png.size());
  const std::size_t idat = text.find("IDAT");
  ASSERT_NE(idat, std::string_view::npos);
  std::uint32_t length = 0;
  for (std::size_t i = idat - 4; i < idat; ++i)
    length = (length << 8) | png[i];
  png[idat + 4] = 0xff;
  const auto crc = static_cast<std::uint32_t>(crc32(0, png.data() + idat, 4 + length));
  for (int i = 0; i < 4; ++i)
    png[idat + 4 + length + static_cast<std::size_t>(i)] =
        static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  expect_decode_error(png, "zlib.png", {"corrupt PNG"});
}

TEST(PngMalformed, BadSignature) {
  Bytes png = make_png({.width = 2, .scanlines = {0, 1, 2}});
  png[5] = 'x';
  expect_decode_error(png, "sig.png", {"corrupt PNG"});
}

TEST(PngMalformed, WidthOverTheLimitWithValidCrc) {
  expect_decode_error(make_png({.width = 16385, .scanlines = {0}}), "wide.png",
                      {"width 16385 is out of range 1..16384"});
}

TEST(PngMalformed, WidthZeroWithValidCrc) {
  expect_decode_error(make_png({.width = 0, .scanlines = {0}}), "zero.png",
                      {"corrupt PNG", "width"});
}

TEST(PngMalformed, HugeHeaderIsRejectedBeforeAllocatingPixels) {
  // A valid 16384 x 16384 RGB header over one row of data: 768 MiB promised by ~100 bytes.
  testing::LargestRequestResource resource;
  expect_decode_error(
      make_png({.width = 16384, .height = 16384, .colour_type = kRgb, .scanlines = {0, 0, 0, 0}}),
      "huge.png", {"corrupt PNG", "cannot hold 16384x16384 pixels"});
  EXPECT_LT(resource.largest(), 4096U);
}

} // namespace
} // namespace marsokhod::imaging
