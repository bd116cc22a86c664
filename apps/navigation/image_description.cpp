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
nlohmann::json describe_image(const std::string& file, const imaging::Image<T>& image) {
  const SampleStats stats = sample_stats(image);
  nlohmann::json info = {{"file", file},
                         {"format", format_name(file)},
                         {"width", image.width()},
                         {"height", image.height()},
                         {"channels", image.channels()},
                         {"bit_depth", 8 * sizeof(T)},
                         {"sample_type", sample_type<T>()},
                         {"finite", stats.finite},
                         {"non_finite", stats.non_finite}};
  if (stats.finite == 0) {
    info["min"] = info["max"] = info["mean"] = nullptr;
    return info;
  }
  info["min"] = stats.min;
  info["max"] = stats.max;
  info["mean"] = stats.sum / static_cast<double>(stats.finite);
  return info;
}

template nlohmann::json describe_image(const std::string&, const imaging::Image<std::uint8_t>&);
template nlohmann::json describe_image(const std::string&, const imaging::Image<std::uint16_t>&);
template nlohmann::json describe_image(const std::string&, const imaging::Image<float>&);

} // namespace marsokhod::apps
