// Writing a rendered scene: the pair, its ground truth, their previews and scene.json.

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/pictures/colormap.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/world/scene/scene.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

namespace marsokhod::world {
namespace {

namespace fs = std::filesystem;

// The left image in colour with the pixels that see an obstacle painted red.
imaging::Image<std::uint8_t> obstacle_overlay(const imaging::Image<std::uint8_t>& left,
                                              const imaging::Image<std::uint8_t>& obstacles) {
  imaging::Image<std::uint8_t> out(left.width(), left.height(), 3);
  for (int v = 0; v < left.height(); ++v)
    for (int u = 0; u < left.width(); ++u) {
      const std::uint8_t grey = left(u, v);
      const bool obstacle = obstacles(u, v) != 0;
      out(u, v, 0) = obstacle ? static_cast<std::uint8_t>(128 + grey / 2) : grey;
      out(u, v, 1) = obstacle ? static_cast<std::uint8_t>(grey / 3) : grey;
      out(u, v, 2) = obstacle ? static_cast<std::uint8_t>(grey / 3) : grey;
    }
  return out;
}

imaging::Image<std::uint8_t> colour_field(const imaging::Image<float>& field, const char* title,
                                          const char* unit) {
  imaging::ColormapOptions options;
  options.title = title;
  options.unit = unit;
  return imaging::false_colour(field, options);
}

class SceneWriter {
public:
  SceneWriter(const fs::path& folder, SceneDescription& scene) : folder_(folder), scene_(&scene) {}

  template <class T>
  void image(const std::string& key, const std::string& name, const imaging::Image<T>& pixels) {
    imaging::write_image(folder_ / name, pixels.view());
    scene_->outputs[key] = name;
  }

  // Through a temporary and a rename, as the images: a full disk is an error naming the file,
  // never a truncated scene.json.
  void json(const std::string& key, const std::string& name, const nlohmann::json& document) {
    io::write_file_atomically(folder_ / name, document.dump(2) + '\n');
    scene_->outputs[key] = name;
  }

private:
  fs::path folder_;
  SceneDescription* scene_;
};

} // namespace

void create_scene_folder(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder))
    throw std::runtime_error(fmt::format("{}: cannot create the output folder: {}", folder.string(),
                                         error ? error.message() : "not a directory"));
}

void write_scene(const fs::path& folder, const RenderedFrame& frame, SceneDescription& scene) {
  create_scene_folder(folder);
  scene.stats = summarize(frame.truth);
  scene.outputs.clear();
  SceneWriter write(folder, scene);
  const GroundTruth& truth = frame.truth;
  write.image("left", "left.pgm", frame.images.left);
  write.image("right", "right.pgm", frame.images.right);
  write.image("gt_disparity", "gt_disparity.pfm", truth.disparity);
  write.image("gt_range", "gt_range.pfm", truth.range);
  write.image("gt_elevation", "gt_elevation.pfm", truth.elevation);
  write.image("gt_obstacles", "gt_obstacles.pgm", truth.obstacles);
  write.image("gt_valid", "gt_valid.pgm", truth.valid);
  write.image("left_png", "left.png", frame.images.left);
  write.image("right_png", "right.png", frame.images.right);
  write.image("gt_disparity_png", "gt_disparity.png",
              colour_field(truth.disparity, "disparity", "px"));
  write.image("gt_range_png", "gt_range.png", colour_field(truth.range, "range", "m"));
  write.image("gt_elevation_png", "gt_elevation.png",
              colour_field(truth.elevation, "elevation", "m"));
  write.image("gt_obstacles_png", "gt_obstacles.png",
              obstacle_overlay(frame.images.left, truth.obstacles));
  scene.outputs["scene"] = "scene.json";
  write.json("scene", "scene.json", scene_to_json(scene));
}

} // namespace marsokhod::world
