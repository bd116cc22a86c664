// The height field: heights on a square grid, bilinear between nodes, in the world frame.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <Eigen/Core>

namespace marsokhod::world {

/// Heights in metres on a regular square grid. World frame: x east, y north, z up; node (i, j)
/// sits at origin + (i, j) * cell. Between nodes the surface is bilinear.
class HeightField {
public:
  HeightField() = default;
  /// Throws std::invalid_argument unless nx, ny >= 2 and cell_m is positive and finite.
  HeightField(int nx, int ny, double cell_m, Eigen::Vector2d origin = Eigen::Vector2d::Zero());

  int nx() const { return heights_.width(); }
  int ny() const { return heights_.height(); }
  double cell_m() const { return cell_m_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  /// World (x, y) of node (i, j).
  Eigen::Vector2d node_position(int i, int j) const {
    return origin_ + Eigen::Vector2d(i * cell_m_, j * cell_m_);
  }

  float& at(int i, int j) { return heights_(i, j); }
  float at(int i, int j) const { return heights_(i, j); }
  imaging::Image<float>& nodes() { return heights_; }
  const imaging::Image<float>& nodes() const { return heights_; }

  /// True when (x, y) lies inside the grid, where height() and normal() are defined.
  bool contains(double x, double y) const;
  /// Bilinear height at (x, y); clamps to the border outside the grid.
  double height(double x, double y) const;
  /// Unit upward surface normal of the bilinear patch at (x, y).
  Eigen::Vector3d normal(double x, double y) const;

private:
  /// The grid cell holding (x, y) (clamped to the grid) and the position inside it.
  struct Patch {
    const float* corner; ///< node (i, j); (i + 1, j) follows, (i, j + 1) is one row on
    double fx;
    double fy;
  };
  Patch locate(double x, double y) const;

  imaging::Image<float> heights_;
  double cell_m_ = 0.02;
  double inv_cell_ = 50.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
};

/// Nodes (i0..i1, j0..j1, inclusive) of the square of half-side `reach` around `centre`,
/// clipped to the grid; empty (i0 > i1 or j0 > j1) when the square misses the grid.
struct NodeRange {
  int i0 = 0;
  int i1 = -1;
  int j0 = 0;
  int j1 = -1;
};
NodeRange nodes_around(const HeightField& height, const Eigen::Vector2d& centre, double reach);

/// Grid coordinate u clamped into [0, last]; NaN maps to 0 so a bad ray can never index outside.
inline double clamp_grid_coordinate(double u, double last) {
  if (!(u > 0.0))
    return 0.0;
  return u < last ? u : last;
}

inline bool HeightField::contains(double x, double y) const {
  const double u = (x - origin_.x()) * inv_cell_;
  const double v = (y - origin_.y()) * inv_cell_;
  return u >= 0.0 && v >= 0.0 && u <= nx() - 1 && v <= ny() - 1;
}

inline HeightField::Patch HeightField::locate(double x, double y) const {
  const double u = clamp_grid_coordinate((x - origin_.x()) * inv_cell_, nx() - 1);
  const double v = clamp_grid_coordinate((y - origin_.y()) * inv_cell_, ny() - 1);
  int i = static_cast<int>(u);
  int j = static_cast<int>(v);
  if (i > nx() - 2)
    i = nx() - 2;
  if (j > ny() - 2)
    j = ny() - 2;
  return {heights_.data() + static_cast<std::ptrdiff_t>(j) * nx() + i, u - i, v - j};
}

inline double HeightField::height(double x, double y) const {
  if (heights_.empty())
    return 0.0;
  const Patch p = locate(x, y);
  const double z00 = p.corner[0];
  const double z10 = p.corner[1];
  const double z01 = p.corner[nx()];
  const double z11 = p.corner[nx() + 1];
  return z00 + p.fx * (z10 - z00) + p.fy * (z01 - z00) + p.fx * p.fy * (z00 - z10 - z01 + z11);
}

inline Eigen::Vector3d HeightField::normal(double x, double y) const {
  if (heights_.empty())
    return Eigen::Vector3d::UnitZ();
  const Patch p = locate(x, y);
  const double z00 = p.corner[0];
  const double z10 = p.corner[1];
  const double z01 = p.corner[nx()];
  const double z11 = p.corner[nx() + 1];
  const double twist = z00 - z10 - z01 + z11;
  const double dz_dx = (z10 - z00 + p.fy * twist) * inv_cell_;
  const double dz_dy = (z01 - z00 + p.fx * twist) * inv_cell_;
  return Eigen::Vector3d(-dz_dx, -dz_dy, 1.0).normalized();
}

} // namespace marsokhod::world
