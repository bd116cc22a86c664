// The stereo half of the navigation program: features, matching and refine.

#include "processes/process_bodies.hpp"

#include "marsokhod/nav/features/layer_features.hpp"
#include "marsokhod/nav/features/pair_pyramid.hpp"
#include "marsokhod/nav/stereo/layered_matching.hpp"

#include <fmt/format.h>

#include <limits>
#include <optional>
#include <utility>

namespace marsokhod::nav_program::detail {
namespace {

/// A band of the original layer's matched rows on the matched channel, before its rows: a
/// first row of -1 ends the layer.
struct BandHeader {
  std::int32_t first_row = -1;
  std::int32_t rows = 0;
};

void send_features(BlockChannel& channel, const nav::LayerFeatures& features) {
  if (features.kind == nav::FeatureKind::census3x3) {
    send_image<std::uint8_t>(channel, features.bytes.view());
    return;
  }
  send_image<std::uint32_t>(channel, features.words.view());
}

nav::LayerFeatures receive_features(ProcessContext& c, BlockChannel& channel, std::string_view eye,
                                    int width, int height) {
  const nav::FeatureKind kind = c.cycle().options.stereo.feature;
  nav::LayerFeatures features{kind, U8Image(c.memory()), imaging::Image<std::uint32_t>(c.memory())};
  if (kind == nav::FeatureKind::census3x3) {
    features.bytes =
        receive_bytes(c, channel, fmt::format("census features, {}", eye), width, height);
    return features;
  }
  c.doing(image_what(fmt::format("features, {}", eye), width, height, 4));
  features.words = receive_image<std::uint32_t>(channel, width, height, c.memory());
  return features;
}

// The cycle's stereo options, worked out on the node as the program would at its start.
nav::StereoOptions stereo_options(ProcessContext& c, std::pmr::vector<std::int16_t>& unseen) {
  c.doing(fmt::format("unseen columns, {} rows x 2 B", c.cycle().height));
  return nav::rover_stereo_options(*c.cycle().rig, c.cycle().options, unseen);
}

// Matches every layer as its features arrive; the original layer's bands go to refine as they
// are matched, after the original left image its texture mask needs.
nav::StereoResult match_layers(ProcessContext& c, const nav::StereoOptions& options) {
  CycleState& s = c.cycle();
  BlockChannel& matched = s.channels.matched;
  const nav::MatchedBandSink bands = [&matched](const nav::MatchedBand& band) {
    send_value(matched, BandHeader{band.first_row, band.disparity.height()});
    send_image<float>(matched, band.disparity);
    send_image<std::uint8_t>(matched, band.valid);
  };
  nav::LayeredMatching walk(s.width, s.height, options, c.memory(), &bands);
  for (int level = walk.levels() - 1; level >= 0; --level) {
    const int width = s.width >> level;
    const int height = s.height >> level;
    const U8Image layer = receive_bytes(c, s.channels.features,
                                        fmt::format("layer {} left image", level), width, height);
    const nav::LayerFeatures left_features =
        receive_features(c, s.channels.features, "left", width, height);
    const nav::LayerFeatures right_features =
        receive_features(c, s.channels.features, "right", width, height);
    if (level == walk.levels() - 1)
      c.start_stage();
    if (level == 0)
      send_image<std::uint8_t>(matched, layer.view());
    c.doing(level == 0 ? fmt::format("matching layer 0 ({}x{}): cost rows and a band of disparity "
                                     "and validity",
                                     width, height)
                       : fmt::format("matching layer {} ({}x{}): cost rows, layer disparity and "
                                     "validity",
                                     level, width, height));
    if (!walk.finished())
      walk.match_layer(layer, left_features, right_features, c.meter());
  }
  return walk.take_result();
}

// The original layer's bands, assembled and finished as match_stereo finishes it.
nav::StereoResult assemble_stereo(ProcessContext& c, const nav::StereoOptions& options) {
  CycleState& s = c.cycle();
  BlockChannel& matched = s.channels.matched;
  c.doing(image_what("matched disparity and validity", s.width, s.height, 5));
  FloatImage disparity(s.width, s.height, 1, std::numeric_limits<float>::infinity(), c.memory());
  U8Image valid(s.width, s.height, 1, 0, c.memory());
  for (auto band = receive_value<BandHeader>(matched); band.first_row >= 0;
       band = receive_value<BandHeader>(matched)) {
    receive_rows<float>(matched, disparity.view().sub(0, band.first_row, s.width, band.rows));
    receive_rows<std::uint8_t>(matched, valid.view().sub(0, band.first_row, s.width, band.rows));
  }
  std::string reason = receive_text(matched, c.memory());
  const auto valid_pixels = receive_value<std::uint64_t>(matched);
  c.doing("layer figures");
  std::pmr::vector<nav::StereoLayerStats> layers =
      receive_list<nav::StereoLayerStats>(matched, c.memory());
  if (!reason.empty()) {
    disparity = FloatImage(c.memory());
    valid = U8Image(c.memory());
    c.doing(image_what("unmatched disparity and validity", s.width, s.height, 5));
    nav::StereoResult failed =
        nav::unmatched_stereo(s.width, s.height, std::move(reason), c.memory());
    failed.layers = std::move(layers);
    return failed;
  }
  c.doing(image_what("fill and median of layer 0: smoothed disparity", s.width, s.height, 4));
  nav::finish_original_layer(disparity, valid.view(), options, c.meter(), c.memory());
  return {std::move(disparity), std::move(valid), valid_pixels, std::move(layers), {}};
}

} // namespace

void features(ProcessContext& c) {
  CycleState& s = c.cycle();
  const U8Image left = receive_bytes(c, s.channels.images, "left image", s.width, s.height);
  c.start_stage();
  const U8Image right = receive_bytes(c, s.channels.images, "right image", s.width, s.height);
  const std::optional<std::string> uniform = nav::uniform_pair_reason(left, right);
  send_text(s.channels.features, uniform.value_or(""));
  if (uniform) {
    send_image<std::uint8_t>(s.channels.features, left.view());
    return;
  }
  std::pmr::vector<std::int16_t> unseen(c.memory());
  const nav::StereoOptions options = stereo_options(c, unseen);
  const int levels = nav::pyramid_levels_for(s.width, s.height, options);
  c.doing(fmt::format("pyramid layers 1..{}, both eyes", levels - 1));
  const nav::PairPyramid pyramid(left, right, levels, c.meter(), c.memory());
  for (int level = levels - 1; level >= 0; --level) {
    const auto left_layer = pyramid.layer(level, imaging::Eye::left);
    c.doing(image_what(fmt::format("layer {} features", level), left_layer.width(),
                       left_layer.height(), 1));
    const nav::LayerFeatures left_features =
        nav::layer_features(left_layer, options.feature, c.meter(), c.memory());
    const nav::LayerFeatures right_features = nav::layer_features(
        pyramid.layer(level, imaging::Eye::right), options.feature, c.meter(), c.memory());
    send_image<std::uint8_t>(s.channels.features, left_layer);
    send_features(s.channels.features, left_features);
    send_features(s.channels.features, right_features);
  }
}

void matching(ProcessContext& c) {
  CycleState& s = c.cycle();
  const std::string uniform = receive_text(s.channels.features, c.memory());
  send_text(s.channels.matched, uniform);
  if (!uniform.empty()) {
    const U8Image left = receive_bytes(c, s.channels.features, "left image", s.width, s.height);
    c.start_stage();
    send_image<std::uint8_t>(s.channels.matched, left.view());
    return;
  }
  std::pmr::vector<std::int16_t> unseen(c.memory());
  const nav::StereoOptions options = stereo_options(c, unseen);
  const nav::StereoResult walked = match_layers(c, options);
  send_value(s.channels.matched, BandHeader{});
  send_text(s.channels.matched, walked.reason);
  send_value(s.channels.matched, walked.valid_pixels);
  send_list<nav::StereoLayerStats>(s.channels.matched, walked.layers);
}

// The original layer assembled and finished, and its seeable disparity. Only what range needs
// is kept: the rest goes before the hand-over, when range's buffers arrive beside these.
namespace {

struct Refined {
  std::string reason;
  FloatImage seeable;
  U8Image valid;
};

Refined refined_stereo(ProcessContext& c) {
  CycleState& s = c.cycle();
  std::string uniform = receive_text(s.channels.matched, c.memory());
  const U8Image left = receive_bytes(c, s.channels.matched, "left image", s.width, s.height);
  c.start_stage();
  std::pmr::vector<std::int16_t> unseen(c.memory());
  const nav::StereoOptions options = stereo_options(c, unseen);
  if (!uniform.empty())
    c.doing(image_what("unmatched disparity and validity", s.width, s.height, 5));
  nav::StereoResult stereo =
      uniform.empty() ? assemble_stereo(c, options)
                      : nav::unmatched_stereo(s.width, s.height, std::move(uniform), c.memory());
  c.doing(image_what("seeable disparity and texture mask", s.width, s.height, 5));
  FloatImage seeable =
      nav::seeable_disparity(left, stereo.disparity, *s.rig, s.options, c.memory());
  s.products.stereo = stereo;
  return {stereo.reason, std::move(seeable), std::move(stereo.valid)};
}

} // namespace

void refine(ProcessContext& c) {
  CycleState& s = c.cycle();
  {
    const Refined refined = refined_stereo(c);
    send_text(s.channels.disparity, refined.reason);
    send_image<float>(s.channels.disparity, refined.seeable.view());
    send_image<std::uint8_t>(s.channels.disparity, refined.valid.view());
  }
  close_hand_over(s.channels.disparity);
}

} // namespace marsokhod::nav_program::detail
