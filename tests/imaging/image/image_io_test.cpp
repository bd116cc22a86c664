// Files on disk: reading errors, atomic writing, round trips, grey and PFM convenience readers.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace marsokhod::imaging {
namespace {

using testing::Bytes;
using testing::bytes_of;
using testing::expect_image_error;
using testing::TemporaryFolder;

template <class T>
Image<T> pattern(int width, int height, int channels, T low, T high) {
  Image<T> image(width, height, channels);
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<T>(i % 3 == 0 ? low : (i % 3 == 1 ? high : static_cast<T>(i)));
  return image;
}

template <class T>
void expect_round_trip(const std::filesystem::path& path, const Image<T>& image) {
  write_image(path, image.view());
  const AnyImage back = read_image(path);
  ASSERT_TRUE(std::holds_alternative<Image<T>>(back)) << path;
  EXPECT_TRUE(std::get<Image<T>>(back) == image) << path;
}

TEST(ImageRead, MissingFile) {
  TemporaryFolder folder;
  const auto path = folder / "absent.pgm";
  expect_image_error([&] { (void)read_image(path); }, path.string(), {"no such file"});
}

TEST(ImageRead, DirectoryInsteadOfFile) {
  TemporaryFolder folder;
  std::filesystem::create_directory(folder / "dir.pgm");
  const auto path = folder / "dir.pgm";
  expect_image_error([&] { (void)read_image(path); }, path.string(), {"is a directory"});
}

TEST(ImageRead, EmptyFile) {
  TemporaryFolder folder;
  const auto path = folder / "empty.png";
  testing::write_bytes(path, {});
  expect_image_error([&] { (void)read_image(path); }, path.string(), {"empty file"});
  expect_image_error([&] { (void)decode_image({}, "memory"); }, "memory", {"empty file"});
}

TEST(ImageRead, FormatComesFromContentNotExtension) {
  TemporaryFolder folder;
  const auto path = folder / "actually_pgm.png";
  testing::write_bytes(path, bytes_of("P5 1 1 255\n", {42}));
  const AnyImage image = read_image(path);
  ASSERT_TRUE(std::holds_alternative<Image<std::uint8_t>>(image));
  EXPECT_EQ(std::get<Image<std::uint8_t>>(image)(0, 0), 42);
}

TEST(ImageRead, DecodeErrorsNameTheFilePath) {
  TemporaryFolder folder;
  const auto path = folder / "short.pgm";
  testing::write_bytes(path, bytes_of("P5 2 2 255\n", {1}));
  expect_image_error([&] { (void)read_image(path); }, path.string(), {"truncated pixel data"});
}

TEST(ImageRoundTrip, Pgm8And16Bit) {
  TemporaryFolder folder;
  expect_round_trip(folder / "a.pgm", pattern<std::uint8_t>(5, 4, 1, 0, 255));
  expect_round_trip(folder / "b.pgm", pattern<std::uint16_t>(5, 4, 1, 0, 65535));
}

TEST(ImageRoundTrip, Ppm8And16Bit) {
  TemporaryFolder folder;
  expect_round_trip(folder / "a.ppm", pattern<std::uint8_t>(3, 7, 3, 0, 255));
  expect_round_trip(folder / "b.ppm", pattern<std::uint16_t>(3, 7, 3, 0, 65535));
}

TEST(ImageRoundTrip, PngGreyAndRgb8And16Bit) {
  TemporaryFolder folder;
  expect_round_trip(folder / "a.png", pattern<std::uint8_t>(6, 5, 1, 0, 255));
  expect_round_trip(folder / "b.png", pattern<std::uint16_t>(6, 5, 1, 0, 65535));
  expect_round_trip(folder / "c.png", pattern<std::uint8_t>(6, 5, 3, 0, 255));
  expect_round_trip(folder / "d.PNG", pattern<std::uint16_t>(6, 5, 3, 0, 65535));
}

TEST(ImageRoundTrip, PfmOneAndThreeChannelsKeepEveryBit) {
  TemporaryFolder folder;
  Image<float> grey(4, 3, 1);
  const float specials[] = {0.0F,
                            -0.0F,
                            1.5F,
                            -1e30F,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::denorm_min(),
                            3.25F};
  for (std::size_t i = 0; i < grey.size(); ++i)
    grey.data()[i] = specials[i % std::size(specials)];
  expect_round_trip(folder / "a.pfm", grey);
  expect_round_trip(folder / "b.pfm", pattern<float>(3, 5, 3, -2.5F, 1e6F));

  Image<float> with_nan(2, 1, 1, std::numeric_limits<float>::quiet_NaN());
  write_image(folder / "nan.pfm", with_nan.view());
  const Image<float> back = read_pfm(folder / "nan.pfm");
  EXPECT_TRUE(std::isnan(back(0, 0)) && std::isnan(back(1, 0)));
}

TEST(ImageRoundTrip, PfmFileIsLittleEndianBottomUp) {
  TemporaryFolder folder;
  Image<float> image(1, 2, 1);
  image(0, 0) = 1.0F; // top: 0x3f800000
  image(0, 1) = 2.0F; // bottom: 0x40000000, first in the file
  write_image(folder / "o.pfm", image.view());
  EXPECT_EQ(testing::read_bytes(folder / "o.pfm"),
            bytes_of("Pf\n1 2\n-1\n", {0, 0, 0, 0x40, 0, 0, 0x80, 0x3f}));
}

TEST(ImageRoundTrip, SixteenBitPgmFileIsBigEndianWithMaxval65535) {
  TemporaryFolder folder;
  Image<std::uint16_t> image(2, 1, 1);
  image(0, 0) = 0x1234;
  image(1, 0) = 0xabcd;
  write_image(folder / "o.pgm", image.view());
  EXPECT_EQ(testing::read_bytes(folder / "o.pgm"),
            bytes_of("P5\n2 1\n65535\n", {0x12, 0x34, 0xab, 0xcd}));
}

TEST(ImageRoundTrip, StridedSubViewIsWrittenAsItsOwnImage) {
  TemporaryFolder folder;
  Image<std::uint8_t> image = pattern<std::uint8_t>(9, 7, 3, 1, 254);
  const ImageView<const std::uint8_t> window = std::as_const(image).view().sub(2, 3, 4, 2);
  for (const char* name : {"w.ppm", "w.png"}) {
    write_image(folder / name, window);
    const AnyImage back = read_image(folder / name);
    EXPECT_TRUE(std::get<Image<std::uint8_t>>(back) == to_image(window)) << name;
  }
}

TEST(ImageWrite, MissingFolderIsNamed) {
  TemporaryFolder folder;
  const auto path = folder / "no_such_folder" / "out.pgm";
  const Image<std::uint8_t> image(2, 2);
  const std::string message = expect_image_error([&] { write_image(path, image.view()); },
                                                 path.string(), {"does not exist"});
  EXPECT_NE(message.find((folder / "no_such_folder").string()), std::string::npos) << message;
}

TEST(ImageWrite, ExtensionMustFitThePixels) {
  TemporaryFolder folder;
  const Image<std::uint8_t> grey(2, 2);
  const Image<std::uint8_t> rgb(2, 2, 3);
  const Image<float> field(2, 2);
  auto path = folder / "g.ppm";
  expect_image_error([&] { write_image(path, grey.view()); }, path.string(),
                     {"grey image goes to .pgm"});
  path = folder / "c.pgm";
  expect_image_error([&] { write_image(path, rgb.view()); }, path.string(), {"goes to .ppm"});
  path = folder / "f.png";
  expect_image_error([&] { write_image(path, field.view()); }, path.string(),
                     {"float pixels go to .pfm"});
  path = folder / "i.pfm";
  expect_image_error([&] { write_image(path, grey.view()); }, path.string(),
                     {"PFM holds float pixels"});
  path = folder / "x.jpg";
  expect_image_error([&] { write_image(path, grey.view()); }, path.string(),
                     {"unsupported extension '.jpg'"});
  path = folder / "two.png";
  const Image<std::uint8_t> grey_alpha(2, 2, 2);
  expect_image_error([&] { write_image(path, grey_alpha.view()); }, path.string(), {"2-channel"});
  path = folder / "empty.pgm";
  expect_image_error([&] { write_image(path, Image<std::uint8_t>().view()); }, path.string(),
                     {"empty image"});
  EXPECT_TRUE(std::filesystem::is_empty(folder.path())) << "a refused write left a file behind";
}

TEST(ImageWrite, ReplacesTheTargetAndLeavesNoTemporaryFile) {
  TemporaryFolder folder;
  const auto path = folder / "out.pgm";
  testing::write_bytes(path, bytes_of("old content that is longer than the new image"));
  write_image(path, Image<std::uint8_t>(1, 1, 1, 77).view());
  EXPECT_EQ(testing::read_bytes(path), bytes_of("P5\n1 1\n255\n", {77}));
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path()))
    ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(ImageWrite, ADirectoryAtTheTargetPathIsRefused) {
  TemporaryFolder folder;
  std::filesystem::create_directory(folder / "taken.pgm");
  const auto path = folder / "taken.pgm";
  expect_image_error([&] { write_image(path, Image<std::uint8_t>(1, 1).view()); }, path.string(),
                     {"is a directory"});
}

