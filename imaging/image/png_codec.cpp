// The PNG codec: decoding and encoding 8- and 16-bit PNG files through libpng.
// PNG through libpng. libpng reports errors by longjmp, so every call that may fail runs in a
// small function holding only trivially destructible locals; owning C++ objects (the image,
// the row table, the libpng structs' guard) live in the caller and are never jumped over.

#include "image/image_codec.hpp"

#include <fmt/format.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <bit>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace marsokhod::imaging::detail {
namespace {

// Plain data shared with libpng's callbacks.
struct PngIo {
  const std::uint8_t* input = nullptr;
  std::size_t input_size = 0;
  std::size_t input_offset = 0;
  ImageFileReader* file = nullptr; ///< where the bytes after `input` come from, if anywhere
  std::uint64_t fed = 0;           ///< bytes given to libpng so far
  std::uint64_t feed_limit = ~std::uint64_t{0};
  std::vector<std::uint8_t>* output = nullptr;
  char message[160] = {};
  char first_warning[160] = {};
};

// Deflate cannot expand data by more than about 1032:1; a header promising more pixels than
// that is damaged, and is rejected before the pixel buffer is allocated.
constexpr std::uint64_t kMaxDeflateRatio = 1032;

void on_error(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", message);
  png_longjmp(png, 1);
}

// Warnings describe problems libpng recovered from (e.g. a bad ancillary chunk), so they are
// not printed; the first one is kept because it often explains a later error.
void on_warning(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  if (io->first_warning[0] == '\0')
    std::snprintf(io->first_warning, sizeof io->first_warning, "%s", message);
}

std::string corrupt(const PngIo& io) {
  if (io.first_warning[0] == '\0')
    return fmt::format("corrupt PNG: {}", io.message);
  return fmt::format("corrupt PNG: {} ({})", io.message, io.first_warning);
}

// Reads the file in its own frame, so that an ImageError never crosses libpng's frames.
bool read_file(ImageFileReader& file, png_bytep out, png_size_t length, char* message,
               std::size_t message_size) {
  try {
    return file.read_next(out, length) == length;
  } catch (const std::exception& error) {
    std::snprintf(message, message_size, "%s", error.what());
    return false;
  }
}

void read_callback(png_structp png, png_bytep out, png_size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (length > io->feed_limit - io->fed)
    png_error(png, "more data than the image in its header can need");
  io->fed += length;
  const std::size_t buffered = std::min(length, io->input_size - io->input_offset);
  std::memcpy(out, io->input + io->input_offset, buffered);
  io->input_offset += buffered;
  if (buffered == length)
    return;
  char message[160] = "truncated PNG data";
  if (io->file == nullptr ||
      !read_file(*io->file, out + buffered, length - buffered, message, sizeof message))
    png_error(png, message);
}

bool append(std::vector<std::uint8_t>& bytes, const std::uint8_t* data, std::size_t length) {
  try {
    bytes.insert(bytes.end(), data, data + length);
    return true;
  } catch (...) {
    return false;
  }
}

void write_callback(png_structp png, png_bytep data, png_size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (!append(*io->output, data, length))
    png_error(png, "out of memory");
}

void flush_callback(png_structp) {}

struct PngHeader {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int bit_depth = 0;
  int colour_type = 0;
  int file_channels = 0;
};

bool read_header(png_structp png, png_infop info, PngHeader* header) {
  if (setjmp(png_jmpbuf(png)))
    return false;
  png_read_info(png, info);
  header->width = png_get_image_width(png, info);
  header->height = png_get_image_height(png, info);
  header->bit_depth = png_get_bit_depth(png, info);
  header->colour_type = png_get_color_type(png, info);
  header->file_channels = png_get_channels(png, info);
  return true;
}

// Asks libpng for 8- or 16-bit grey or RGB in host byte order, without alpha.
bool configure_read(png_structp png, png_infop info, const PngHeader* header) {
  if (setjmp(png_jmpbuf(png)))
    return false;
  if (header->colour_type == PNG_COLOR_TYPE_PALETTE)
    png_set_palette_to_rgb(png);
  if (header->colour_type == PNG_COLOR_TYPE_GRAY && header->bit_depth < 8)
    png_set_expand_gray_1_2_4_to_8(png);
  png_set_strip_alpha(png);
  if (header->bit_depth == 16 && std::endian::native == std::endian::little)
    png_set_swap(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)))
    return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

