// Campaign files: the platform, scenarios, fault mix, protection, upset rate and stopping rule
// of a fault-injection campaign (docs/faults.md, "Campaign file").
#pragma once

#include "marsokhod/io/formats/keyed_file_error.hpp"
#include "marsokhod/overswitch/faults/fault.hpp"
#include "marsokhod/overswitch/protection/protection.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::overswitch {

/// A campaign file is wrong: "FILE:LINE: 'KEY': problem", like a platform file's errors.
class CampaignError : public io::KeyedFileError {
public:
  using io::KeyedFileError::KeyedFileError;
};

/// One kind of fault in the mix: how often it is drawn, where and when it strikes.
struct FaultMix {
  Fault::Kind kind = Fault::Kind::hang;
  double weight = 1.0;
  /// Modules drawn from, uniformly; empty: the modules the platform powers at the start.
  std::vector<std::string> modules;
  /// The strike time is uniform over this share of the fault-free cycle, from its start.
  double from_share = 0.0;
  double to_share = 1.0;
  /// Upsets and stuck bits: where the bit is drawn.
  MemoryTarget memory;
  /// Link faults: the module's links drawn from (default: link 0, the module0-module1 wire of
  /// the onboard placement), the wire cut (LinkDirection), and for a link down, the range its
  /// duration is drawn from (nothing: for good). A flipped bit strikes a data byte drawn from
  /// the first `byte_within` bytes after the strike.
  std::vector<int> links{0};
  LinkDirection direction = LinkDirection::both;
  std::optional<std::pair<double, double>> down_for_s;
  std::uint64_t byte_within = 1;
  int line = 0;
};

/// An environment's upset rate: each run injects one upset, and the rate scales the outcome of
/// one upset to a year of operations (docs/faults.md, "Upset rates").
struct UpsetRate {
  std::string name; ///< a preset's name, or "custom"
  double per_bit_per_day = 0.0;
  std::string source; ///< where the preset's figure comes from
};

/// A whole campaign. Run k draws its scenario and fault from (seed, k) alone, so that any run
/// can be replayed without the others.
struct CampaignSpec {
  std::string source;
  std::string name;
  std::string description;
  /// A shipped platform's name or a file, relative to the campaign file's folder.
  std::string platform;
  std::uint64_t seed = 1;
  std::vector<std::uint64_t> world_seeds;
  std::string light = "high-sun";
  double rock_cover = 0.10;
  std::vector<FaultMix> faults;
  Protection protection;
  /// With an upset rate the summary gives the expected unsafe outcomes per year.
  std::optional<UpsetRate> upset_rate;
  std::uint64_t runs = 0;
  /// Stop before `runs` once the unsafe rate's 95 % interval is narrower than this.
  std::optional<double> ci_width;
};

/// Reads and checks a campaign file: every key known and of its type and range. Throws
/// CampaignError naming the file, line and key (io::InputError for an unreadable file or bad
/// TOML).
CampaignSpec load_campaign(const std::filesystem::path& file);

/// The most runs a campaign may ask for.
inline constexpr std::uint64_t kMaxCampaignRuns = 10'000'000;

} // namespace marsokhod::overswitch
