// The reader table: seeds, companion files and the checked call of every project file reader.
#include "fuzz/reader_targets.hpp"

#include "fuzz/placement_reader.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/stereo/stereo_pairs.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"
#include "marsokhod/world/scene/scene.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace marsokhod::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = MARSOKHOD_SOURCE_DIR;

bool finite(double value) {
  return std::isfinite(value);
}

// ---- platform and processor files ----

std::vector<Seed> platform_seeds() {
  return shipped({"platforms/onboard.toml", "platforms/pc-card.toml"});
}
std::vector<Seed> processor_seeds() {
  return shipped({"platforms/processors/t805.toml"});
}

// A mutated platform file still names the shipped processor file beside it.
void prepare_platform(const fs::path& folder) {
  fs::create_directories(folder / "processors");
  write_bytes(folder / "processors/t805.toml",
              file_bytes(kSource / "platforms/processors/t805.toml"));
}

// A valid platform file naming the mutated processor file.
void prepare_processor(const fs::path& folder) {
  std::istringstream lines(file_bytes(kSource / "platforms/onboard.toml"));
  std::string text;
  for (std::string line; std::getline(lines, line);) {
    text += line.starts_with("processor =") ? "processor = \"processor.toml\"" : line;
    text += '\n';
  }
  write_bytes(folder / "platform.toml", text);
}

void check_platform(const emulator::PlatformSpec& platform) {
  const emulator::LinkTimingSpec& t = platform.link_timing;
  for (const double bits : {t.data_packet_bits, t.ack_packet_bits, t.ack_delay_bits,
                            t.ack_turnaround_bits, t.inter_packet_gap_bits})
    expect(finite(bits) && bits >= 0 && bits < 1e6, "link timing bits not finite and >= 0");
  expect(t.ack_turnaround_fixed >= 0, "negative ack_turnaround_fixed");
  for (const int speed : platform.link_speeds_mbps)
    expect(speed > 0, "link speed <= 0");
  for (const emulator::NodeSpec& node : platform.nodes) {
    const emulator::CpuSpec& cpu = node.cpu;
    expect(cpu.cycle > 0 && cpu.timeslice > 0 && cpu.high_timer_tick > 0 &&
               cpu.low_timer_tick > 0 && cpu.slices_before_deschedule > 0,
           fmt::format("node {}: a time <= 0: cycle {} timeslice {} high_timer_tick {} "
                       "low_timer_tick {} slices_before_deschedule {}",
                       node.name, cpu.cycle, cpu.timeslice, cpu.high_timer_tick, cpu.low_timer_tick,
                       cpu.slices_before_deschedule));
    expect(node.memory.external_bytes <= (std::size_t{1} << 32) &&
               node.memory.reserved_on_chip_bytes <= node.memory.on_chip_bytes,
           fmt::format("node {}: memory sizes: external {} reserved {} on-chip {}", node.name,
                       node.memory.external_bytes, node.memory.reserved_on_chip_bytes,
                       node.memory.on_chip_bytes));
    expect(node.links >= 0 && node.links <= 64,
           fmt::format("node {}: {} links", node.name, node.links));
  }
  for (const emulator::DeviceSpec& device : platform.devices) {
    expect(device.links >= 0 && device.links <= 64 && device.image_width >= 0 &&
               device.image_width <= imaging::kMaxImageSide && device.image_height >= 0 &&
               device.image_height <= imaging::kMaxImageSide && device.bits_per_pixel >= 0 &&
               device.bits_per_pixel <= 32,
           fmt::format("device {}: links {} image {}x{} bits_per_pixel {}", device.name,
                       device.links, device.image_width, device.image_height,
                       device.bits_per_pixel));
  }
  for (const emulator::WireSpec& wire : platform.wires)
    expect(wire.speed_mbps > 0, "wire speed <= 0");
}

