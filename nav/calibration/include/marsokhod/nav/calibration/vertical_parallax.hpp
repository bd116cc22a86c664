// The vertical parallax map: its quadratic model, its file, and its removal from right images.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/io/formats/keyed_file_error.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory_resource>
#include <stdexcept>
#include <string>

namespace marsokhod::nav {

/// A calibration that cannot be fitted, or a map that does not fit the images.
class CalibrationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A calibration file whose content the reader cannot accept:
/// "FILE:LINE: 'vertical_parallax.KEY': problem", as every keyed file's error reads
/// (io::KeyedFileError). A file that cannot be read or is not TOML is an io::InputError instead.
class CalibrationFileError : public io::KeyedFileError {
public:
  using io::KeyedFileError::KeyedFileError;
};

/// The vertical parallax of a stereo pair (paper, section 2): how many rows lower the right
/// image shows what the left image shows at row y, as a smooth function of the position.
/// The model is a quadratic in x and y measured from the image centre ((W-1)/2, (H-1)/2):
///
///   shift(x, y) = c0 + cx x + cy y + cxx x^2 + cxy x y + cyy y^2
///
/// which holds the first-order effect of every small turn of the right camera exactly
/// (docs/camera.md: dy = tilt (f + y^2/f) - pan x y / f - roll x). A positive shift means the
/// right image's content sits further down. Sizes are those of the images it was fitted on.
struct VerticalParallaxMap {
  int width = 0;
  int height = 0;
  /// c0, cx, cy, cxx, cxy, cyy (rows, rows per pixel, rows per pixel squared).
  std::array<double, 6> coefficients{};

  /// The shift at pixel (x, y) of the image (column, row; pixel centres at integers).
  double shift_at(double x, double y) const;
  /// The largest |shift| over the image (reached at a corner or the centre for a quadratic
  /// without interior extremes; checked on a grid, so valid for any coefficients).
  double largest_shift() const;
  bool is_identity() const;
};

/// How remove_vertical_parallax reads between two rows.
enum class VerticalInterpolation : std::uint8_t {
  linear, ///< two rows: a half-row shift averages them, blurring the image vertically
  cubic,  ///< four rows, Keys' cubic convolution: keeps the detail matching relies on
};

/// The right image with every pixel taken from `shift_at(x, y)` rows further down, so that the
/// pair is row-aligned before matching; rows beyond the border repeat the border row. Reports
/// Work::pyramid_pixel per output pixel: like a pyramid pixel it is a few loads and one
/// integer weighted sum. Throws CalibrationError when the map's size differs from the image's.
/// Instantiated for NullMeter, CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
imaging::Image<std::uint8_t> remove_vertical_parallax(
    imaging::ImageView<const std::uint8_t> right, const VerticalParallaxMap& map,
    VerticalInterpolation interpolation = VerticalInterpolation::linear, Meter& meter = null_meter,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Largest |shift| a calibration file may hold, rows: beyond it rows no longer correspond.
inline constexpr double kMaxVerticalShift = 64.0;
/// Smallest width or height of the images a calibration file describes, pixels.
inline constexpr int kMinCalibrationSide = 16;
/// Largest |coefficient| a calibration file may hold. A quadratic within kMaxVerticalShift rows
/// over an image of at least 16 x 16 pixels has coefficients below about 64 * 4, so this refuses
/// no usable map; it keeps every term (at most 1e6 * 8192^2 rows over the largest image) finite,
/// so that no two terms can cancel to NaN.
inline constexpr double kMaxCalibrationCoefficient = 1e6;

/// Why a calibration file cannot hold `map`, empty when it can: the rules load_vertical_parallax
/// applies, so that what a calibration writes the navigation reads.
std::string calibration_map_problem(const VerticalParallaxMap& map);

/// Reads a calibration file (TOML, docs/navigation.md, "Calibration file"). Throws
/// io::InputError for a file that cannot be read or a TOML syntax error, and
/// CalibrationFileError, naming the file, line and key, for an unknown or missing key, a value
/// of the wrong type or out of its range, or a map shifting rows by more than kMaxVerticalShift.
VerticalParallaxMap load_vertical_parallax(const std::filesystem::path& path);

/// The calibration file text for a map; `comment` lines (may be empty) describe the fit.
std::string vertical_parallax_to_toml(const VerticalParallaxMap& map,
                                      const std::string& comment = {});

/// Throws CalibrationError naming `source` when the map's size differs from width x height.
void check_map_size(const VerticalParallaxMap& map, int width, int height,
                    const std::string& source);

} // namespace marsokhod::nav
