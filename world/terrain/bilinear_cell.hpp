// One bilinear cell of the height field and where a ray meets it (private to ray casting).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

namespace marsokhod::world {

/// One cell of a height field: the bilinear patch through its four corner heights, with local
/// coordinates (s, r) in [0, 1]^2 (s along x, r along y).
struct BilinearCell {
  double h00, h10, h01, h11;

  double height(double s, double r) const {
    return h00 + (h10 - h00) * s + (h01 - h00) * r + (h00 - h10 - h01 + h11) * s * r;
  }

  /// First tau in [0, span] where the ray (s + ds tau, r + dr tau, z + dz tau) reaches the patch,
  /// if any. Along a straight ray the bilinear height is a quadratic in tau, so the crossing is
  /// the smallest root of (ray z - surface height), solved in closed form; a ray that starts at
  /// or below the surface crosses at 0.
  std::optional<double> first_crossing(double s, double r, double z, double ds, double dr,
                                       double dz, double span) const {
    const double b = h10 - h00;
    const double c = h01 - h00;
    const double d = h00 - h10 - h01 + h11;
    const double f0 = z - height(s, r);
    if (f0 <= 0.0)
      return 0.0;
    const double f1 = dz - (b * ds + c * dr + d * (s * dr + r * ds));
    const double f2 = -d * ds * dr;
    if (f2 == 0.0) {
      if (f1 >= 0.0)
        return std::nullopt;
      return within(-f0 / f1, span);
    }
    const double discriminant = f1 * f1 - 4.0 * f2 * f0;
    if (discriminant < 0.0)
      return std::nullopt;
    // Numerically stable pair of roots (no cancellation between f1 and the square root).
    const double q = -0.5 * (f1 + std::copysign(std::sqrt(discriminant), f1));
    const double root_a = q / f2;
    const double root_b = q != 0.0 ? f0 / q : root_a;
    const double first = std::min(root_a, root_b);
    const double second = std::max(root_a, root_b);
    if (first >= 0.0)
      return within(first, span);
    return within(second, span);
  }

private:
  static std::optional<double> within(double tau, double span) {
    if (tau < 0.0 || tau > span)
      return std::nullopt;
    return tau;
  }
};

} // namespace marsokhod::world