void read_platform(const fs::path& input) {
  check_platform(emulator::load_platform(input));
}
void read_processor(const fs::path& input) {
  check_platform(emulator::load_platform(input.parent_path() / "platform.toml"));
}

// ---- rig files ----

std::vector<Seed> rig_seeds() {
  std::vector<Seed> seeds =
      shipped({"platforms/rigs/marsokhod-128.toml", "platforms/rigs/marsokhod-256.toml"});
  imaging::RigParameters tilted;
  tilted.right_misalignment = {120.0, -35.5, 12.0};
  seeds.push_back({"to_toml(misaligned)", imaging::StereoRig(tilted).to_toml()});
  return seeds;
}

void read_rig(const fs::path& input) {
  const imaging::StereoRig rig = imaging::StereoRig::load(input);
  const imaging::RigParameters& p = rig.parameters();
  const std::pair<const char*, double> figures[] = {
      {"mast_height_m", p.mast_height_m},
      {"mast_forward_m", p.mast_forward_m},
      {"pitch_down_deg", p.pitch_down_deg},
      {"focal_mm", p.focal_mm},
      {"sensor_mm", p.sensor_mm},
      {"baseline_m", p.baseline_m},
      {"pan_arcsec", p.right_misalignment.pan_arcsec},
      {"tilt_arcsec", p.right_misalignment.tilt_arcsec},
      {"roll_arcsec", p.right_misalignment.roll_arcsec},
      {"focal_px()", rig.focal_px()},
      {"vertical_fov_deg()", rig.vertical_fov_deg()}};
  for (const auto& [name, value] : figures)
    expect(finite(value), std::string(name) + " is not finite: " + std::to_string(value));
  expect(p.width_px >= 1 && p.width_px <= imaging::kMaxImageSide && p.height_px >= 1 &&
             p.height_px <= imaging::kMaxImageSide,
         "image size beyond the limits");
}

// ---- scene files ----

std::vector<Seed> scene_seeds() {
  world::SceneDescription scene;
  scene.placement.attitude = {2.5, -1.25};
  scene.outputs = {{"left", "left.pgm"}, {"right", "right.pgm"}};
  const nlohmann::json document = world::scene_to_json(scene);
  return {{"scene_to_json (indented)", document.dump(2) + "\n"},
          {"scene_to_json (compact)", document.dump()}};
}

void read_scene(const fs::path& input) {
  const imaging::Attitude attitude = world::read_scene_attitude(input);
  expect(finite(attitude.pitch_deg) && finite(attitude.roll_deg), "attitude not finite");
  // docs/formats.md, Scenes: the attitude nav --pitch and --roll accept, -45..45 deg.
  expect(std::abs(attitude.pitch_deg) <= 45 && std::abs(attitude.roll_deg) <= 45,
         "attitude beyond +-45 deg");
}

// ---- calibration files ----

std::vector<Seed> calibration_seeds() {
  nav::VerticalParallaxMap map{128, 128, {0.75, 2e-3, -1.5e-3, 1e-5, -2e-5, 3e-6}};
  nav::VerticalParallaxMap identity{256, 256, {}};
  return {{"vertical_parallax_to_toml(fit)", nav::vertical_parallax_to_toml(map, "fit on a pair")},
          {"vertical_parallax_to_toml(identity)", nav::vertical_parallax_to_toml(identity)}};
}

void read_calibration(const fs::path& input) {
  const nav::VerticalParallaxMap map = nav::load_vertical_parallax(input);
  expect(map.width >= 1 && map.width <= imaging::kMaxImageSide && map.height >= 1 &&
             map.height <= imaging::kMaxImageSide,
         "map size beyond the limits");
  for (const double c : map.coefficients)
    expect(finite(c), "a coefficient is not finite");
  expect(map.largest_shift() <= nav::kMaxVerticalShift, "shift beyond kMaxVerticalShift");
}

// ---- stereo-pair indexes ----

