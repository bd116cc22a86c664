// A PLplot stream into memory: memcairo renders onto our buffer, which becomes the image.
#include "pictures/plot_canvas.hpp"

#include <algorithm>
#include <plplot/plplot.h>
#include <stdexcept>

namespace marsokhod::imaging::detail {
namespace {

std::mutex& plplot_mutex() {
  static std::mutex mutex;
  return mutex;
}

// The pen's slot in PLplot's colour map 0; slot 0 is the background.
constexpr PLINT kPen = 1;

} // namespace

PlotCanvas::PlotCanvas(int width, int height)
    : lock_(plplot_mutex()), width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 255) {
  if (width < 64 || height < 64)
    throw std::invalid_argument("chart: at least 64 x 64 pixels");
  PLINT current = 0;
  plgstrm(&current);
  previous_stream_ = current;
  PLINT stream = 0;
  plmkstrm(&stream);
  stream_ = stream;
  plsdev("memcairo");
  plsmem(width, height, pixels_.data());
  plscolbg(255, 255, 255);
  plinit();
  pladv(0);
  plschr(0.0, 0.85);
}

PlotCanvas::~PlotCanvas() {
  if (stream_ >= 0) {
    plend1();
    plsstrm(previous_stream_);
  }
}

void PlotCanvas::colour(PlotColour rgb) const {
  plscol0(kPen, rgb[0], rgb[1], rgb[2]);
  plcol0(kPen);
}

Image<std::uint8_t> PlotCanvas::take() {
  plend1();
  plsstrm(previous_stream_);
  stream_ = -1;
  Image<std::uint8_t> picture(width_, height_, 3);
  std::copy(pixels_.begin(), pixels_.end(), picture.data());
  return picture;
}

void plot_box(double x0, double y0, double x1, double y1) {
  PLFLT x[4] = {x0, x0, x1, x1};
  PLFLT y[4] = {y0, y1, y1, y0};
  plfill(4, x, y);
}

} // namespace marsokhod::imaging::detail