class ReadGuard {
public:
  ReadGuard(png_structp png, png_infop info) : png_(png), info_(info) {}
  ReadGuard(const ReadGuard&) = delete;
  ReadGuard& operator=(const ReadGuard&) = delete;
  ~ReadGuard() { png_destroy_read_struct(&png_, &info_, nullptr); }

private:
  png_structp png_;
  png_infop info_;
};

std::uint64_t raw_bytes(const PngHeader& header) {
  const std::uint64_t row_bits = std::uint64_t{header.width} *
                                 static_cast<std::uint64_t>(header.bit_depth) *
                                 static_cast<std::uint64_t>(header.file_channels);
  return (row_bits + 7) / 8 * header.height;
}

void check_plausible_size(const PngHeader& header, std::uint64_t file_size, std::string_view name) {
  if (raw_bytes(header) > kMaxDeflateRatio * file_size)
    fail(name, fmt::format("corrupt PNG: {} bytes cannot hold {}x{} pixels", file_size,
                           header.width, header.height));
}

template <class T>
Image<T> read_pixels(png_structp png, png_infop info, PngIo& io, std::string_view name) {
  const int width = static_cast<int>(png_get_image_width(png, info));
  const int height = static_cast<int>(png_get_image_height(png, info));
  const int channels = png_get_channels(png, info);
  if (channels != 1 && channels != 3)
    fail(name, fmt::format("unsupported PNG layout ({} channels after conversion)", channels));
  const std::size_t row_bytes =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(channels) * sizeof(T);
  if (png_get_rowbytes(png, info) != row_bytes)
    fail(name, "unsupported PNG layout (unexpected row size after conversion)");
  Image<T> image(width, height, channels);
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    rows[static_cast<std::size_t>(y)] = reinterpret_cast<png_bytep>(image.row(y));
  if (!read_rows(png, info, rows.data()))
    fail(name, corrupt(io));
  return image;
}

// Deflate's stored blocks add 5 bytes per 65535, and each chunk 12 bytes; twice the raw size
// (one filter byte per row included) plus room for ancillary chunks is more than any honest
// file holds for its image, and bounds what a streamed file can make us read.
constexpr std::uint64_t kAncillaryAllowance = std::uint64_t{16} << 20;

std::uint64_t feed_limit(const PngHeader& header) {
  return 2 * (raw_bytes(header) + header.height) + kAncillaryAllowance;
}

std::uint32_t big_endian_at(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i)
    value = (value << 8) | bytes[offset + i];
  return value;
}

// The same bound before libpng has read anything: png_read_info reads every chunk before the
// first IDAT, so the limit must hold from the first byte. It is taken from the IHDR, which the
// PNG specification places right after the signature; libpng checks that chunk itself.
std::uint64_t initial_feed_limit(std::span<const std::uint8_t> head) {
  constexpr std::size_t kIhdrEnd = 8 + 8 + 13;
  PngHeader header;
  header.width = kMaxImageSide;
  header.height = kMaxImageSide;
  header.bit_depth = 16;
  header.file_channels = 4;
  if (head.size() >= kIhdrEnd && std::equal(head.begin() + 12, head.begin() + 16, "IHDR")) {
    header.width = std::min<png_uint_32>(big_endian_at(head, 16), kMaxImageSide);
    header.height = std::min<png_uint_32>(big_endian_at(head, 20), kMaxImageSide);
    header.bit_depth = std::min<int>(head[24], 16);
    // Grey, -, RGB, palette, grey + alpha, -, RGB + alpha.
    constexpr std::array<int, 7> kChannels = {1, 4, 3, 1, 2, 4, 4};
    header.file_channels = head[25] < kChannels.size() ? kChannels[head[25]] : 4;
  }
  return feed_limit(header);
}