std::vector<Seed> pairs_seeds() {
  const std::string header =
      "name\tleft\tright\tgt\tgt_scale(disp=value/scale)\tgt_bits\twidth\theight\tmax_gt_disp_px\n";
  return {
      {"two pairs", header + "first\tleft.pgm\tright.pgm\tgt.pgm\t4\t8\t128\t64\t16\n"
                             "second\tleft.pgm\tright.pgm\t-\t-\t-\t128\t64\t-\n"},
      {"16-bit truth", header + "deep\tleft.pgm\tright.pgm\tgt16.pgm\t256\t16\t128\t64\t12.5\n"}};
}

// Small textured images the index points to, large enough for `eval stereo` to match them, so
// that the command-line run of a mutant that stays valid gets as far as scoring.
void prepare_pairs(const fs::path& folder) {
  imaging::Image<std::uint8_t> grey(128, 64, 1);
  for (std::size_t i = 0; i < grey.size(); ++i)
    grey.data()[i] = static_cast<std::uint8_t>((i * 2654435761U) >> 24);
  imaging::write_image(folder / "left.pgm", grey.view());
  imaging::write_image(folder / "right.pgm", grey.view());
  imaging::write_image(folder / "gt.pgm", grey.view());
  imaging::write_image(folder / "gt16.pgm", imaging::Image<std::uint16_t>(128, 64, 1, 512).view());
}

void read_pairs(const fs::path& input) {
  for (const eval::StereoPairEntry& entry : eval::read_stereo_pairs(input)) {
    expect(!entry.name.empty(), "a pair without a name");
    expect(entry.width >= 1 && entry.width <= imaging::kMaxImageSide && entry.height >= 1 &&
               entry.height <= imaging::kMaxImageSide,
           "pair size beyond the limits");
    expect(finite(entry.truth_scale) && entry.truth_scale > 0, "gt_scale not finite and > 0");
    expect(entry.truth_bits == 8 || entry.truth_bits == 16, "gt_bits neither 8 nor 16");
    if (entry.max_truth_disparity) {
      const double largest = *entry.max_truth_disparity;
      expect(finite(largest) && largest >= 0,
             "max_gt_disp_px not finite and >= 0: " + std::to_string(largest));
    }
  }
}

// ---- images ----

std::vector<Seed> image_seeds() {
  return shipped({"tests/fuzz/corpus/grey8.pgm", "tests/fuzz/corpus/commented.pgm",
                  "tests/fuzz/corpus/rgb16.ppm", "tests/fuzz/corpus/grey8.png",
                  "tests/fuzz/corpus/rgb16.png", "tests/fuzz/corpus/grey.pfm"});
}
std::vector<Seed> gray8_seeds() {
  std::vector<Seed> seeds = image_seeds();
  seeds.pop_back(); // float pixels have no grey range: read_gray8 rejects a valid PFM
  return seeds;
}
std::vector<Seed> pfm_seeds() {
  return shipped({"tests/fuzz/corpus/grey.pfm"});
}

template <class T>
void check_image(const imaging::Image<T>& image, int channels = 0) {
  expect(image.width() >= 1 && image.width() <= imaging::kMaxImageSide && image.height() >= 1 &&
             image.height() <= imaging::kMaxImageSide,
         "image size beyond the limits");
  expect(image.channels() == 1 || image.channels() == 3, "channel count");
  expect(channels == 0 || image.channels() == channels, "unexpected channel count");
  expect(image.size() == static_cast<std::size_t>(image.width()) *
                             static_cast<std::size_t>(image.height()) *
                             static_cast<std::size_t>(image.channels()),
         "sample count differs from the size");
}

void read_any_image(const fs::path& input) {
  std::visit([](const auto& image) { check_image(image); }, imaging::read_image(input));
}
void read_gray8_image(const fs::path& input) {
  check_image(imaging::read_gray8(input), 1);
}
void read_pfm_image(const fs::path& input) {
  check_image(imaging::read_pfm(input), 1);
}

// ---- campaign files ----

