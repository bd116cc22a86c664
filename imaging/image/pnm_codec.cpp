// Binary PGM (P5) and PPM (P6), 8 bit (maxval 1..255) and 16 bit big endian (256..65535).

#include "image/header_scanner.hpp"
#include "image/image_codec.hpp"

#include <fmt/format.h>

namespace marsokhod::imaging::detail {
namespace {

template <class T>
void load_samples(const std::uint8_t* raw, std::size_t count, std::size_t first,
                  const RasterLayout& layout, T* out, std::string_view name) {
  for (std::size_t i = 0; i < count; ++i) {
    unsigned value = raw[i * sizeof(T)];
    if constexpr (sizeof(T) == 2)
      value = (value << 8) | raw[i * 2 + 1];
    if (value > static_cast<unsigned>(layout.maxval)) {
      const std::size_t pixel = (first + i) / static_cast<std::size_t>(layout.channels);
      fail(name, fmt::format("sample value {} exceeds maxval {} at pixel ({}, {})", value,
                             layout.maxval, pixel % static_cast<std::size_t>(layout.width),
                             pixel / static_cast<std::size_t>(layout.width)));
    }
    out[i] = static_cast<T>(value);
  }
}

template <class T>
Image<T> read_raster(std::span<const std::uint8_t> raster, const RasterLayout& layout,
                     std::string_view name) {
  Image<T> image(layout.width, layout.height, layout.channels);
  load_samples(raster.data(), image.size(), 0, layout, image.data(), name);
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

RasterLayout pnm_layout(std::span<const std::uint8_t> head, std::string_view name,
                        bool head_is_cut) {
  RasterLayout layout;
  if (head.size() < 2 || head[0] != 'P' || (head[1] != '5' && head[1] != '6'))
    fail(name, "not a binary PGM/PPM file (magic P5 or P6 expected)");
  if (head[1] == '6') {
    layout.format = ImageFormat::ppm;
    layout.channels = 3;
  }
  HeaderScanner scanner(head.subspan(2), name, /*comments=*/true, head_is_cut);
  scanner.read_size(layout.width, layout.height);
  layout.maxval = scanner.read_number("maxval", 1, 65535);
  scanner.expect_single_whitespace("maxval");
  layout.raster_offset = 2 + scanner.position();
  layout.sample_bytes = layout.maxval > 255 ? 2 : 1;
  return layout;
}

void load_pnm_samples(const std::uint8_t* raw, std::size_t count, std::size_t first,
                      const RasterLayout& layout, std::uint8_t* out, std::string_view name) {
  load_samples(raw, count, first, layout, out, name);
}

void load_pnm_samples(const std::uint8_t* raw, std::size_t count, std::size_t first,
                      const RasterLayout& layout, std::uint16_t* out, std::string_view name) {
  load_samples(raw, count, first, layout, out, name);
}

DecodedImage decode_pnm(std::span<const std::uint8_t> bytes, std::string_view name) {
  const RasterLayout layout = pnm_layout(bytes, name);
  const std::size_t expected = layout.raster_bytes();
  const std::span<const std::uint8_t> raster = bytes.subspan(layout.raster_offset);
  // Checked before allocating, so a lying header cannot make us reserve gigabytes.
  if (raster.size() < expected)
    fail(name,
         fmt::format("truncated pixel data: expected {} bytes, found {}", expected, raster.size()));
  DecodedImage decoded;
  decoded.format = layout.format;
  decoded.maxval = layout.maxval;
  if (layout.sample_bytes == 1)
    decoded.pixels = read_raster<std::uint8_t>(raster, layout, name);
  else
    decoded.pixels = read_raster<std::uint16_t>(raster, layout, name);
  return decoded;
}

std::size_t pnm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut) {
  const RasterLayout layout = pnm_layout(head, name, head_is_cut);
  return layout.raster_offset + layout.raster_bytes();
}

std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint8_t> image) {
  return encode(image, 255);
}

std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint16_t> image) {
  return encode(image, 65535);
}

} // namespace marsokhod::imaging::detail
