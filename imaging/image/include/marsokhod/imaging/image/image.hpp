// Image<T> and ImageView<T>: owning and non-owning interleaved pixel grids.
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <memory_resource>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace marsokhod::imaging {

/// Largest width or height any image may have; readers reject larger headers before allocating.
inline constexpr int kMaxImageSide = 16384;

/// A non-owning, cheap-to-copy window onto interleaved pixels: rows may be strided, so a
/// sub-rectangle of an image is a view of the same bytes.
template <class T>
class ImageView {
public:
  ImageView() = default;
  ImageView(T* data, int width, int height, int channels, std::ptrdiff_t row_stride)
      : data_(data), width_(width), height_(height), channels_(channels), stride_(row_stride) {}

  // A view of T converts to a view of const T, never the other way.
  template <class U>
  requires(std::is_same_v<const U, T> && !std::is_same_v<U, T>)
      ImageView(const ImageView<U>& other) // NOLINT(google-explicit-constructor)
      : data_(other.data()), width_(other.width()), height_(other.height()),
        channels_(other.channels()), stride_(other.stride()) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int channels() const { return channels_; }
  /// Elements (not bytes) from the start of one row to the start of the next.
  std::ptrdiff_t stride() const { return stride_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  T* data() const { return data_; }

  T* row(int y) const {
    assert(y >= 0 && y < height_);
    return data_ + y * stride_;
  }
  T& operator()(int x, int y, int c = 0) const {
    assert(x >= 0 && x < width_ && c >= 0 && c < channels_);
    return row(y)[static_cast<std::ptrdiff_t>(x) * channels_ + c];
  }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  /// The w x h window whose top-left pixel is (x, y); it must lie inside this view.
  ImageView sub(int x, int y, int w, int h) const {
    // Written as subtractions so that huge w or h cannot overflow into range.
    if (x < 0 || y < 0 || w < 0 || h < 0 || x > width_ || y > height_ || w > width_ - x ||
        h > height_ - y)
      throw std::out_of_range("ImageView::sub: window outside the image");
    return ImageView(data_ + y * stride_ + static_cast<std::ptrdiff_t>(x) * channels_, w, h,
                     channels_, stride_);
  }

private:
  T* data_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  int channels_ = 1;
  std::ptrdiff_t stride_ = 0;
};

/// An owning image with interleaved channels whose pixels come from a caller-chosen
/// std::pmr::memory_resource (contract 2 of the design: memory from the caller).
template <class T>
class Image {
public:
  using value_type = T;
  using allocator_type = std::pmr::polymorphic_allocator<T>;

  Image() = default;
  explicit Image(allocator_type alloc) : pixels_(alloc) {}
  Image(int width, int height, int channels = 1, T fill = T{}, allocator_type alloc = {})
      : width_(checked_side(width)), height_(checked_side(height)),
        channels_(checked_channels(channels)),
        pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                    static_cast<std::size_t>(channels),
                fill, alloc) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int channels() const { return channels_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  std::size_t size() const { return pixels_.size(); }
  T* data() { return pixels_.data(); }
  const T* data() const { return pixels_.data(); }
  allocator_type get_allocator() const { return pixels_.get_allocator(); }

  ImageView<T> view() { return {pixels_.data(), width_, height_, channels_, stride()}; }
  ImageView<const T> view() const { return {pixels_.data(), width_, height_, channels_, stride()}; }
  operator ImageView<T>() { return view(); }             // NOLINT(google-explicit-constructor)
  operator ImageView<const T>() const { return view(); } // NOLINT(google-explicit-constructor)

  T* row(int y) { return pixels_.data() + y * stride(); }
  const T* row(int y) const { return pixels_.data() + y * stride(); }
  T& operator()(int x, int y, int c = 0) {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_ && c >= 0 && c < channels_);
    return pixels_[static_cast<std::size_t>(y * stride() +
                                            static_cast<std::ptrdiff_t>(x) * channels_ + c)];
  }
  const T& operator()(int x, int y, int c = 0) const {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_ && c >= 0 && c < channels_);
    return pixels_[static_cast<std::size_t>(y * stride() +
                                            static_cast<std::ptrdiff_t>(x) * channels_ + c)];
  }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  void fill(T value) { std::fill(pixels_.begin(), pixels_.end(), value); }

  friend bool operator==(const Image& a, const Image& b) {
    return a.width_ == b.width_ && a.height_ == b.height_ && a.channels_ == b.channels_ &&
           a.pixels_ == b.pixels_;
  }

private:
  std::ptrdiff_t stride() const { return static_cast<std::ptrdiff_t>(width_) * channels_; }
  static int checked_side(int side) {
    if (side < 0 || side > kMaxImageSide)
      throw std::invalid_argument("Image: width and height must be within 0..16384");
    return side;
  }
  static int checked_channels(int channels) {
    if (channels < 1 || channels > 4)
      throw std::invalid_argument("Image: channels must be within 1..4");
    return channels;
  }

  int width_ = 0;
  int height_ = 0;
  int channels_ = 1;
  std::pmr::vector<T> pixels_;
};

/// Copies a view into a new owning image (same size and channels).
template <class T>
Image<std::remove_const_t<T>>
to_image(ImageView<T> view, std::pmr::polymorphic_allocator<std::remove_const_t<T>> alloc = {}) {
  Image<std::remove_const_t<T>> out(view.width(), view.height(), view.channels(), {}, alloc);
  for (int y = 0; y < view.height(); ++y)
    std::copy(view.row(y),
              view.row(y) + static_cast<std::ptrdiff_t>(view.width()) * view.channels(),
              out.row(y));
  return out;
}

} // namespace marsokhod::imaging
