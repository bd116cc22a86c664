// Tests: the image decoders on seeded random damage to valid files of every format.
// Seeded random damage to valid files of every format: decode_image must either return a
// well-formed image or throw ImageError, whatever the damage.

#include "imaging/image_test_support.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <zlib.h>

namespace marsokhod::imaging {
namespace {

using testing::Bytes;
using testing::TemporaryFolder;

constexpr int kMutationsPerBase = 2000;
constexpr std::uint64_t kSeed = 0x6d61'7273'6f6b'686fULL;

struct Base {
  std::string name;
  Bytes bytes;
};

template <class T>
Image<T> gradient(int width, int height, int channels, int maxval) {
  Image<T> image(width, height, channels);
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<T>((i * 37) % static_cast<std::size_t>(maxval + 1));
  return image;
}

// Valid files of each format and depth, written by the library and then read back as bytes.
std::vector<Base> valid_files(const TemporaryFolder& folder) {
  std::vector<Base> bases;
  auto add = [&](const std::string& name, const auto& image) {
    write_image(folder / name, image.view());
    bases.push_back({name, testing::read_bytes(folder / name)});
  };
  add("grey8.pgm", gradient<std::uint8_t>(7, 5, 1, 255));
  add("grey16.pgm", gradient<std::uint16_t>(6, 4, 1, 65535));
  add("rgb8.ppm", gradient<std::uint8_t>(5, 3, 3, 255));
  add("rgb16.ppm", gradient<std::uint16_t>(3, 4, 3, 65535));
  add("grey8.png", gradient<std::uint8_t>(9, 6, 1, 255));
  add("grey16.png", gradient<std::uint16_t>(5, 5, 1, 65535));
  add("rgb8.png", gradient<std::uint8_t>(6, 4, 3, 255));
  add("rgb16.png", gradient<std::uint16_t>(4, 3, 3, 65535));
  Image<float> field(5, 4, 1);
  for (std::size_t i = 0; i < field.size(); ++i)
    field.data()[i] = static_cast<float>(i) * 0.5F - 3.0F;
  add("grey.pfm", field);
  add("rgb.pfm", Image<float>(3, 2, 3, 1.25F));
  // A header with comments and an odd maxval exercises the comment paths.
  Bytes commented = testing::bytes_of("P5\n# comment\n4 # w\n3\n1000\n");
  commented.resize(commented.size() + 24, 1);
  bases.push_back({"commented.pgm", commented});
  return bases;
}

std::uint64_t below(std::mt19937_64& random, std::uint64_t bound) {
  return random() % bound;
}

// Replaces one run of decimal digits in the header with another number, often an edge value.
void change_header_number(Bytes& bytes, std::mt19937_64& random) {
  const std::size_t header = std::min<std::size_t>(bytes.size(), 40);
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < header; ++i)
    if (bytes[i] >= '0' && bytes[i] <= '9' && (i == 0 || bytes[i - 1] < '0' || bytes[i - 1] > '9'))
      starts.push_back(i);
  if (starts.empty())
    return;
  const std::size_t start = starts[below(random, starts.size())];
  std::size_t end = start;
  while (end < bytes.size() && bytes[end] >= '0' && bytes[end] <= '9')
    ++end;
  static const char* const kNumbers[] = {"0",
                                         "1",
                                         "2",
                                         "255",
                                         "256",
                                         "65535",
                                         "65536",
                                         "16384",
                                         "16385",
                                         "2147483647",
                                         "2147483648",
                                         "4294967297",
                                         "99999999999999999999999",
                                         "-1",
                                         "1e3",
                                         "007"};
  const std::string replacement = below(random, 4) == 0
                                      ? std::to_string(below(random, 100000))
                                      : kNumbers[below(random, std::size(kNumbers))];
  bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(start),
              bytes.begin() + static_cast<std::ptrdiff_t>(end));
  bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(start), replacement.begin(),
               replacement.end());
}

