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
  // from_chars takes no '+', and one '+' may only be followed by the number itself.
  if (first != last && *first == '+')
    ++first;
  if (first != token.data() && first != last && (*first == '-' || *first == '+'))
    fail(name, fmt::format("scale '{}' is not a finite decimal number", token));
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

} // namespace

RasterLayout pfm_layout(std::span<const std::uint8_t> head, std::string_view name,
                        bool head_is_cut) {
  if (head.size() < 2 || head[0] != 'P' || (head[1] != 'f' && head[1] != 'F'))
    fail(name, "not a PFM file (magic Pf or PF expected)");
  RasterLayout layout;
  layout.format = ImageFormat::pfm;
  layout.channels = head[1] == 'F' ? 3 : 1;
  layout.sample_bytes = sizeof(float);
  HeaderScanner scanner(head.subspan(2), name, /*comments=*/false, head_is_cut);
  scanner.read_size(layout.width, layout.height);
  layout.little_endian = parse_scale(scanner.read_token("scale", kMaxScaleLength), name) < 0.0;
  scanner.expect_single_whitespace("the scale");
  layout.raster_offset = 2 + scanner.position();
  return layout;
}

void load_pfm_row(const std::uint8_t* raw, const RasterLayout& layout, float* out) {
  const std::size_t samples = layout.row_samples();
  for (std::size_t i = 0; i < samples; ++i)
    out[i] = load_float(raw + i * 4, layout.little_endian);
}

std::size_t pfm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut) {
  const RasterLayout layout = pfm_layout(head, name, head_is_cut);
  return layout.raster_offset + layout.raster_bytes();
}

DecodedImage decode_pfm(std::span<const std::uint8_t> bytes, std::string_view name) {
  const RasterLayout layout = pfm_layout(bytes, name);
  const std::span<const std::uint8_t> raster = bytes.subspan(layout.raster_offset);
  const std::size_t expected = layout.raster_bytes();
  if (raster.size() < expected)
    fail(name,
         fmt::format("truncated pixel data: expected {} bytes, found {}", expected, raster.size()));
  Image<float> image(layout.width, layout.height, layout.channels);
  for (int file_row = 0; file_row < layout.height; ++file_row)
    load_pfm_row(raster.data() + static_cast<std::size_t>(file_row) * layout.row_bytes(), layout,
                 image.row(layout.height - 1 - file_row));
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
