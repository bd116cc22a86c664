// The PFM codec: decoding and encoding float images the Middlebury way.
// PFM as used by the Middlebury stereo benchmark: "Pf" (grey) or "PF" (RGB), width, height, a
// scale whose sign gives the byte order (negative = little endian), then 32-bit floats with the
// bottom row first.

#include "image/header_scanner.hpp"
#include "image/image_codec.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>

namespace marsokhod::imaging::detail {
namespace {

constexpr std::size_t kMaxScaleLength = 64;

double parse_scale(const std::string& token, std::string_view name) {
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+')
    ++first;
  double scale = 0.0;
  const auto [end, error] = std::from_chars(first, last, scale);
  if (error != std::errc{} || end != last || !std::isfinite(scale))
    fail(name, fmt::format("scale '{}' is not a finite decimal number", token));
  if (scale == 0.0)
    fail(name, "scale 0: its sign must give the byte order (negative = little endian)");
  return scale;
}

float load_float(const std::uint8_t* bytes, bool little_endian) {
  std::uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t byte = bytes[little_endian ? 3 - i : i];
    bits = (bits << 8) | byte;
  }
  return std::bit_cast<float>(bits);
}

struct PfmHeader {
  int channels = 1;
  int width = 0;
  int height = 0;
  double scale = 0.0;
  std::size_t raster_offset = 0;

  std::size_t row_samples() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  }
  std::size_t raster_bytes() const {
    return row_samples() * static_cast<std::size_t>(height) * sizeof(float);
  }
};

PfmHeader read_pfm_header(std::span<const std::uint8_t> bytes, std::string_view name,
                          bool cut = false) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'f' && bytes[1] != 'F'))
    fail(name, "not a PFM file (magic Pf or PF expected)");
  PfmHeader header;
  header.channels = bytes[1] == 'F' ? 3 : 1;
  HeaderScanner scanner(bytes.subspan(2), name, /*comments=*/false, cut);
  scanner.skip_separator("the magic number");
  header.width = scanner.read_number("width", 1, kMaxImageSide);
  scanner.skip_separator("the width");
  header.height = scanner.read_number("height", 1, kMaxImageSide);
  scanner.skip_separator("the height");
  header.scale = parse_scale(scanner.read_token("scale", kMaxScaleLength), name);
  scanner.expect_single_whitespace("the scale");
  header.raster_offset = 2 + scanner.position();
  return header;
}

} // namespace

std::size_t pfm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut) {
  const PfmHeader header = read_pfm_header(head, name, head_is_cut);
  return header.raster_offset + header.raster_bytes();
}

DecodedImage decode_pfm(std::span<const std::uint8_t> bytes, std::string_view name) {
  const PfmHeader header = read_pfm_header(bytes, name);
  const int width = header.width;
  const int height = header.height;
  const int channels = header.channels;
  const double scale = header.scale;
  const std::span<const std::uint8_t> raster = bytes.subspan(header.raster_offset);
  const std::size_t row_samples = header.row_samples();
  const std::size_t expected = header.raster_bytes();
  if (raster.size() < expected)
    fail(name,
         fmt::format("truncated pixel data: expected {} bytes, found {}", expected, raster.size()));

  const bool little_endian = scale < 0.0;
  Image<float> image(width, height, channels);
  for (int file_row = 0; file_row < height; ++file_row) {
    const std::uint8_t* source =
        raster.data() + static_cast<std::size_t>(file_row) * row_samples * 4;
    float* target = image.row(height - 1 - file_row);
    for (std::size_t i = 0; i < row_samples; ++i)
      target[i] = load_float(source + i * 4, little_endian);
  }
  DecodedImage decoded;
  decoded.pixels = std::move(image);
  decoded.format = ImageFormat::pfm;
  return decoded;
}

std::vector<std::uint8_t> encode_pfm(ImageView<const float> image) {
  const char magic = image.channels() == 1 ? 'f' : 'F';
  const std::string header = fmt::format("P{}\n{} {}\n-1\n", magic, image.width(), image.height());
  std::vector<std::uint8_t> bytes(header.begin(), header.end());
  const std::size_t row_samples =
      static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.channels());
  bytes.reserve(bytes.size() + row_samples * 4 * static_cast<std::size_t>(image.height()));
  for (int y = image.height() - 1; y >= 0; --y) {
    const float* row = image.row(y);
    for (std::size_t i = 0; i < row_samples; ++i) {
      const std::uint32_t bits = std::bit_cast<std::uint32_t>(row[i]);
      for (int shift = 0; shift < 32; shift += 8)
        bytes.push_back(static_cast<std::uint8_t>((bits >> shift) & 0xff));
    }
  }
  return bytes;
}

} // namespace marsokhod::imaging::detail
