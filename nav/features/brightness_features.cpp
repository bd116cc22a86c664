// Brightness features: census and rank transforms of every pixel of an image.

#include "marsokhod/nav/features/brightness_features.hpp"

#include "features/census_rows.hpp"
#include "lanes/bit_count.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <cstdlib>

namespace marsokhod::nav {
namespace {

// Rows of the image with the border repeated, so the transforms need no bounds checks.
class PaddedRows {
public:
  PaddedRows(imaging::ImageView<const std::uint8_t> image, int radius,
             std::pmr::memory_resource* memory)
      : image_(image), radius_(radius), width_(image.width() + 2 * radius),
        rows_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(2 * radius + 1), 0,
              memory) {}

  // Loads rows y - radius .. y + radius (clamped) into the padded window.
  void load(int y) {
    for (int dy = -radius_; dy <= radius_; ++dy) {
      const int source_y = std::clamp(y + dy, 0, image_.height() - 1);
      const std::uint8_t* source = image_.row(source_y);
      std::uint8_t* target = row(dy);
      std::copy(source, source + image_.width(), target + radius_);
      std::fill(target, target + radius_, source[0]);
      std::fill(target + radius_ + image_.width(), target + width_, source[image_.width() - 1]);
    }
  }
  // Row y + dy of the last load, indexed by x + radius.
  const std::uint8_t* row(int dy) const {
    return rows_.data() + static_cast<std::ptrdiff_t>(dy + radius_) * width_;
  }

private:
  std::uint8_t* row(int dy) {
    return rows_.data() + static_cast<std::ptrdiff_t>(dy + radius_) * width_;
  }

  imaging::ImageView<const std::uint8_t> image_;
  int radius_;
  int width_;
  std::pmr::vector<std::uint8_t> rows_;
};

// Bit i is set when neighbour i of the (2r+1)^2 window (raster order, centre skipped) is darker.
// The bits are gathered eight neighbours at a time in bytes, one pass over the row per
// neighbour, so the inner loops vectorise.
template <int Radius>
void census_row(const PaddedRows& rows, int width, std::uint8_t* byte, std::uint32_t* out) {
  const std::uint8_t* centre = rows.row(0) + Radius;
  std::fill(out, out + width, 0U);
  int in_byte = 0;
  std::fill(byte, byte + width, std::uint8_t{0});
  for (int dy = -Radius; dy <= Radius; ++dy) {
    for (int dx = -Radius; dx <= Radius; ++dx) {
      if (dx == 0 && dy == 0)
        continue;
      const std::uint8_t* neighbour = rows.row(dy) + Radius + dx;
      for (int x = 0; x < width; ++x)
        byte[x] = static_cast<std::uint8_t>((byte[x] << 1) | (neighbour[x] < centre[x] ? 1 : 0));
      if (++in_byte < 8)
        continue;
      for (int x = 0; x < width; ++x)
        out[x] = (out[x] << 8) | byte[x];
      in_byte = 0;
    }
  }
}

void rank_row(const PaddedRows& rows, int width, std::uint32_t* out) {
  const std::uint8_t* centre = rows.row(0) + 2;
  std::fill(out, out + width, 0U);
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const std::uint8_t* neighbour = rows.row(dy) + 2 + dx;
      for (int x = 0; x < width; ++x)
        out[x] += static_cast<std::uint32_t>(neighbour[x] < centre[x]);
    }
}

int radius_of(FeatureKind kind) {
  return kind == FeatureKind::census3x3 ? 1 : 2;
}

} // namespace

std::string_view to_string(FeatureKind kind) {
  switch (kind) {
  case FeatureKind::census3x3:
    return "census3x3";
  case FeatureKind::census5x5:
    return "census5x5";
  case FeatureKind::rank5x5:
    return "rank5x5";
  }
  return "unknown";
}

std::optional<FeatureKind> parse_feature_kind(std::string_view text) {
  for (FeatureKind kind : {FeatureKind::census3x3, FeatureKind::census5x5, FeatureKind::rank5x5})
    if (text == to_string(kind))
      return kind;
  return std::nullopt;
}

int feature_distance(FeatureKind kind, std::uint32_t a, std::uint32_t b) {
  if (kind == FeatureKind::rank5x5)
    return std::abs(static_cast<int>(a) - static_cast<int>(b));
  return detail::bit_count(a ^ b);
}

template <class Meter>
imaging::Image<std::uint32_t> brightness_features(imaging::ImageView<const std::uint8_t> image,
                                                  FeatureKind kind, Meter& meter,
                                                  std::pmr::memory_resource* memory) {
  imaging::Image<std::uint32_t> features(image.width(), image.height(), 1, 0, memory);
  if (image.empty())
    return features;
  PaddedRows rows(image, radius_of(kind), memory);
  std::pmr::vector<std::uint8_t> bytes(static_cast<std::size_t>(image.width()), 0, memory);
  for (int y = 0; y < image.height(); ++y) {
    rows.load(y);
    std::uint32_t* out = features.row(y);
    if (kind == FeatureKind::census3x3) {
      const PaddedRows& loaded = rows;
      detail::census3x3_row(loaded.row(-1) + 1, loaded.row(0) + 1, loaded.row(1) + 1, image.width(),
                            bytes.data());
      std::copy(bytes.begin(), bytes.end(), out);
    } else if (kind == FeatureKind::census5x5)
      census_row<2>(rows, image.width(), bytes.data(), out);
    else
      rank_row(rows, image.width(), out);
    detail::report(meter, Work::feature_pixel, static_cast<std::uint64_t>(image.width()));
  }
  return features;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template imaging::Image<std::uint32_t> brightness_features<M>(                                   \
      imaging::ImageView<const std::uint8_t>, FeatureKind, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
