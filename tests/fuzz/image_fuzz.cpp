// Fuzz target: the image decoders must give a well-formed image or an ImageError.
// libFuzzer target for the image decoders: any input must give a well-formed image or an
// ImageError; anything else (a crash, a sanitizer report, another exception) is a finding.

#include "marsokhod/imaging/image/image_io.hpp"

#include <cstdint>
#include <cstdlib>
#include <span>
#include <variant>

namespace {

template <class T>
void check_well_formed(const marsokhod::imaging::Image<T>& image) {
  using marsokhod::imaging::kMaxImageSide;
  const bool sides = image.width() >= 1 && image.width() <= kMaxImageSide && image.height() >= 1 &&
                     image.height() <= kMaxImageSide;
  const bool channels = image.channels() == 1 || image.channels() == 3;
  const std::size_t samples = static_cast<std::size_t>(image.width()) *
                              static_cast<std::size_t>(image.height()) *
                              static_cast<std::size_t>(image.channels());
  if (!sides || !channels || image.size() != samples)
    std::abort();
  // Reading every sample lets MemorySanitizer builds catch pixels that were never written.
  volatile T sink{};
  for (std::size_t i = 0; i < image.size(); ++i)
    sink = image.data()[i];
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const marsokhod::imaging::AnyImage image =
        marsokhod::imaging::decode_image(std::span<const std::uint8_t>(data, size), "fuzz-input");
    std::visit([](const auto& pixels) { check_well_formed(pixels); }, image);
  } catch (const marsokhod::imaging::ImageError&) {
    // The expected outcome for malformed input.
  }
  return 0;
}
