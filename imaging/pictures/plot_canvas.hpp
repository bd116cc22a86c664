// PlotCanvas: a PLplot stream drawing into an RGB image with real fonts (private to pictures).
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace marsokhod::imaging::detail {

using PlotColour = std::array<std::uint8_t, 3>;
inline constexpr PlotColour kPlotInk{30, 30, 30};
inline constexpr PlotColour kPlotGrid{225, 225, 225};
/// Average width of a character of the charts' text, pixels: enough to tell when labels collide.
inline constexpr double kPlotCharPx = 8.0;

/// One chart drawn by PLplot through its memcairo driver (antialiased lines, DejaVu text) into
/// an image of the given size on white. PLplot's streams are process-wide state, so one canvas
/// draws at a time (a lock held from construction to take()).
class PlotCanvas {
public:
  PlotCanvas(int width, int height);
  PlotCanvas(const PlotCanvas&) = delete;
  PlotCanvas& operator=(const PlotCanvas&) = delete;
  ~PlotCanvas();

  int width() const { return width_; }
  int height() const { return height_; }
  /// Sets the pen and fill colour.
  void colour(PlotColour rgb) const;
  /// Ends the stream and gives the picture; the canvas draws nothing after.
  Image<std::uint8_t> take();

private:
  std::unique_lock<std::mutex> lock_;
  int width_;
  int height_;
  std::vector<unsigned char> pixels_;
  int stream_ = -1;
  int previous_stream_ = 0;
};

/// A filled rectangle in world coordinates.
void plot_box(double x0, double y0, double x1, double y1);

} // namespace marsokhod::imaging::detail
