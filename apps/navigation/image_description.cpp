// What `marsokhod image info` says of an image: its container, size, sample type and values.

#include "navigation/image_description.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>

namespace marsokhod::apps {
namespace {

struct SampleStats {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  std::uint64_t finite = 0;
  std::uint64_t non_finite = 0;
};

// The container named by the file's magic bytes, which is also what read_image trusts.
std::string format_name(const std::string& file) {
  std::ifstream stream(file, std::ios::binary);
  char magic[2] = {};
  stream.read(magic, 2);
  if (magic[0] == 'P' && magic[1] == '5')
    return "pgm";
  if (magic[0] == 'P' && magic[1] == '6')
    return "ppm";
  if (magic[0] == 'P' && (magic[1] == 'f' || magic[1] == 'F'))
    return "pfm";
  return "png";
}

template <class T>
SampleStats sample_stats(const imaging::Image<T>& image) {
  SampleStats stats;
  const T* samples = image.data();
  for (std::size_t i = 0; i < image.size(); ++i) {
    const double value = static_cast<double>(samples[i]);
    if (!std::isfinite(value)) {
      ++stats.non_finite;
      continue;
    }
    stats.min = std::min(stats.min, value);
    stats.max = std::max(stats.max, value);
    stats.sum += value;
    ++stats.finite;
  }
  return stats;
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

template <class T>
ImageDescription describe_image(const std::string& file, const imaging::Image<T>& image) {
  const SampleStats stats = sample_stats(image);
  ImageDescription d{file,
                     format_name(file),
                     image.width(),
                     image.height(),
                     image.channels(),
                     8 * sizeof(T),
                     sample_type<T>(),
                     stats.finite,
                     stats.non_finite,
                     {},
                     {},
                     {}};
  if (stats.finite == 0)
    return d;
  d.min = stats.min;
  d.max = stats.max;
  d.mean = stats.sum / static_cast<double>(stats.finite);
  return d;
}

template ImageDescription describe_image(const std::string&, const imaging::Image<std::uint8_t>&);
template ImageDescription describe_image(const std::string&, const imaging::Image<std::uint16_t>&);
template ImageDescription describe_image(const std::string&, const imaging::Image<float>&);

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
