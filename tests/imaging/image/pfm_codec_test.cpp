// PFM decoding (Middlebury convention) against byte sequences written by hand.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace marsokhod::imaging {
namespace {

using testing::append;
using testing::Bytes;
using testing::bytes_of;
using testing::expect_decode_error;

// IEEE 754 single precision bit patterns, written out rather than computed.
constexpr std::uint32_t kOne = 0x3f800000;       // 1.0
constexpr std::uint32_t kTwo = 0x40000000;       // 2.0
constexpr std::uint32_t kMinusHalf = 0xbf000000; // -0.5
constexpr std::uint32_t kTen = 0x41200000;       // 10.0
constexpr std::uint32_t kPlusInf = 0x7f800000;
constexpr std::uint32_t kMinusInf = 0xff800000;
constexpr std::uint32_t kNanWithPayload = 0x7fc00123;

void put_float(Bytes& bytes, std::uint32_t bits, bool little_endian) {
  for (int i = 0; i < 4; ++i) {
    const int shift = little_endian ? 8 * i : 24 - 8 * i;
    bytes.push_back(static_cast<std::uint8_t>((bits >> shift) & 0xff));
  }
}

Bytes pfm(std::string_view header, std::initializer_list<std::uint32_t> samples,
          bool little_endian) {
  Bytes bytes = bytes_of(header);
  for (std::uint32_t bits : samples)
    put_float(bytes, bits, little_endian);
  return bytes;
}

const Image<float>& floats(const AnyImage& image) {
  EXPECT_TRUE(std::holds_alternative<Image<float>>(image));
  return std::get<Image<float>>(image);
}

TEST(PfmDecode, NegativeScaleMeansLittleEndianAndRowsRunBottomToTop) {
  // File order: bottom row (1, 2), then top row (-0.5, 10).
  const AnyImage decoded =
      decode_image(pfm("Pf\n2 2\n-1.0\n", {kOne, kTwo, kMinusHalf, kTen}, true), "d.pfm");
  const auto& image = floats(decoded);
  ASSERT_EQ(image.channels(), 1);
  EXPECT_EQ(image(0, 0), -0.5F);
  EXPECT_EQ(image(1, 0), 10.0F);
  EXPECT_EQ(image(0, 1), 1.0F);
  EXPECT_EQ(image(1, 1), 2.0F);
}

TEST(PfmDecode, PositiveScaleMeansBigEndian) {
  const AnyImage decoded = decode_image(pfm("Pf\n2 1\n1.0\n", {kTen, kMinusHalf}, false), "b.pfm");
  EXPECT_EQ(floats(decoded)(0, 0), 10.0F);
  EXPECT_EQ(floats(decoded)(1, 0), -0.5F);
  const AnyImage plus = decode_image(pfm("Pf 1 1 +2.5\n", {kTwo}, false), "p.pfm");
  EXPECT_EQ(floats(plus)(0, 0), 2.0F);
}

TEST(PfmDecode, ScaleMagnitudeDoesNotScaleValues) {
  const AnyImage decoded = decode_image(pfm("Pf\n1 1\n-0.0625\n", {kTen}, true), "s.pfm");
  EXPECT_EQ(floats(decoded)(0, 0), 10.0F);
}

TEST(PfmDecode, ThreeChannelPfmIsInterleavedRgb) {
  const AnyImage decoded = decode_image(
      pfm("PF\n1 2\n-1\n", {kOne, kTwo, kTen, kMinusHalf, kMinusHalf, kOne}, true), "rgb.pfm");
  const auto& image = floats(decoded);
  ASSERT_EQ(image.channels(), 3);
  EXPECT_EQ(image(0, 1, 2), 10.0F); // first in the file = bottom row
  EXPECT_EQ(image(0, 0, 0), -0.5F);
  EXPECT_EQ(image(0, 0, 2), 1.0F);
}

TEST(PfmDecode, InfinitiesAndNanArePreservedBitForBit) {
  const AnyImage decoded =
      decode_image(pfm("Pf 3 1 -1\n", {kPlusInf, kMinusInf, kNanWithPayload}, true), "inf.pfm");
  const auto& image = floats(decoded);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(image(0, 0)), kPlusInf);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(image(1, 0)), kMinusInf);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(image(2, 0)), kNanWithPayload);
}

