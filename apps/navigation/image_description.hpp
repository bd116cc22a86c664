// What `marsokhod image info` says of an image.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace marsokhod::apps {

/// {file, format (the container its magic bytes name), width, height, channels, bit_depth,
/// sample_type, finite, non_finite, min, max, mean (null without a finite sample)}.
/// Instantiated for 8- and 16-bit and float images.
template <class T>
nlohmann::json describe_image(const std::string& file, const imaging::Image<T>& image);

} // namespace marsokhod::apps
