// The image pyramid's next layer: an image halved by 2x2 means.

#include "marsokhod/nav/features/image_pyramid.hpp"

#include "work/work_report.hpp"

namespace marsokhod::nav {

template <class Meter>
imaging::Image<std::uint8_t> halve_image(imaging::ImageView<const std::uint8_t> image, Meter& meter,
                                         std::pmr::memory_resource* memory) {
  const int width = image.width() / 2;
  const int height = image.height() / 2;
  imaging::Image<std::uint8_t> half(width, height, 1, 0, memory);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* top = image.row(2 * y);
    const std::uint8_t* bottom = image.row(2 * y + 1);
    std::uint8_t* out = half.row(y);
    for (int x = 0; x < width; ++x) {
      const int sum = top[2 * x] + top[2 * x + 1] + bottom[2 * x] + bottom[2 * x + 1];
      out[x] = static_cast<std::uint8_t>((sum + 2) >> 2);
    }
    detail::report(meter, Work::pyramid_pixel, static_cast<std::uint64_t>(width));
  }
  return half;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template imaging::Image<std::uint8_t> halve_image<M>(imaging::ImageView<const std::uint8_t>, M&, \
                                                       std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