// Recomputes every chunk CRC so that libpng looks past the CRC check into the damaged content.
void fix_png_crcs(Bytes& bytes) {
  std::size_t at = 8;
  while (at + 12 <= bytes.size()) {
    std::uint32_t length = 0;
    for (std::size_t i = at; i < at + 4; ++i)
      length = (length << 8) | bytes[i];
    if (length > bytes.size() - at - 12)
      return;
    const auto crc = static_cast<std::uint32_t>(crc32(0, bytes.data() + at + 4, 4 + length));
    for (int i = 0; i < 4; ++i)
      bytes[at + 8 + length + static_cast<std::size_t>(i)] =
          static_cast<std::uint8_t>(crc >> (24 - 8 * i));
    at += 12 + length;
  }
}

Bytes mutate(const Bytes& original, std::mt19937_64& random, bool png) {
  Bytes bytes = original;
  const int edits = 1 + static_cast<int>(below(random, 3));
  for (int edit = 0; edit < edits && !bytes.empty(); ++edit) {
    // Half of the edits land in the first 48 bytes, where the header lives.
    const std::size_t span =
        below(random, 2) == 0 ? std::min<std::size_t>(bytes.size(), 48) : bytes.size();
    const std::size_t at = below(random, span);
    switch (below(random, 5)) {
    case 0: // flip one bit
      bytes[at] ^= static_cast<std::uint8_t>(1U << below(random, 8));
      break;
    case 1: // overwrite with a byte that means something to a header parser
      bytes[at] = static_cast<std::uint8_t>("# \n\t0123456789-+.eP5fF\x89\xff"[below(random, 24)]);
      break;
    case 2: // truncate
      bytes.resize(at);
      break;
    case 3: // insert a few bytes
      bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), 1 + below(random, 4),
                   static_cast<std::uint8_t>(random()));
      break;
    default:
      change_header_number(bytes, random);
      break;
    }
  }
  if (png && below(random, 2) == 0)
    fix_png_crcs(bytes);
  return bytes;
}

template <class T>
::testing::AssertionResult well_formed(const Image<T>& image) {
  const bool sides = image.width() >= 1 && image.width() <= kMaxImageSide && image.height() >= 1 &&
                     image.height() <= kMaxImageSide;
  const bool channels = image.channels() == 1 || image.channels() == 3;
  const std::size_t expected = static_cast<std::size_t>(image.width()) *
                               static_cast<std::size_t>(image.height()) *
                               static_cast<std::size_t>(image.channels());
  if (sides && channels && image.size() == expected)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << image.width() << "x" << image.height() << "x" << image.channels() << " with "
         << image.size() << " samples";
}

TEST(ImageMutation, DamagedFilesDecodeOrThrowImageErrorOnly) {
  TemporaryFolder folder;
  std::mt19937_64 random(kSeed);
  int decoded = 0;
  int refused = 0;
  for (const Base& base : valid_files(folder)) {
    const bool png = base.name.ends_with(".png");
    for (int i = 0; i < kMutationsPerBase; ++i) {
      const Bytes bytes = mutate(base.bytes, random, png);
      const std::string name = base.name + "#" + std::to_string(i);
      try {
        const AnyImage image = decode_image(bytes, name);
        std::visit([&](const auto& pixels) { EXPECT_TRUE(well_formed(pixels)) << name; }, image);
        ++decoded;
      } catch (const ImageError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(name + ": ", 0), 0U) << error.what();
        ++refused;
      } catch (const std::exception& error) {
        ADD_FAILURE() << name << ": unexpected " << typeid(error).name() << ": " << error.what();
      }
    }
  }
  // Both outcomes must occur, or the mutations are too mild or too destructive to test much.
  EXPECT_GT(decoded, 2000);
  EXPECT_GT(refused, 2000);
  std::printf("mutations: %d decoded, %d refused\n", decoded, refused);
}

} // namespace
} // namespace marsokhod::imaging
