// Tests: the renderer's ground truth against analytic planes and boxes, and its summary.

#include "support/test_files.hpp"
#include "world/hand_scenes.hpp"

#include "marsokhod/world/render/ground_truth.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace marsokhod;
using test::HandCamera;

using test_support::kPi;

world::Lighting plain_light() {
  return world::lighting_preset(world::LightPreset::high_sun);
}

world::RenderOptions noiseless() {
  world::RenderOptions options;
  options.noise_sigma = 0.0;
  return options;
}

// Ground plane disparity and range, written out from the pinhole geometry of a camera at height
// h pitched down by a: a ray through row v dips a + atan((v - cy) / f) below the horizon, meets
// the ground at depth Z = h / (sin a + (v - cy) cos a / f) along the optical axis, so
// d = f B / Z = (B / h) (f sin a + (v - cy) cos a), at forward distance h / tan(a + atan(...))
// from the camera and (u - cx) Z / f to the right of the left camera.
struct PlaneTruth {
  double disparity, range;
};

PlaneTruth plane_truth(const imaging::RigParameters& p, double u, double v) {
  const double a = p.pitch_down_deg * kPi / 180.0;
  const double h = p.mast_height_m;
  const double b = p.baseline_m;
  const double f = p.focal_mm / p.sensor_mm * p.width_px;
  const double cx = 0.5 * (p.width_px - 1);
  const double cy = 0.5 * (p.height_px - 1);
  const double z = h / (std::sin(a) + (v - cy) * std::cos(a) / f);
  const double forward = h / std::tan(a + std::atan((v - cy) / f)) + p.mast_forward_m;
  const double left = 0.5 * b - (u - cx) * z / f;
  return {(b / h) * (f * std::sin(a) + (v - cy) * std::cos(a)), std::hypot(forward, left)};
}

struct FlatScene {
  world::Terrain terrain = test::terrain_from(test::flat_field(30.0, 0.1), test::smooth_albedo);
  world::LitSurface surface{terrain, plain_light()};
  world::Renderer renderer{terrain};
};

FlatScene& flat_scene() {
  static FlatScene scene;
  return scene;
}

void check_flat_plane(const imaging::RigParameters& parameters) {
  FlatScene& scene = flat_scene();
  const world::RenderedFrame frame = scene.renderer.render_with_ground_truth(
      imaging::StereoRig(parameters), test::level_placement(), scene.surface, noiseless());
  const world::GroundTruth& gt = frame.truth;
  const HandCamera left(parameters, imaging::Eye::left);
  int checked = 0;
  int out_of_right = 0;
  for (int v = 0; v < parameters.height_px; ++v)
    for (int u = 0; u < parameters.width_px; ++u) {
      const Eigen::Vector3d ray = left.ray(u, v);
      if (ray.z() >= -1e-3) { // at or above the horizon: sky
        EXPECT_EQ(gt.visible(u, v), 0) << u << "," << v;
        continue;
      }
      const Eigen::Vector3d ground = left.ground_point(u, v);
      const double reach = std::max(std::abs(ground.x()), std::abs(ground.y()));
      if (std::abs(reach - 30.0) < 0.3)
        continue; // grazing the border of the field
      if (reach > 30.0) {
        EXPECT_EQ(gt.visible(u, v), 0) << u << "," << v;
        continue;
      }
      ASSERT_EQ(gt.visible(u, v), 255) << u << "," << v;
      const PlaneTruth expected = plane_truth(parameters, u, v);
      EXPECT_NEAR(gt.disparity(u, v), expected.disparity, 0.05) << u << "," << v;
      EXPECT_NEAR(gt.range(u, v), expected.range, 0.01) << u << "," << v;
      EXPECT_NEAR(gt.elevation(u, v), 0.0, 1e-4) << u << "," << v;
      EXPECT_NEAR(gt.vertical_parallax(u, v), 0.0, 1e-3) << u << "," << v;
      // Nothing stands on a plane, so the right camera misses a point only when it projects
      // left of the right image: u - d < -0.5.
      const double right_u = u - expected.disparity;
      if (std::abs(right_u + 0.5) > 0.01) {
        const bool outside = right_u < -0.5;
        out_of_right += outside;
        EXPECT_EQ(gt.occluded(u, v), outside ? 255 : 0) << u << "," << v;
        EXPECT_EQ(gt.valid(u, v), outside ? 0 : 255) << u << "," << v;
      }
      EXPECT_EQ(gt.obstacles(u, v), 0);
      ++checked;
    }
  EXPECT_GT(checked, parameters.width_px * parameters.height_px / 2);
  EXPECT_GT(out_of_right, 0);
}

