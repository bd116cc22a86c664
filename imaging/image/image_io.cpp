// Image files: reading chosen by content, writing chosen by extension, grey conversion.

#include "marsokhod/imaging/image/image_io.hpp"

#include "image/image_codec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace marsokhod::imaging {
namespace {

using detail::DecodedImage;
using detail::fail;
using detail::starts_with;

// The content decides the format, never the name: a mislabelled file still reads correctly.
DecodedImage decode_any(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (bytes.empty())
    fail(name, "empty file");
  if (starts_with(bytes, "\x89PNG"))
    return detail::decode_png(bytes, name);
  if (starts_with(bytes, "P5") || starts_with(bytes, "P6"))
    return detail::decode_pnm(bytes, name);
  if (starts_with(bytes, "Pf") || starts_with(bytes, "PF"))
    return detail::decode_pfm(bytes, name);
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')
    fail(name, fmt::format("unsupported netpbm format P{} (only binary P5 and P6 are read)",
                           static_cast<char>(bytes[1])));
  fail(name, "unknown image format (expected PGM/PPM P5/P6, PNG or PFM Pf/PF)");
}

// Reads only what the header says the image needs: the first kImageHeaderWindow bytes, then
// for PGM, PPM and PFM the rest of the raster, for PNG what libpng asks for. Bytes after the
// image are neither read nor kept.
DecodedImage decode_file(const std::filesystem::path& path) {
  detail::ImageFileReader file(path);
  const std::string& name = file.name();
  std::vector<std::uint8_t> bytes;
  file.read_up_to(bytes, detail::kImageHeaderWindow);
  const bool cut = bytes.size() < file.size();
  if (starts_with(bytes, "\x89PNG"))
    return detail::decode_png_file(bytes, file);
  if (starts_with(bytes, "P5") || starts_with(bytes, "P6")) {
    file.read_up_to(bytes, detail::pnm_file_extent(bytes, name, cut));
    return detail::decode_pnm(bytes, name);
  }
  if (starts_with(bytes, "Pf") || starts_with(bytes, "PF")) {
    file.read_up_to(bytes, detail::pfm_file_extent(bytes, name, cut));
    return detail::decode_pfm(bytes, name);
  }
  return decode_any(bytes, name);
}

std::uint8_t to_8_bit(unsigned sample, unsigned maxval) {
  return static_cast<std::uint8_t>((sample * 255U + maxval / 2) / maxval);
}

template <class T>
Image<std::uint8_t> to_gray8(const Image<T>& image, int maxval) {
  const auto max = static_cast<unsigned>(maxval);
  Image<std::uint8_t> grey(image.width(), image.height(), 1);
  for (int y = 0; y < image.height(); ++y) {
    const T* source = image.row(y);
    std::uint8_t* target = grey.row(y);
    for (int x = 0; x < image.width(); ++x) {
      if (image.channels() == 1) {
        target[x] = to_8_bit(source[x], max);
        continue;
      }
      const T* rgb = source + 3 * x;
      // Rec. 601 luma with weights in thousandths, rounded.
      const unsigned luma = 299U * to_8_bit(rgb[0], max) + 587U * to_8_bit(rgb[1], max) +
                            114U * to_8_bit(rgb[2], max);
      target[x] = static_cast<std::uint8_t>((luma + 500U) / 1000U);
    }
  }
  return grey;
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

void check_writable_shape(std::string_view name, int width, int height, int channels) {
  if (width == 0 || height == 0)
    fail(name, fmt::format("cannot write an empty image ({}x{})", width, height));
  if (channels != 1 && channels != 3)
    fail(name, fmt::format("cannot write a {}-channel image (1 grey or 3 RGB)", channels));
}

template <class T>
void write_integer_image(const std::filesystem::path& path, ImageView<const T> image) {
  const std::string name = path.string();
  check_writable_shape(name, image.width(), image.height(), image.channels());
  const std::string extension = lower_extension(path);
  const bool grey = image.channels() == 1;
  if (extension == ".png")
    return detail::write_file_atomically(path, detail::encode_png(image, name));
  if ((extension == ".pgm" && grey) || (extension == ".ppm" && !grey))
    return detail::write_file_atomically(path, detail::encode_pnm(image));
  if (extension == ".pgm" || extension == ".ppm")
    fail(name, fmt::format("a {} image goes to {}, not {}", grey ? "grey" : "3-channel RGB",
                           grey ? ".pgm" : ".ppm", extension));
  if (extension == ".pfm")
    fail(name, fmt::format("PFM holds float pixels, not {}-bit integers", 8 * sizeof(T)));
  fail(name, fmt::format("unsupported extension '{}' (use .pgm, .ppm, .png or .pfm)", extension));
}

} // namespace

AnyImage decode_image(std::span<const std::uint8_t> bytes, std::string_view name) {
  return decode_any(bytes, name).pixels;
}

AnyImage read_image(const std::filesystem::path& path) {
  return decode_file(path).pixels;
}

Image<std::uint8_t> read_gray8(const std::filesystem::path& path) {
  const std::string name = path.string();
  DecodedImage decoded = decode_file(path);
  if (auto* image = std::get_if<Image<std::uint8_t>>(&decoded.pixels)) {
    if (image->channels() == 1 && decoded.maxval == 255)
      return std::move(*image);
    return to_gray8(*image, decoded.maxval);
  }
  if (auto* image = std::get_if<Image<std::uint16_t>>(&decoded.pixels))
    return to_gray8(*image, decoded.maxval);
  fail(name, "float pixels (PFM) have no implied grey range; read them with read_pfm");
}

Image<float> read_pfm(const std::filesystem::path& path) {
  const std::string name = path.string();
  DecodedImage decoded = decode_file(path);
  auto* image = std::get_if<Image<float>>(&decoded.pixels);
  if (image == nullptr)
    fail(name, "expected a one-channel PFM (Pf), found an integer image");
  if (image->channels() != 1)
    fail(name, "expected a one-channel PFM (Pf), found a 3-channel PFM (PF)");
  return std::move(*image);
}

void write_image(const std::filesystem::path& path, ImageView<const std::uint8_t> image) {
  write_integer_image(path, image);
}

void write_image(const std::filesystem::path& path, ImageView<const std::uint16_t> image) {
  write_integer_image(path, image);
}

void write_image(const std::filesystem::path& path, ImageView<const float> image) {
  const std::string name = path.string();
  check_writable_shape(name, image.width(), image.height(), image.channels());
  const std::string extension = lower_extension(path);
  if (extension == ".pfm")
    return detail::write_file_atomically(path, detail::encode_pfm(image));
  if (extension == ".pgm" || extension == ".ppm" || extension == ".png")
    fail(name,
         fmt::format("float pixels go to .pfm, not {} (no implied integer range)", extension));
  fail(name, fmt::format("unsupported extension '{}' (use .pfm for float pixels)", extension));
}

} // namespace marsokhod::imaging
