// Scanning an image file strip by strip: its header and pixels without holding the whole image.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <variant>

namespace marsokhod::imaging {

/// What an image file's header says of its pixels.
struct ImageFileHeader {
  std::string format; ///< the container its magic bytes name: pgm, ppm, pfm, png
  int width = 0;
  int height = 0;
  int channels = 0;
  int maxval = 0; ///< largest sample value: PNM maxval, 255 or 65535 for PNG, 0 for PFM
};

/// Consecutive whole rows of a scanned image, in the type they are stored in.
using ImageStrip = std::variant<ImageView<const std::uint8_t>, ImageView<const std::uint16_t>,
                                ImageView<const float>>;

/// Pixel bytes a scan holds at once for PGM, PPM and PFM files (one row at least).
inline constexpr std::size_t kScanStripBytes = std::size_t{4} << 20;

/// Reads an image file as read_image does (same checks, same ImageError for a bad file) but
/// hands its pixels to `visit` in strips of rows, `first_row` being the strip's top row, so that
/// the memory a PGM, PPM or PFM file takes is about kScanStripBytes however large the image.
/// Strips arrive in the file's order: top down, or bottom up for PFM. A PNG is decoded whole
/// and visited as one strip. Returns the header.
ImageFileHeader scan_image(const std::filesystem::path& path,
                           const std::function<void(int first_row, const ImageStrip&)>& visit);

} // namespace marsokhod::imaging