TEST(GroundTruth, FlatPlaneMatchesTheAnalyticGroundDisparityAndRange) {
  check_flat_plane(imaging::RigParameters{});
}

TEST(GroundTruth, FlatPlaneMatchesTheAnalyticFormulasForAnotherRig) {
  imaging::RigParameters p;
  p.width_px = p.height_px = 128;
  p.pitch_down_deg = 14.0;
  p.mast_height_m = 1.3;
  p.mast_forward_m = 0.4;
  p.baseline_m = 0.35;
  check_flat_plane(p);
}

TEST(GroundTruth, SummaryCountsTheMasks) {
  world::GroundTruth gt = world::GroundTruth::unknown(4, 2);
  gt.visible.fill(255);
  gt.valid(0, 0) = gt.valid(1, 0) = gt.valid(2, 0) = 255;
  gt.occluded(3, 0) = 255;
  gt.obstacles(2, 1) = 255;
  const world::GroundTruthStats stats = world::summarize(gt);
  EXPECT_EQ(stats.pixels, 8);
  EXPECT_EQ(stats.visible, 8);
  EXPECT_EQ(stats.valid, 3);
  EXPECT_EQ(stats.occluded, 1);
  EXPECT_DOUBLE_EQ(stats.valid_fraction(), 3.0 / 8.0);
  EXPECT_DOUBLE_EQ(stats.obstacle_fraction(), 1.0 / 8.0);
  EXPECT_TRUE(std::isinf(gt.disparity(1, 1)));
}

// --- A box of known size at a known place -------------------------------------------------

using Polygon = std::vector<Eigen::Vector2d>;

// Convex hull (counter-clockwise in image coordinates) by the monotone chain.
Polygon convex_hull(Polygon points) {
  std::sort(
      points.begin(), points.end(),
      [](const auto& a, const auto& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
      });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
      --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0)
      --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Signed distance of p inside a convex counter-clockwise polygon (negative outside).
double inside_distance(const Polygon& polygon, const Eigen::Vector2d& p) {
  double nearest = 1e30;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i];
    const Eigen::Vector2d b = polygon[(i + 1) % polygon.size()];
    const Eigen::Vector2d edge = (b - a).normalized();
    nearest = std::min(nearest, edge.x() * (p - a).y() - edge.y() * (p - a).x());
  }
  return nearest;
}

struct Box {
  double x0, x1, y0, y1, height;
};

Polygon projected(const HandCamera& camera, const Box& box, double grow, double z) {
  return {camera.project({box.x0 - grow, box.y0 - grow, z}),
          camera.project({box.x1 + grow, box.y0 - grow, z}),
          camera.project({box.x1 + grow, box.y1 + grow, z}),
          camera.project({box.x0 - grow, box.y1 + grow, z})};
}

TEST(GroundTruth, BoxAppearsAtItsProjectedPixelsWithItsHeight) {
  const Box box{4.0, 4.6, -0.3, 0.5, 0.4};
  world::HeightField field = test::flat_field(8.0, 0.02);
  test::raise_box(field, box.x0, box.x1, box.y0, box.y1, box.height);
  const world::Terrain terrain = test::terrain_from(std::move(field), test::smooth_albedo);
  const world::LitSurface surface(terrain, plain_light());
  const world::Renderer renderer(terrain);
  const imaging::RigParameters parameters;
  const world::RenderedFrame frame = renderer.render_with_ground_truth(
      imaging::StereoRig(parameters), test::level_placement(), surface, noiseless());
  const world::GroundTruth& gt = frame.truth;

  const HandCamera left(parameters, imaging::Eye::left);
  const Polygon top = convex_hull(projected(left, box, 0.0, box.height));
  Polygon corners = projected(left, box, 0.02, 0.0); // the sides reach the ground one cell out
  for (const Eigen::Vector2d& c : top)
    corners.push_back(c);
  const Polygon silhouette = convex_hull(corners);

  int on_top = 0;
  int around = 0;
  for (int v = 0; v < parameters.height_px; ++v)
    for (int u = 0; u < parameters.width_px; ++u) {
      const Eigen::Vector2d pixel(u, v);
      if (inside_distance(top, pixel) >= 1.0) {
        ASSERT_EQ(gt.visible(u, v), 255) << u << "," << v;
        EXPECT_NEAR(gt.elevation(u, v), box.height, 1e-4) << u << "," << v;
        // Taller than the 30 cm step limit: the box top is an obstacle.
        EXPECT_EQ(gt.obstacles(u, v), 255) << u << "," << v;
        ++on_top;
      } else if (inside_distance(silhouette, pixel) <= -1.0 && gt.visible(u, v)) {
        EXPECT_NEAR(gt.elevation(u, v), 0.0, 1e-4) << u << "," << v;
        ++around;
      }
    }
  // The top is 0.6 m x 0.8 m seen from about 4 m: dozens of pixels on a side.
  EXPECT_GT(on_top, 500);
  EXPECT_GT(around, 20000);
}