TEST(PfmMalformed, ScaleZero) {
  expect_decode_error(pfm("Pf 1 1 0.0\n", {kOne}, true), "zero.pfm", {"scale 0", "byte order"});
  expect_decode_error(pfm("Pf 1 1 -0\n", {kOne}, true), "zero.pfm", {"scale 0"});
}

TEST(PfmMalformed, ScaleNotANumber) {
  expect_decode_error(pfm("Pf 1 1 abc\n", {kOne}, true), "abc.pfm",
                      {"scale 'abc' is not a finite decimal number"});
  expect_decode_error(pfm("Pf 1 1 -1x\n", {kOne}, true), "x.pfm", {"scale '-1x'"});
  expect_decode_error(pfm("Pf 1 1 nan\n", {kOne}, true), "nan.pfm", {"scale 'nan'"});
  expect_decode_error(pfm("Pf 1 1 -inf\n", {kOne}, true), "inf.pfm", {"scale '-inf'"});
  expect_decode_error(pfm("Pf 1 1 -1e999\n", {kOne}, true), "big.pfm", {"scale '-1e999'"});
}

// The scale is one real number: a '+' may lead it, but not lead another sign.
TEST(PfmMalformed, ScaleWithTwoSigns) {
  expect_decode_error(pfm("Pf 1 1 +-1\n", {kOne}, true), "signs.pfm",
                      {"scale '+-1' is not a finite decimal number"});
  expect_decode_error(pfm("Pf 1 1 ++1\n", {kOne}, false), "signs.pfm", {"scale '++1'"});
  expect_decode_error(pfm("Pf 1 1 -+1\n", {kOne}, true), "signs.pfm", {"scale '-+1'"});
  const AnyImage plus = decode_image(pfm("Pf 1 1 +1\n", {kOne}, false), "plus.pfm");
  EXPECT_EQ(floats(plus)(0, 0), 1.0F);
}

TEST(PfmMalformed, ScaleTooLong) {
  Bytes bytes = bytes_of("Pf 1 1 -" + std::string(100, '1') + "\n");
  expect_decode_error(bytes, "long.pfm", {"scale is longer than 64 characters"});
}

TEST(PfmMalformed, Truncated) {
  Bytes bytes = pfm("Pf\n2 2\n-1\n", {kOne, kOne, kOne, kOne}, true);
  bytes.pop_back();
  expect_decode_error(bytes, "cut.pfm", {"truncated pixel data", "expected 16 bytes", "found 15"});
  expect_decode_error(bytes_of("Pf\n2 2\n-1"), "cut.pfm", {"after the scale", "end of the file"});
  expect_decode_error(bytes_of("Pf\n2"), "cut.pfm", {"after the width", "end of the file"});
}

TEST(PfmMalformed, WidthOrHeightOutOfRange) {
  expect_decode_error(bytes_of("Pf 0 1 -1\n"), "w.pfm", {"width 0 is out of range"});
  expect_decode_error(bytes_of("PF 1 16385 -1\n"), "h.pfm", {"height 16385 is out of range"});
  expect_decode_error(bytes_of("Pf 18446744073709551617 1 -1\n"), "w.pfm",
                      {"width 18446744073709551617 is out of range"});
  expect_decode_error(bytes_of("Pf -1 1 -1\n"), "w.pfm", {"expected width", "'-'"});
}

TEST(PfmMalformed, HugeHeaderIsRejectedBeforeAllocatingPixels) {
  testing::LargestRequestResource resource;
  expect_decode_error(pfm("PF 16384 16384 -1\n", {kOne}, true), "huge.pfm",
                      {"truncated pixel data", "expected 3221225472 bytes", "found 4"});
  EXPECT_LT(resource.largest(), 4096U);
}

TEST(PfmMalformed, CommentsAreNotPartOfPfm) {
  expect_decode_error(pfm("Pf\n# note\n1 1\n-1\n", {kOne}, true), "c.pfm",
                      {"expected width", "'#'"});
}

} // namespace
} // namespace marsokhod::imaging
