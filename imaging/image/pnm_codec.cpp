// Binary PGM (P5) and PPM (P6), 8 bit (maxval 1..255) and 16 bit big endian (256..65535).

#include "image/header_scanner.hpp"
#include "image/image_codec.hpp"

#include <fmt/format.h>

namespace marsokhod::imaging::detail {
namespace {

struct PnmHeader {
  ImageFormat format = ImageFormat::pgm;
  int channels = 1;
  int width = 0;
  int height = 0;
  int maxval = 0;
  std::size_t raster_offset = 0;
};

PnmHeader read_pnm_header(std::span<const std::uint8_t> bytes, std::string_view name,
                          bool cut = false) {
  PnmHeader header;
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '6'))
    fail(name, "not a binary PGM/PPM file (magic P5 or P6 expected)");
  if (bytes[1] == '6') {
    header.format = ImageFormat::ppm;
    header.channels = 3;
  }
  HeaderScanner scanner(bytes.subspan(2), name, /*comments=*/true, cut);
  scanner.skip_separator("the magic number");
  header.width = scanner.read_number("width", 1, kMaxImageSide);
  scanner.skip_separator("the width");
  header.height = scanner.read_number("height", 1, kMaxImageSide);
  scanner.skip_separator("the height");
  header.maxval = scanner.read_number("maxval", 1, 65535);
  scanner.expect_single_whitespace("maxval");
  header.raster_offset = 2 + scanner.position();
  return header;
}

std::size_t raster_bytes(const PnmHeader& header) {
  const std::size_t sample_bytes = header.maxval > 255 ? 2 : 1;
  return static_cast<std::size_t>(header.width) * static_cast<std::size_t>(header.height) *
         static_cast<std::size_t>(header.channels) * sample_bytes;
}

template <class T>
Image<T> read_raster(std::span<const std::uint8_t> raster, const PnmHeader& header,
                     std::string_view name) {
  Image<T> image(header.width, header.height, header.channels);
  const std::size_t samples = image.size();
  for (std::size_t i = 0; i < samples; ++i) {
    unsigned value = raster[i * sizeof(T)];
    if constexpr (sizeof(T) == 2)
      value = (value << 8) | raster[i * 2 + 1];
    if (value > static_cast<unsigned>(header.maxval)) {
      const std::size_t pixel = i / static_cast<std::size_t>(header.channels);
      fail(name, fmt::format("sample value {} exceeds maxval {} at pixel ({}, {})", value,
                             header.maxval, pixel % static_cast<std::size_t>(header.width),
                             pixel / static_cast<std::size_t>(header.width)));
    }
    image.data()[i] = static_cast<T>(value);
  }
  return image;
}

template <class T>
std::vector<std::uint8_t> encode(ImageView<const T> image, int maxval) {
  const char magic = image.channels() == 1 ? '5' : '6';
  const std::string header =
      fmt::format("P{}\n{} {}\n{}\n", magic, image.width(), image.height(), maxval);
  std::vector<std::uint8_t> bytes(header.begin(), header.end());
  const std::size_t row_samples =
      static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.channels());
  bytes.reserve(bytes.size() + row_samples * sizeof(T) * static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y) {
    const T* row = image.row(y);
    for (std::size_t i = 0; i < row_samples; ++i) {
      if constexpr (sizeof(T) == 2)
        bytes.push_back(static_cast<std::uint8_t>(row[i] >> 8));
      bytes.push_back(static_cast<std::uint8_t>(row[i] & 0xff));
    }
  }
  return bytes;
}

} // namespace

DecodedImage decode_pnm(std::span<const std::uint8_t> bytes, std::string_view name) {
  const PnmHeader header = read_pnm_header(bytes, name);
  const std::size_t sample_bytes = header.maxval > 255 ? 2 : 1;
  const std::size_t expected = raster_bytes(header);
  const std::span<const std::uint8_t> raster = bytes.subspan(header.raster_offset);
  // Checked before allocating, so a lying header cannot make us reserve gigabytes.
  if (raster.size() < expected)
    fail(name,
         fmt::format("truncated pixel data: expected {} bytes, found {}", expected, raster.size()));
  DecodedImage decoded;
  decoded.format = header.format;
  decoded.maxval = header.maxval;
  if (sample_bytes == 1)
    decoded.pixels = read_raster<std::uint8_t>(raster, header, name);
  else
    decoded.pixels = read_raster<std::uint16_t>(raster, header, name);
  return decoded;
}

std::size_t pnm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut) {
  const PnmHeader header = read_pnm_header(head, name, head_is_cut);
  return header.raster_offset + raster_bytes(header);
}

std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint8_t> image) {
  return encode(image, 255);
}

std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint16_t> image) {
  return encode(image, 65535);
}

} // namespace marsokhod::imaging::detail