// --- Occlusion behind a tall box ----------------------------------------------------------

// True when the plan-view segment from a to b crosses the rectangle grown by `grow` (slab
// clipping on the parameter of the segment).
bool segment_crosses(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Box& box,
                     double grow) {
  double t0 = 0.0;
  double t1 = 1.0;
  const double lo[2] = {box.x0 - grow, box.y0 - grow};
  const double hi[2] = {box.x1 + grow, box.y1 + grow};
  for (int k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    if (std::abs(d) < 1e-15) {
      if (a[k] < lo[k] || a[k] > hi[k])
        return false;
      continue;
    }
    double near = (lo[k] - a[k]) / d;
    double far = (hi[k] - a[k]) / d;
    if (near > far)
      std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  return t0 <= t1;
}

TEST(GroundTruth, GroundHiddenFromTheRightCameraBehindATallBoxIsOccluded) {
  // 3 m tall, much taller than the 1 m mast: any sight line crossing its footprint is blocked.
  const Box box{5.0, 5.6, -0.1, 0.5, 3.0};
  world::HeightField field = test::flat_field(10.0, 0.02);
  test::raise_box(field, box.x0, box.x1, box.y0, box.y1, box.height);
  const world::Terrain terrain = test::terrain_from(std::move(field), test::smooth_albedo);
  const world::LitSurface surface(terrain, plain_light());
  const world::Renderer renderer(terrain);
  const imaging::RigParameters parameters;
  const world::RenderedFrame frame = renderer.render_with_ground_truth(
      imaging::StereoRig(parameters), test::level_placement(), surface, noiseless());
  const world::GroundTruth& gt = frame.truth;

  const HandCamera left(parameters, imaging::Eye::left);
  const HandCamera right(parameters, imaging::Eye::right);
  const double cell = 0.02;
  int hidden = 0;
  int seen = 0;
  for (int v = 0; v < parameters.height_px; ++v)
    for (int u = 0; u < parameters.width_px; ++u) {
      if (left.ray(u, v).z() >= -1e-3)
        continue;
      const Eigen::Vector3d g = left.ground_point(u, v);
      if (std::max(std::abs(g.x()), std::abs(g.y())) > 9.5)
        continue;
      const Eigen::Vector2d ground = g.head<2>();
      // Only ground whose sight line from the left camera clears the sloped sides by 2 cm.
      if (segment_crosses(left.centre.head<2>(), ground, box, cell + 0.02))
        continue; // the left camera sees the box there, not the ground
      ASSERT_EQ(gt.visible(u, v), 255) << u << "," << v;
      ASSERT_NEAR(gt.elevation(u, v), 0.0, 1e-4) << u << "," << v;
      // Blocked for sure when the sight line crosses the top's footprint 1 cm inside its edge;
      // clear when it misses the sloped sides by 2 cm; undecided in between.
      const bool right_blocked = segment_crosses(right.centre.head<2>(), ground, box, -0.01);
      const bool right_clear = !segment_crosses(right.centre.head<2>(), ground, box, cell + 0.02);
      const double right_u = right.project(g).x();
      if ((!right_blocked && !right_clear) || std::abs(right_u + 0.5) < 0.01)
        continue; // too close to the box edge or the image edge to call by hand
      const bool occluded = right_blocked || right_u < -0.5;
      EXPECT_EQ(gt.occluded(u, v), occluded ? 255 : 0) << u << "," << v;
      EXPECT_EQ(gt.valid(u, v), occluded ? 0 : 255) << u << "," << v;
      hidden += right_blocked;
      seen += !occluded;
    }
  EXPECT_GT(hidden, 150); // a wedge a few pixels wide over some hundred rows
  EXPECT_GT(seen, 10000);
}

} // namespace