std::vector<Seed> campaign_seeds() {
  return shipped({"campaigns/hang-power.toml", "campaigns/links.toml", "campaigns/seu-edac.toml"});
}

void read_campaign(const fs::path& input) {
  const overswitch::CampaignSpec spec = overswitch::load_campaign(input);
  expect(!spec.platform.empty() && !spec.world_seeds.empty() && !spec.faults.empty(),
         "a campaign without platform, scenarios or faults");
  expect(spec.runs >= 1 && spec.runs <= overswitch::kMaxCampaignRuns, "runs out of range");
  expect(finite(spec.rock_cover) && spec.rock_cover >= 0 && spec.rock_cover <= 0.5,
         "rock_cover out of range");
  for (const overswitch::FaultMix& mix : spec.faults)
    expect(finite(mix.weight) && mix.weight > 0 && mix.from_share >= 0 &&
               mix.from_share < mix.to_share && mix.to_share <= 1,
           fmt::format("fault mix on line {}: weight {} shares {}..{}", mix.line, mix.weight,
                       mix.from_share, mix.to_share));
}

} // namespace

std::vector<Seed> shipped(std::initializer_list<const char*> paths) {
  std::vector<Seed> seeds;
  for (const char* path : paths) {
    Bytes bytes = file_bytes(kSource / path);
    if (bytes.empty())
      throw std::runtime_error("seed file " + (kSource / path).string() + " is missing or empty");
    seeds.push_back({path, std::move(bytes)});
  }
  return seeds;
}

void expect(bool ok, const std::string& problem) {
  if (!ok)
    throw Garbage{problem};
}

// A new reader joins with one line in this table, plus its seed and read functions above.
const std::vector<ReaderTarget>& reader_targets() {
  // One line a reader: name, input file name, syntax, seeds, companions, checked call, and
  // another file a message may name instead of the input.
  // clang-format off
  static const std::vector<ReaderTarget> targets = {
      {"platform",    "platform.toml",    Syntax::toml,   platform_seeds,    prepare_platform,  read_platform,    {}},
      {"processor",   "processor.toml",   Syntax::toml,   processor_seeds,   prepare_processor, read_processor,   "platform.toml"},
      {"rig",         "rig.toml",         Syntax::toml,   rig_seeds,         nullptr,           read_rig,         {}},
      {"scene",       "scene.json",       Syntax::json,   scene_seeds,       nullptr,           read_scene,       {}},
      {"calibration", "calibration.toml", Syntax::toml,   calibration_seeds, nullptr,           read_calibration, {}},
      {"pairs",       "PAIRS.tsv",        Syntax::tsv,    pairs_seeds,       prepare_pairs,     read_pairs,       {}},
      {"image",       "input.img",        Syntax::binary, image_seeds,       nullptr,           read_any_image,   {}},
      {"gray8",       "input.img",        Syntax::binary, gray8_seeds,       nullptr,           read_gray8_image, {}},
      {"pfm",         "input.pfm",        Syntax::binary, pfm_seeds,         nullptr,           read_pfm_image,   {}},
      {"placement",   "placement.toml",   Syntax::toml,   placement_seeds,   nullptr,           read_placement,   {}},
      {"campaign",    "campaign.toml",    Syntax::toml,   campaign_seeds,    nullptr,           read_campaign,    {}},
  };
  // clang-format on
  return targets;
}

const ReaderTarget* find_reader(std::string_view name) {
  for (const ReaderTarget& target : reader_targets())
    if (target.name == name)
      return &target;
  return nullptr;
}

Bytes file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_bytes(const fs::path& path, const Bytes& bytes) {
  // A new file, not a truncated one: ext4 flushes a file truncated and rewritten when it is
  // closed (auto_da_alloc), which costs milliseconds per input.
  std::error_code ignored;
  fs::remove(path, ignored);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out)
    throw std::runtime_error("cannot write " + path.string());
}

} // namespace marsokhod::fuzz
