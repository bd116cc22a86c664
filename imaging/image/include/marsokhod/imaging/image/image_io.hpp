// Image files: reading and writing PGM/PPM, PNG and PFM, and ImageError for bad ones.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

namespace marsokhod::imaging {

/// A file or buffer that could not be read or written as an image; what() names the file and
/// the problem (e.g. "left.pgm: truncated pixel data: expected 65536 bytes, found 1200").
class ImageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Pixels as they were stored: 8-bit or 16-bit integers (PGM, PPM, PNG) or 32-bit floats (PFM).
/// Channels are 1 (grey) or 3 (RGB); PNG alpha is dropped and palette images are expanded.
using AnyImage = std::variant<Image<std::uint8_t>, Image<std::uint16_t>, Image<float>>;

/// Reads a PGM/PPM (P5/P6, maxval 1..65535), PNG or PFM (PF/Pf) file, chosen by its magic bytes,
/// never by the extension. PFM follows the Middlebury convention: a negative scale means little
/// endian, rows are stored bottom to top (returned top to bottom), +inf means unknown.
AnyImage read_image(const std::filesystem::path& path);

/// Same as read_image on bytes already in memory; `name` is used in error messages.
AnyImage decode_image(std::span<const std::uint8_t> bytes, std::string_view name);

/// Reads any supported file as one 8-bit grey channel: RGB is converted with Rec. 601 luma,
/// 16-bit samples are rescaled from their maxval; float images are an error (no implied range).
Image<std::uint8_t> read_gray8(const std::filesystem::path& path);

/// Reads a PFM file with one channel (Pf); anything else is an error naming the file.
Image<float> read_pfm(const std::filesystem::path& path);

/// Writers pick the format from the extension: .pgm/.ppm (P5/P6; 16-bit images are written
/// big-endian with maxval 65535), .png (8 or 16 bit), .pfm (float, little endian, bottom-up).
/// Grey images go to .pgm, RGB to .ppm; a mismatch is an ImageError.
void write_image(const std::filesystem::path& path, ImageView<const std::uint8_t> image);
void write_image(const std::filesystem::path& path, ImageView<const std::uint16_t> image);
void write_image(const std::filesystem::path& path, ImageView<const float> image);

} // namespace marsokhod::imaging
