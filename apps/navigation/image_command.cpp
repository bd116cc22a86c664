// `marsokhod image info|convert`: look at an image file and convert between formats, with an
// optional false-colour picture of a one-channel field.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/image_description.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/pictures/colormap.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

// The colour scale is in float: a bound beyond would become infinite.
constexpr double kLargestFloat = std::numeric_limits<float>::max();

struct InfoOptions {
  std::string file;
  bool json = false;
};

struct ConvertOptions {
  std::string input;
  std::string output;
  bool colour = false;
  double min = 0.0;
  double max = 0.0;
  CLI::Option* min_option = nullptr;
  CLI::Option* max_option = nullptr;
  std::string unit;
  std::string title;
};

std::string text_value(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : "none (no finite samples)";
}

int run_info(const InfoOptions& options) {
  const ImageDescription info = describe_image_file(options.file);
  if (options.json) {
    fmt::print("{}\n", nlohmann::json(info).dump());
    return kSuccess;
  }
  fmt::print("file:       {}\n", options.file);
  fmt::print("format:     {}\n", info.format);
  fmt::print("width:      {}\n", info.width);
  fmt::print("height:     {}\n", info.height);
  fmt::print("channels:   {}\n", info.channels);
  fmt::print("bit depth:  {} ({})\n", info.bit_depth, info.sample_type);
  fmt::print("min:        {}\n", text_value(info.min));
  fmt::print("max:        {}\n", text_value(info.max));
  fmt::print("mean:       {}\n", text_value(info.mean));
  fmt::print("non-finite: {}\n", info.non_finite);
  return kSuccess;
}

template <class T>
imaging::Image<float> to_float(const imaging::Image<T>& image) {
  imaging::Image<float> field(image.width(), image.height(), image.channels());
  for (std::size_t i = 0; i < image.size(); ++i)
    field.data()[i] = static_cast<float>(image.data()[i]);
  return field;
}

imaging::Image<float> to_float(imaging::AnyImage&& image) {
  if (auto* floats = std::get_if<imaging::Image<float>>(&image))
    return std::move(*floats);
  return std::visit([](const auto& pixels) { return to_float(pixels); }, image);
}

bool ends_with_pfm(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".pfm";
}

int run_convert(const ConvertOptions& options) {
  const bool has_min = options.min_option->count() > 0;
  const bool has_max = options.max_option->count() > 0;
  if (has_min && has_max && !(options.min < options.max))
    throw UsageError(fmt::format("--min {} must be below --max {}", options.min, options.max));
  imaging::AnyImage image = imaging::read_image(options.input);
  if (options.colour) {
    const imaging::Image<float> field = to_float(std::move(image));
    if (field.channels() != 1)
      throw CommandError(fmt::format("{}: --colour needs a one-channel image, found {} channels",
                                     options.input, field.channels()));
    imaging::ColormapOptions colour;
    if (has_min)
      colour.min_value = static_cast<float>(options.min);
    if (has_max)
      colour.max_value = static_cast<float>(options.max);
    colour.unit = options.unit;
    colour.title = options.title;
    imaging::write_image(options.output, imaging::false_colour(field, colour).view());
  } else if (ends_with_pfm(options.output)) {
    imaging::write_image(options.output, to_float(std::move(image)).view());
  } else {
    std::visit([&](const auto& pixels) { imaging::write_image(options.output, pixels.view()); },
               image);
  }
  fmt::print("wrote {}\n", options.output);
  return kSuccess;
}

CLI::App* add_info(CLI::App& image, const std::shared_ptr<InfoOptions>& options) {
  CLI::App* info = image.add_subcommand(
      "info", "Print the format, size, channels, bit depth and value statistics of an image.");
  info->add_option("FILE", options->file, "PGM/PPM (P5/P6), PNG or PFM file")->required();
  info->add_flag("--json", options->json, "Print one JSON object instead of text");
  return info;
}

CLI::App* add_convert(CLI::App& image, const std::shared_ptr<ConvertOptions>& options) {
  CLI::App* convert = image.add_subcommand(
      "convert", "Convert an image; OUT's extension (.pgm .ppm .png .pfm) picks the format.");
  convert->add_option("IN", options->input, "Input image (PGM/PPM, PNG or PFM)")->required();
  convert->add_option("OUT", options->output, "Output image")->required();
  CLI::Option* colour = convert->add_flag("--colour", options->colour,
                                          "Render a one-channel image as a false-colour picture");
  options->min_option =
      convert->add_option("--min", options->min, "Value at the bottom of the colour scale")
          ->check(real_between(-kLargestFloat, kLargestFloat))
          ->needs(colour);
  options->max_option =
      convert->add_option("--max", options->max, "Value at the top of the colour scale")
          ->check(real_between(-kLargestFloat, kLargestFloat))
          ->needs(colour);
  convert->add_option("--unit", options->unit, "Unit shown on the legend, e.g. px or m")
      ->needs(colour);
  convert->add_option("--title", options->title, "Title shown above the legend")->needs(colour);
  return convert;
}

} // namespace

Command make_image_command(CLI::App& parent) {
  CLI::App* image = parent.add_subcommand("image", "Inspect and convert image files.");
  image->require_subcommand(1);
  auto info_options = std::make_shared<InfoOptions>();
  auto convert_options = std::make_shared<ConvertOptions>();
  CLI::App* info = add_info(*image, info_options);
  CLI::App* convert = add_convert(*image, convert_options);
  return {image, [=]() {
            if (info->parsed())
              return run_info(*info_options);
            if (convert->parsed())
              return run_convert(*convert_options);
            return static_cast<int>(kUsageError);
          }};
}

} // namespace marsokhod::apps