TEST(ReadGray8, RgbBecomesRec601Luma) {
  TemporaryFolder folder;
  const auto path = folder / "rgb.ppm";
  testing::write_bytes(path,
                       bytes_of("P6 4 1 255\n", {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30}));
  const Image<std::uint8_t> grey = read_gray8(path);
  ASSERT_EQ(grey.channels(), 1);
  EXPECT_EQ(grey(0, 0), 76);  // 0.299 * 255 = 76.2
  EXPECT_EQ(grey(1, 0), 150); // 0.587 * 255 = 149.7
  EXPECT_EQ(grey(2, 0), 29);  // 0.114 * 255 = 29.1
  EXPECT_EQ(grey(3, 0), 18);  // 2.99 + 11.74 + 3.42 = 18.15
}

TEST(ReadGray8, SixteenBitSamplesAreRescaledFromMaxval) {
  TemporaryFolder folder;
  const auto deep = folder / "deep.pgm";
  testing::write_bytes(deep, bytes_of("P5 3 1 65535\n", {0xff, 0xff, 0x80, 0x00, 0x00, 0x81}));
  const Image<std::uint8_t> grey = read_gray8(deep);
  EXPECT_EQ(grey(0, 0), 255);
  EXPECT_EQ(grey(1, 0), 128); // 32768 * 255 / 65535 = 127.50
  EXPECT_EQ(grey(2, 0), 1);   // 129 * 255 / 65535 = 0.502
  const auto tenbit = folder / "ten.pgm";
  testing::write_bytes(tenbit, bytes_of("P5 2 1 1023\n", {0x03, 0xff, 0x01, 0x00}));
  EXPECT_EQ(read_gray8(tenbit)(0, 0), 255);
  EXPECT_EQ(read_gray8(tenbit)(1, 0), 64); // 256 * 255 / 1023 = 63.8
  const auto small = folder / "small.pgm";
  testing::write_bytes(small, bytes_of("P5 1 1 100\n", {50}));
  EXPECT_EQ(read_gray8(small)(0, 0), 128); // 50 * 255 / 100 = 127.5
}

TEST(ReadGray8, FloatImagesAreRefused) {
  TemporaryFolder folder;
  const auto path = folder / "d.pfm";
  write_image(path, Image<float>(1, 1).view());
  expect_image_error([&] { (void)read_gray8(path); }, path.string(), {"no implied grey range"});
}

TEST(ReadPfm, OnlyOneChannelPfmIsAccepted) {
  TemporaryFolder folder;
  const auto rgb = folder / "rgb.pfm";
  write_image(rgb, Image<float>(1, 1, 3).view());
  expect_image_error([&] { (void)read_pfm(rgb); }, rgb.string(),
                     {"expected a one-channel PFM", "PF"});
  const auto pgm = folder / "i.pgm";
  write_image(pgm, Image<std::uint8_t>(1, 1).view());
  expect_image_error([&] { (void)read_pfm(pgm); }, pgm.string(), {"expected a one-channel PFM"});
}

} // namespace
} // namespace marsokhod::imaging
