// DecodedImage and the per-format decode and encode functions (private to the image room).
#pragma once

// Internal interface between the image dispatcher (image_io.cpp) and the per-format codecs.

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/io/files/input_file.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
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

/// Whether the file's first bytes are `prefix` (its magic number).
bool starts_with(std::span<const std::uint8_t> bytes, std::string_view prefix);

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

/// How many bytes of a file are read before its header tells how many more the image needs.
/// A PGM, PPM or PFM header (comments included) must end within them.
inline constexpr std::size_t kImageHeaderWindow = std::size_t{64} << 10;

/// An image file opened for reading in order, never more than asked: regular files only
/// (FIFOs and devices are refused without blocking), ImageError for a missing file, a
/// directory, an empty file or a read failure.
class ImageFileReader {
public:
  explicit ImageFileReader(const std::filesystem::path& path);

  const std::string& name() const { return name_; }
  /// The file's size when it was opened.
  std::uint64_t size() const { return file_.size(); }
  /// Appends the next bytes of the file to `bytes` until it holds `count` bytes or the file
  /// ends; `bytes` must hold exactly what was read so far.
  void read_up_to(std::vector<std::uint8_t>& bytes, std::size_t count);
  /// Reads `length` more bytes into `out`; how many there were (fewer at the end of the file).
  std::size_t read_next(std::uint8_t* out, std::size_t length);

private:
  std::string name_;
  io::InputFile file_;
  std::uint64_t position_ = 0;
};

/// Where a PGM, PPM or PFM file's raster lies and how its samples are stored.
struct RasterLayout {
  ImageFormat format = ImageFormat::pgm;
  int width = 0;
  int height = 0;
  int channels = 1;
  int maxval = 0;             ///< PNM; 0 for PFM
  bool little_endian = false; ///< PFM: a negative scale
  std::size_t raster_offset = 0;
  std::size_t sample_bytes = 1;

  std::size_t row_samples() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  }
  std::size_t row_bytes() const { return row_samples() * sample_bytes; }
  std::size_t raster_bytes() const { return row_bytes() * static_cast<std::size_t>(height); }
};

/// The layout a PGM/PPM or PFM header gives, from the file's first bytes `head`; ImageError for
/// a bad header. `head_is_cut`: the file goes on beyond `head`.
RasterLayout pnm_layout(std::span<const std::uint8_t> head, std::string_view name,
                        bool head_is_cut = false);
RasterLayout pfm_layout(std::span<const std::uint8_t> head, std::string_view name,
                        bool head_is_cut = false);

/// Converts `count` raw big-endian PNM samples, the first being sample `first` of the raster, to
/// `out`; ImageError naming the pixel of a sample above maxval.
void load_pnm_samples(const std::uint8_t* raw, std::size_t count, std::size_t first,
                      const RasterLayout& layout, std::uint8_t* out, std::string_view name);
void load_pnm_samples(const std::uint8_t* raw, std::size_t count, std::size_t first,
                      const RasterLayout& layout, std::uint16_t* out, std::string_view name);

/// One PFM row of raw bytes to floats in the byte order of the layout.
void load_pfm_row(const std::uint8_t* raw, const RasterLayout& layout, float* out);

/// Bytes a PGM/PPM (pnm) or PFM file needs, header plus raster, from its first bytes `head`.
/// `head_is_cut`: the file goes on beyond `head`, so a header running to its end is too long.
std::size_t pnm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut);
std::size_t pfm_file_extent(std::span<const std::uint8_t> head, std::string_view name,
                            bool head_is_cut);

/// A PNG streamed from `file`, whose first bytes `head` were read already: libpng is fed only
/// what it asks for, and at most what the header's image can need.
DecodedImage decode_png_file(std::span<const std::uint8_t> head, ImageFileReader& file);

/// Writes through a temporary file in the same folder and renames it over `path`, so readers
/// never see a half-written file; ImageError when the folder is missing or the write fails.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

} // namespace marsokhod::imaging::detail
