// What `marsokhod image info` says of an image: its container, size, sample type and values.

#include "navigation/image_description.hpp"

#include "marsokhod/imaging/image/image_scan.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <variant>

namespace marsokhod::apps {
namespace {

struct SampleStats {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  std::uint64_t finite = 0;
  std::uint64_t non_finite = 0;
};

template <class T>
void add_samples(imaging::ImageView<const T> strip, SampleStats& stats) {
  for (int y = 0; y < strip.height(); ++y) {
    const T* row = strip.row(y);
    const std::size_t samples =
        static_cast<std::size_t>(strip.width()) * static_cast<std::size_t>(strip.channels());
    for (std::size_t i = 0; i < samples; ++i) {
      const double value = static_cast<double>(row[i]);
      if (!std::isfinite(value)) {
        ++stats.non_finite;
        continue;
      }
      stats.min = std::min(stats.min, value);
      stats.max = std::max(stats.max, value);
      stats.sum += value;
      ++stats.finite;
    }
  }
}

template <class T>
constexpr const char* sample_type() {
  if constexpr (std::is_same_v<T, float>)
    return "float32";
  else if constexpr (std::is_same_v<T, std::uint16_t>)
    return "uint16";
  else
    return "uint8";
}

} // namespace

ImageDescription describe_image_file(const std::string& file) {
  SampleStats stats;
  ImageDescription d;
  const imaging::ImageFileHeader header =
      imaging::scan_image(file, [&](int, const imaging::ImageStrip& strip) {
        std::visit(
            [&](const auto& view) {
              using T = std::remove_const_t<std::remove_pointer_t<decltype(view.data())>>;
              d.bit_depth = 8 * sizeof(T);
              d.sample_type = sample_type<T>();
              add_samples(view, stats);
            },
            strip);
      });
  d.file = file;
  d.format = header.format;
  d.width = header.width;
  d.height = header.height;
  d.channels = header.channels;
  d.finite = stats.finite;
  d.non_finite = stats.non_finite;
  if (stats.finite == 0)
    return d;
  d.min = stats.min;
  d.max = stats.max;
  d.mean = stats.sum / static_cast<double>(stats.finite);
  return d;
}

void to_json(nlohmann::json& json, const ImageDescription& d) {
  const auto or_null = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  json = {{"file", d.file},
          {"format", d.format},
          {"width", d.width},
          {"height", d.height},
          {"channels", d.channels},
          {"bit_depth", d.bit_depth},
          {"sample_type", d.sample_type},
          {"finite", d.finite},
          {"non_finite", d.non_finite},
          {"min", or_null(d.min)},
          {"max", or_null(d.max)},
          {"mean", or_null(d.mean)}};
}

} // namespace marsokhod::apps
