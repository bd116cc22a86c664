// DecodedImage and the per-format decode and encode functions (private to the image room).
#pragma once

// Internal interface between the image dispatcher (image_io.cpp) and the per-format codecs.

#include "marsokhod/imaging/image/image_io.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace marsokhod::imaging::detail {

/// The container a decoded image came from.
enum class ImageFormat { pgm, ppm, png, pfm };

/// Pixels plus what the pixels alone cannot tell: where they came from and the largest value a
/// sample may take (PNM maxval, 255 or 65535 for PNG, 0 for float images).
struct DecodedImage {
  AnyImage pixels;
  ImageFormat format = ImageFormat::pgm;
  int maxval = 0;
};

/// Throws ImageError("<name>: <problem>").
[[noreturn]] void fail(std::string_view name, std::string_view problem);

/// Throws ImageError unless width and height are within 1..kMaxImageSide.
void check_image_size(std::string_view name, long long width, long long height);

DecodedImage decode_pnm(std::span<const std::uint8_t> bytes, std::string_view name);
DecodedImage decode_png(std::span<const std::uint8_t> bytes, std::string_view name);
DecodedImage decode_pfm(std::span<const std::uint8_t> bytes, std::string_view name);

/// Encoders return the whole file; the caller has already checked the channel count.
std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint8_t> image);
std::vector<std::uint8_t> encode_pnm(ImageView<const std::uint16_t> image);
std::vector<std::uint8_t> encode_png(ImageView<const std::uint8_t> image, std::string_view name);
std::vector<std::uint8_t> encode_png(ImageView<const std::uint16_t> image, std::string_view name);
std::vector<std::uint8_t> encode_pfm(ImageView<const float> image);

/// The whole content of a regular file; ImageError for a missing file, a directory, an empty
/// file or a read failure.
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path);

/// Writes through a temporary file in the same folder and renames it over `path`, so readers
/// never see a half-written file; ImageError when the folder is missing or the write fails.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

} // namespace marsokhod::imaging::detail
