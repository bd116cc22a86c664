// The pinhole stereo rig on the rover mast: parameters, misalignment, attitude, frames.
#pragma once

#include "marsokhod/io/formats/keyed_file_error.hpp"

#include <Eigen/Geometry>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace marsokhod::imaging {

/// Rig parameters given in code that make no physical sense (negative baseline, zero focal
/// length, cameras that do not see the ground ahead); what() names the key and the problem.
class RigError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A rig file whose content the reader cannot accept: "FILE:LINE: 'rig.KEY': problem", as every
/// keyed file's error reads (io::KeyedFileError). A file that cannot be read or is not TOML is
/// an io::InputError instead.
class RigFileError : public io::KeyedFileError {
public:
  using io::KeyedFileError::KeyedFileError;
};

/// Which camera of the pair. The left camera is the reference (x_right = x_left - d).
enum class Eye { left, right };

/// Small rotation of the right camera away from the ideal parallel geometry, in arc seconds,
/// with the paper's names (section 2, fig. 3): pan about the camera's vertical axis, tilt
/// about its horizontal axis, roll about its optical axis. Each is a right-hand rotation of the
/// camera about its own axis (x right, y down, z forward), applied as pan * tilt * roll:
/// positive pan turns the optical axis right, positive tilt turns it up, positive roll turns
/// the camera clockwise as seen from behind it.
struct Misalignment {
  double pan_arcsec = 0.0;
  double tilt_arcsec = 0.0;
  double roll_arcsec = 0.0;

  friend bool operator==(const Misalignment&, const Misalignment&) = default;
};

/// The rover's attitude measured by its inclinometers. Pitch is positive nose up; roll is
/// positive when the right side is lower than the left (right-hand rotation about the forward
/// axis with x forward, y left, z up). Body to level is Ry(-pitch) * Rx(roll) about the level
/// origin, so the body's forward axis stays in the level x-z plane (x is the heading).
struct Attitude {
  double pitch_deg = 0.0;
  double roll_deg = 0.0;
};

/// Physical description of the stereo rig; defaults are the paper's Marsokhod rig (section 2).
struct RigParameters {
  double mast_height_m = 1.0;      ///< optical centres above the ground under the rover
  double mast_forward_m = 0.0;     ///< optical centres ahead of the rover centre
  double pitch_down_deg = 10.0;    ///< optical axes below the horizon (rover level)
  double focal_mm = 12.0;          ///< lens focal length
  double sensor_mm = 7.0;          ///< side of the square CCD
  double baseline_m = 0.50;        ///< distance between the optical centres
  int width_px = 256;              ///< image width (the paper uses 128 and 256)
  int height_px = 256;             ///< image height
  Misalignment right_misalignment; ///< zero for an ideal rig

  friend bool operator==(const RigParameters&, const RigParameters&) = default;
};

/// Pinhole stereo pair mounted on the rover mast.
///
/// Frames. Level frame: origin on the ground under the rover centre, z up along gravity, x along
/// the heading projected on the horizontal plane, y to the left; elevations and ranges are
/// measured here. Body frame: the level frame turned by the rover's pitch and roll. Camera
/// frame: x right, y down, z along the optical axis. Pixels: (u, v) = (column, row) with pixel
/// centres at integer coordinates and the principal point at the image centre
/// ((width-1)/2, (height-1)/2).
class StereoRig {
public:
  /// Validates the parameters; throws RigError naming the first bad one.
  explicit StereoRig(const RigParameters& parameters = {});

  /// Loads a TOML rig file (format in docs/formats.md). Missing keys keep the paper's defaults.
  /// Throws io::InputError for a file that cannot be read or a TOML syntax error, and
  /// RigFileError, naming the file, line and key, for an unknown key, a value of the wrong type
  /// or out of its range, or a rig whose cameras do not see the ground ahead.
  static StereoRig load(const std::filesystem::path& path);
  /// The TOML text of this rig, which load() reads back to an identical rig.
  std::string to_toml() const;

  const RigParameters& parameters() const { return parameters_; }
  int width() const { return parameters_.width_px; }
  int height() const { return parameters_.height_px; }
  double focal_px() const { return focal_px_; }
  double cx() const { return (parameters_.width_px - 1) * 0.5; }
  double cy() const { return (parameters_.height_px - 1) * 0.5; }
  double baseline_m() const { return parameters_.baseline_m; }
  /// Full vertical field of view implied by focal length and sensor size, in degrees.
  double vertical_fov_deg() const;

  /// Pose of a camera (camera frame -> level frame) for the given rover attitude.
  Eigen::Isometry3d camera_to_level(Eye eye, const Attitude& attitude = {}) const;
  /// Unit direction, in the level frame, of the ray through pixel (u, v) of a camera.
  Eigen::Vector3d ray(Eye eye, double u, double v, const Attitude& attitude = {}) const;
  /// Pixel where a level-frame point projects, or nothing if it is behind the camera.
  std::optional<Eigen::Vector2d> project(Eye eye, const Eigen::Vector3d& point_level,
                                         const Attitude& attitude = {}) const;

  /// Disparity (px) of a point at depth z along the optical axis: f * B / z.
  double disparity_from_depth(double depth_m) const;
  /// Depth along the optical axis for a disparity: f * B / d; +inf for d <= 0.
  double depth_from_disparity(double disparity_px) const;
  /// Level-frame point seen at left pixel (u, v) with disparity d (ideal rig assumed). A point
  /// needs d > 0; other disparities (unmatched pixels, infinity) throw std::domain_error.
  Eigen::Vector3d point_from_disparity(double u, double v, double disparity_px,
                                       const Attitude& attitude = {}) const;

  /// Disparity of the horizontal plane z = 0 seen at row v, column u; 0 where the row looks
  /// at or above the horizon.
  double ground_disparity(double u, double v, const Attitude& attitude = {}) const;
  /// Ground distance from the rover centre to the nearest ground point the cameras see (the
  /// blind zone of the paper's fig. 2; about 2 m for the default rig).
  double ground_visible_from_m() const;

private:
  const Eigen::Isometry3d& camera_to_body(Eye eye) const;

  RigParameters parameters_;
  double focal_px_ = 0.0;
  Eigen::Isometry3d left_to_body_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d right_to_body_ = Eigen::Isometry3d::Identity();
};

/// Ground (horizontal) distance from the rover centre to a level-frame point.
double ground_range_m(const Eigen::Vector3d& point_level);

} // namespace marsokhod::imaging
