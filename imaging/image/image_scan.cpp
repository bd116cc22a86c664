// Scanning an image file strip by strip, so that its statistics never need the whole raster.

#include "marsokhod/imaging/image/image_scan.hpp"

#include "image/image_codec.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace marsokhod::imaging {
namespace {

using detail::RasterLayout;
using ScanVisitor = std::function<void(int, const ImageStrip&)>;

const char* format_name(detail::ImageFormat format) {
  switch (format) {
  case detail::ImageFormat::pgm:
    return "pgm";
  case detail::ImageFormat::ppm:
    return "ppm";
  case detail::ImageFormat::pfm:
    return "pfm";
  case detail::ImageFormat::png:
    break;
  }
  return "png";
}

/// The raster's bytes in order: first what the header window already holds, then the file.
class RasterSource {
public:
  RasterSource(std::span<const std::uint8_t> head, const RasterLayout& layout,
               detail::ImageFileReader& file)
      : head_(head.subspan(std::min(layout.raster_offset, head.size()))), file_(file),
        expected_(layout.raster_bytes()) {}

  /// Fills `out` entirely; ImageError, as read_image gives it, when the file ends first.
  void read(std::uint8_t* out, std::size_t length) {
    const std::size_t from_head = std::min(length, head_.size());
    std::memcpy(out, head_.data(), from_head);
    head_ = head_.subspan(from_head);
    std::size_t done = from_head;
    while (done < length) {
      const std::size_t got = file_.read_next(out + done, length - done);
      if (got == 0)
        detail::fail(file_.name(), fmt::format("truncated pixel data: expected {} bytes, found {}",
                                               expected_, consumed_ + done));
      done += got;
    }
    consumed_ += length;
  }

private:
  std::span<const std::uint8_t> head_;
  detail::ImageFileReader& file_;
  std::size_t expected_;
  std::size_t consumed_ = 0;
};

int strip_rows(const RasterLayout& layout) {
  const std::size_t rows = std::max<std::size_t>(1, kScanStripBytes / layout.row_bytes());
  return static_cast<int>(std::min<std::size_t>(rows, static_cast<std::size_t>(layout.height)));
}

template <class T>
void scan_pnm(RasterSource& source, const RasterLayout& layout, const std::string& name,
              const ScanVisitor& visit) {
  const int rows = strip_rows(layout);
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(rows) * layout.row_bytes());
  Image<T> strip(layout.width, rows, layout.channels);
  for (int top = 0; top < layout.height; top += rows) {
    const int count = std::min(rows, layout.height - top);
    const std::size_t samples = static_cast<std::size_t>(count) * layout.row_samples();
    source.read(raw.data(), samples * sizeof(T));
    detail::load_pnm_samples(raw.data(), samples,
                             static_cast<std::size_t>(top) * layout.row_samples(), layout,
                             strip.data(), name);
    visit(top, ImageView<const T>(strip).sub(0, 0, layout.width, count));
  }
}

void scan_pfm(RasterSource& source, const RasterLayout& layout, const ScanVisitor& visit) {
  const int rows = strip_rows(layout);
  std::vector<std::uint8_t> raw(layout.row_bytes());
  Image<float> strip(layout.width, rows, layout.channels);
  for (int done = 0; done < layout.height; done += rows) {
    const int count = std::min(rows, layout.height - done);
    // File rows run bottom up: the strip's last row is read first.
    for (int i = count - 1; i >= 0; --i) {
      source.read(raw.data(), raw.size());
      detail::load_pfm_row(raw.data(), layout, strip.row(i));
    }
    visit(layout.height - done - count,
          ImageView<const float>(strip).sub(0, 0, layout.width, count));
  }
}

ImageFileHeader header_of(const RasterLayout& layout) {
  return {format_name(layout.format), layout.width, layout.height, layout.channels, layout.maxval};
}

ImageFileHeader scan_whole_png(std::span<const std::uint8_t> head, detail::ImageFileReader& file,
                               const ScanVisitor& visit) {
  const detail::DecodedImage decoded = detail::decode_png_file(head, file);
  ImageFileHeader header{"png", 0, 0, 0, decoded.maxval};
  std::visit(
      [&](const auto& image) {
        header.width = image.width();
        header.height = image.height();
        header.channels = image.channels();
        visit(0, ImageStrip(image.view()));
      },
      decoded.pixels);
  return header;
}

} // namespace

ImageFileHeader scan_image(const std::filesystem::path& path, const ScanVisitor& visit) {
  detail::ImageFileReader file(path);
  const std::string& name = file.name();
  std::vector<std::uint8_t> head;
  file.read_up_to(head, detail::kImageHeaderWindow);
  const bool cut = head.size() < file.size();
  if (detail::starts_with(head, "\x89PNG"))
    return scan_whole_png(head, file, visit);
  if (detail::starts_with(head, "P5") || detail::starts_with(head, "P6")) {
    const RasterLayout layout = detail::pnm_layout(head, name, cut);
    RasterSource source(head, layout, file);
    if (layout.sample_bytes == 1)
      scan_pnm<std::uint8_t>(source, layout, name, visit);
    else
      scan_pnm<std::uint16_t>(source, layout, name, visit);
    return header_of(layout);
  }
  if (detail::starts_with(head, "Pf") || detail::starts_with(head, "PF")) {
    const RasterLayout layout = detail::pfm_layout(head, name, cut);
    RasterSource source(head, layout, file);
    scan_pfm(source, layout, visit);
    return header_of(layout);
  }
  // Anything else gets read_image's own message for it.
  (void)decode_image(head, name);
  detail::fail(name, "unknown image format");
}

} // namespace marsokhod::imaging
