// Binary PGM/PPM decoding against byte sequences written by hand from the netpbm specification.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace marsokhod::imaging {
namespace {

using testing::append;
using testing::Bytes;
using testing::bytes_of;
using testing::expect_decode_error;

template <class T>
const Image<T>& pnm_as(const AnyImage& image) {
  EXPECT_TRUE(std::holds_alternative<Image<T>>(image));
  return std::get<Image<T>>(image);
}

TEST(PnmDecode, Reads8BitGreyRowByRow) {
  const AnyImage decoded =
      decode_image(bytes_of("P5\n3 2\n255\n", {0, 1, 2, 253, 254, 255}), "a.pgm");
  const auto& image = pnm_as<std::uint8_t>(decoded);
  ASSERT_EQ(image.width(), 3);
  ASSERT_EQ(image.height(), 2);
  ASSERT_EQ(image.channels(), 1);
  EXPECT_EQ(image(2, 0), 2);
  EXPECT_EQ(image(0, 1), 253);
  EXPECT_EQ(image(2, 1), 255);
}

TEST(PnmDecode, Reads8BitRgbInterleaved) {
  const AnyImage decoded =
      decode_image(bytes_of("P6 2 1 255\n", {10, 20, 30, 40, 50, 60}), "a.ppm");
  const auto& image = pnm_as<std::uint8_t>(decoded);
  ASSERT_EQ(image.channels(), 3);
  EXPECT_EQ(image(0, 0, 2), 30);
  EXPECT_EQ(image(1, 0, 0), 40);
  EXPECT_EQ(image(1, 0, 2), 60);
}

TEST(PnmDecode, Reads16BitSamplesMostSignificantByteFirst) {
  const AnyImage decoded =
      decode_image(bytes_of("P5 2 1 65535\n", {0x12, 0x34, 0xff, 0xfe}), "deep.pgm");
  const auto& image = pnm_as<std::uint16_t>(decoded);
  EXPECT_EQ(image(0, 0), 0x1234);
  EXPECT_EQ(image(1, 0), 0xfffe);
}

TEST(PnmDecode, MaxvalAbove255SelectsTwoByteSamples) {
  // maxval 255 means one byte per sample, 256 two bytes (netpbm specification).
  const AnyImage one = decode_image(bytes_of("P5 2 1 255\n", {1, 2}), "one.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(one)(1, 0), 2);
  const AnyImage two = decode_image(bytes_of("P5 2 1 256\n", {0, 1, 1, 0}), "two.pgm");
  EXPECT_EQ(pnm_as<std::uint16_t>(two)(0, 0), 1);
  EXPECT_EQ(pnm_as<std::uint16_t>(two)(1, 0), 256);
}

TEST(PnmDecode, Reads16BitRgbWithSmallMaxval) {
  const AnyImage decoded =
      decode_image(bytes_of("P6 1 1 1023\n", {0x03, 0xff, 0x02, 0x00, 0x00, 0x01}), "rgb.ppm");
  const auto& image = pnm_as<std::uint16_t>(decoded);
  EXPECT_EQ(image(0, 0, 0), 1023);
  EXPECT_EQ(image(0, 0, 1), 512);
  EXPECT_EQ(image(0, 0, 2), 1);
}

TEST(PnmDecode, MaxvalOneIsValid) {
  const AnyImage decoded = decode_image(bytes_of("P5 2 1 1\n", {1, 0}), "bits.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded)(0, 0), 1);
}

TEST(PnmDecode, AnyHeaderWhitespaceSeparatesFields) {
  const AnyImage decoded = decode_image(bytes_of("P5\t2\r\n\v1\f 255\r", {7, 8}), "ws.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded)(1, 0), 8);
}

TEST(PnmDecode, TrailingBytesAfterTheRasterAreIgnored) {
  // A netpbm stream may hold several images one after another.
  const AnyImage decoded = decode_image(bytes_of("P5 1 1 255\n", {9, 'P', '5'}), "multi.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded)(0, 0), 9);
}

TEST(PnmComments, AcceptedBetweenEveryHeaderField) {
  const AnyImage decoded = decode_image(
      bytes_of("P5\n# made by hand\n2 # width\n# height next\n1\n#maxval\n255\n", {4, 5}),
      "comments.pgm");
  const auto& image = pnm_as<std::uint8_t>(decoded);
  EXPECT_EQ(image.width(), 2);
  EXPECT_EQ(image(1, 0), 5);
}

TEST(PnmComments, EndedByCarriageReturn) {
  const AnyImage decoded = decode_image(bytes_of("P5 #note\r2 1 255\n", {1, 2}), "cr.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded).width(), 2);
}

TEST(PnmComments, InsideANumberAreCutOutOfIt) {
  // The specification: a comment "can actually be in the middle of what you might consider a
  // token"; cutting "#x\n" out of "1#x\n2" leaves the width 12.
  Bytes bytes = bytes_of("P5 1#x\n2 1 255\n");
  bytes.resize(bytes.size() + 12, 3);
  const AnyImage decoded = decode_image(bytes, "split.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded).width(), 12);
}

TEST(PnmComments, BeforeTheRasterNeedTheirOwnWhitespaceByte) {
  // "the newline at the end of the comment is not sufficient to delimit the raster"
  const AnyImage decoded = decode_image(bytes_of("P5 2 1 255#last\n\n", {'A', 'B'}), "ok.pgm");
  EXPECT_EQ(pnm_as<std::uint8_t>(decoded)(0, 0), 'A');
  expect_decode_error(bytes_of("P5 2 1 255#last\n", {'A', 'B'}), "bad.pgm",
                      {"expected one whitespace byte after maxval", "'A'"});
}

TEST(PnmComments, HashAfterTheMaxvalWhitespaceIsPixelData) {
  const AnyImage decoded = decode_image(bytes_of("P5 2 1 255\n#c"), "hash.pgm");
  const auto& image = pnm_as<std::uint8_t>(decoded);
  EXPECT_EQ(image(0, 0), '#');
  EXPECT_EQ(image(1, 0), 'c');
}

TEST(PnmComments, CommentRightAfterTheMagicStillNeedsWhitespace) {
  expect_decode_error(bytes_of("P5#c\n2 1 255\n", {1, 2}), "glued.pgm",
                      {"expected whitespace after the magic number", "'2'", "line end"});
}

TEST(PnmComments, UnterminatedCommentIsATruncatedHeader) {
  expect_decode_error(bytes_of("P5 2 1 # no end"), "open.pgm", {"truncated header", "comment"});
}

TEST(PnmMalformed, TruncatedPixelData) {
  expect_decode_error(bytes_of("P5\n4 2\n255\n", {1, 2, 3, 4, 5}), "short.pgm",
                      {"truncated pixel data", "expected 8 bytes", "found 5"});
}

TEST(PnmMalformed, TruncatedSixteenBitRgbPixelData) {
  Bytes bytes = bytes_of("P6 2 2 65535\n");
  bytes.resize(bytes.size() + 23, 0);
  expect_decode_error(bytes, "short.ppm",
                      {"truncated pixel data", "expected 24 bytes", "found 23"});
}

TEST(PnmMalformed, TruncatedHeader) {
  expect_decode_error(bytes_of("P5 2"), "cut.pgm",
                      {"expected whitespace after the width", "end of the file"});
  expect_decode_error(bytes_of("P5 2 1 255"), "cut.pgm",
                      {"expected one whitespace byte after maxval", "end of the file"});
}

TEST(PnmMalformed, WrongMagic) {
  expect_decode_error(bytes_of("P2 2 1 255\n1 2\n"), "ascii.pgm",
                      {"unsupported netpbm format P2", "P5 and P6"});
  expect_decode_error(bytes_of("Q5 2 1 255\n", {1, 2}), "odd.pgm", {"unknown image format"});
  expect_decode_error(bytes_of("P"), "p.pgm", {"unknown image format"});
}

TEST(PnmMalformed, MaxvalZero) {
  expect_decode_error(bytes_of("P5 2 1 0\n", {0, 0}), "zero.pgm",
                      {"maxval 0 is out of range 1..65535"});
}

TEST(PnmMalformed, MaxvalAbove65535) {
  expect_decode_error(bytes_of("P5 1 1 65536\n", {0, 0, 0}), "big.pgm",
                      {"maxval 65536 is out of range 1..65535"});
}

TEST(PnmMalformed, WidthOrHeightZero) {
  expect_decode_error(bytes_of("P5 0 1 255\n"), "w0.pgm", {"width 0 is out of range 1..16384"});
  expect_decode_error(bytes_of("P6 1 0 255\n"), "h0.ppm", {"height 0 is out of range 1..16384"});
}

TEST(PnmMalformed, WidthOrHeightOverTheLimit) {
  expect_decode_error(bytes_of("P5 16385 1 255\n"), "wide.pgm", {"width 16385 is out of range"});
  expect_decode_error(bytes_of("P5 1 16385 255\n"), "tall.pgm", {"height 16385 is out of range"});
}

TEST(PnmMalformed, HugeHeaderIsRejectedBeforeAllocatingPixels) {
  // 16384 x 16384 RGB at 16 bit would be 1.5 GiB; the file holds 10 bytes of it.
  testing::LargestRequestResource resource;
  Bytes bytes = bytes_of("P6 16384 16384 65535\n");
  bytes.resize(bytes.size() + 10, 0);
  expect_decode_error(bytes, "huge.ppm", {"truncated pixel data", "expected 1610612736 bytes"});
  EXPECT_LT(resource.largest(), 4096U);
}

TEST(PnmMalformed, NegativeNumbers) {
  expect_decode_error(bytes_of("P5 -2 1 255\n"), "neg.pgm",
                      {"expected width (a decimal number)", "'-'"});
  expect_decode_error(bytes_of("P5 2 1 -255\n"), "neg.pgm", {"expected maxval", "'-'"});
}

TEST(PnmMalformed, GarbageNumbers) {
  expect_decode_error(bytes_of("P5 2x 1 255\n"), "x.pgm",
                      {"expected whitespace after the width", "'x'"});
  expect_decode_error(bytes_of("P5 two 1 255\n"), "x.pgm", {"expected width", "'t'"});
  expect_decode_error(bytes_of("P5 2 1 2.5e2\n"), "x.pgm", {"after maxval", "'.'"});
  expect_decode_error(bytes_of(std::string_view("P5 2 1\0 255\n", 12)), "x.pgm",
                      {"after the height"});
}

TEST(PnmMalformed, NumbersOverflowingIntAreOutOfRangeNotWrapped) {
  // 4294967297 wraps to 1 in 32 bits and 4294967551 to 255: both must still be refused.
  expect_decode_error(bytes_of("P5 4294967297 1 255\n", {0}), "wrap.pgm",
                      {"width 4294967297 is out of range"});
  expect_decode_error(bytes_of("P5 1 1 4294967551\n", {0}), "wrap.pgm",
                      {"maxval 4294967551 is out of range"});
  expect_decode_error(bytes_of("P5 1 2147483648 255\n", {0}), "wrap.pgm",
                      {"height 2147483648 is out of range"});
  const std::string message = expect_decode_error(
      bytes_of("P5 123456789012345678901234567890123 1 255\n"), "long.pgm", {"is out of range"});
  EXPECT_NE(message.find("123456789012345678901234..."), std::string::npos) << message;
}

TEST(PnmMalformed, SampleAboveMaxval) {
  expect_decode_error(bytes_of("P5 2 1 100\n", {50, 200}), "over.pgm",
                      {"sample value 200 exceeds maxval 100 at pixel (1, 0)"});
  expect_decode_error(bytes_of("P6 1 2 1000\n", {0, 0, 0, 0, 0, 0, 0, 0, 0x03, 0xe9, 0, 0}),
                      "over.ppm", {"sample value 1001 exceeds maxval 1000 at pixel (0, 1)"});
}

TEST(PnmSharedData, MiddleburyPgmMatchesItsRawBytes) {
  const std::filesystem::path path =
      std::filesystem::path(MARSOKHOD_SHARED_DATA) / "stereo" / "tsukuba_left.pgm";
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << "shared data not found: " << path;
  const Bytes file = testing::read_bytes(path);
  const AnyImage decoded = read_image(path);
  const auto& image = pnm_as<std::uint8_t>(decoded);
  ASSERT_EQ(image.width(), 384); // sizes from stereo/PAIRS.tsv
  ASSERT_EQ(image.height(), 288);
  // The header "P5\n384 288\n255\n" is 15 bytes; the raster is the rest of the file.
  ASSERT_EQ(file.size(), 15U + 384U * 288U);
  EXPECT_TRUE(std::equal(file.begin() + 15, file.end(), image.data()));
}

} // namespace
} // namespace marsokhod::imaging