DecodedImage decode(std::span<const std::uint8_t> bytes, ImageFileReader* file,
                    std::string_view name) {
  PngIo io;
  io.input = bytes.data();
  io.input_size = bytes.size();
  io.file = file;
  io.feed_limit = initial_feed_limit(bytes);
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &io, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  ReadGuard guard(png, info);
  if (!png || !info)
    fail(name, "out of memory while starting the PNG reader");
  png_set_read_fn(png, &io, read_callback);

  PngHeader header;
  if (!read_header(png, info, &header))
    fail(name, corrupt(io));
  check_image_size(name, header.width, header.height);
  check_plausible_size(header, file != nullptr ? file->size() : bytes.size(), name);
  io.feed_limit = feed_limit(header);
  if (!configure_read(png, info, &header))
    fail(name, corrupt(io));

  DecodedImage decoded;
  decoded.format = ImageFormat::png;
  if (png_get_bit_depth(png, info) == 16) {
    decoded.pixels = read_pixels<std::uint16_t>(png, info, io, name);
    decoded.maxval = 65535;
  } else {
    decoded.pixels = read_pixels<std::uint8_t>(png, info, io, name);
    decoded.maxval = 255;
  }
  return decoded;
}

} // namespace

DecodedImage decode_png(std::span<const std::uint8_t> bytes, std::string_view name) {
  return decode(bytes, nullptr, name);
}

DecodedImage decode_png_file(std::span<const std::uint8_t> head, ImageFileReader& file) {
  return decode(head, &file, file.name());
}

namespace {

class WriteGuard {
public:
  WriteGuard(png_structp png, png_infop info) : png_(png), info_(info) {}
  WriteGuard(const WriteGuard&) = delete;
  WriteGuard& operator=(const WriteGuard&) = delete;
  ~WriteGuard() { png_destroy_write_struct(&png_, &info_); }

private:
  png_structp png_;
  png_infop info_;
};

bool write_all(png_structp png, png_infop info, png_uint_32 width, png_uint_32 height,
               int bit_depth, int colour_type, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)))
    return false;
  png_set_IHDR(png, info, width, height, bit_depth, colour_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (bit_depth == 16 && std::endian::native == std::endian::little)
    png_set_swap(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

template <class T>
std::vector<std::uint8_t> encode(ImageView<const T> image, std::string_view name) {
  std::vector<std::uint8_t> bytes;
  PngIo io;
  io.output = &bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  WriteGuard guard(png, info);
  if (!png || !info)
    fail(name, "out of memory while starting the PNG writer");
  png_set_write_fn(png, &io, write_callback, flush_callback);

  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y)
    rows[static_cast<std::size_t>(y)] =
        reinterpret_cast<png_bytep>(const_cast<T*>(image.row(y))); // libpng only reads them
  const int colour_type = image.channels() == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB;
  if (!write_all(png, info, static_cast<png_uint_32>(image.width()),
                 static_cast<png_uint_32>(image.height()), 8 * static_cast<int>(sizeof(T)),
                 colour_type, rows.data()))
    fail(name, fmt::format("cannot encode PNG: {}", io.message));
  return bytes;
}

} // namespace

std::vector<std::uint8_t> encode_png(ImageView<const std::uint8_t> image, std::string_view name) {
  return encode(image, name);
}

std::vector<std::uint8_t> encode_png(ImageView<const std::uint16_t> image, std::string_view name) {
  return encode(image, name);
}

} // namespace marsokhod::imaging::detail
