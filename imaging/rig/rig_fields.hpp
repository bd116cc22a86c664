// The keys of a rig description and their allowed values (private to the rig room).
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace marsokhod::imaging::detail {

/// One key of a rig description: its TOML table and name, where it lives in RigParameters and
/// which values make physical sense. Shared by the constructor's checks and the file reader so
/// both apply the same rules.
struct RigField {
  std::string_view table; ///< "rig" or "rig.right_misalignment"
  std::string_view key;
  bool integer; ///< TOML integer required (image sizes)
  double low;   ///< smallest allowed value
  double high;  ///< largest allowed value
  double (*get)(const RigParameters&);
  void (*set)(RigParameters&, double);
};

/// Every key of the rig file, in file order.
std::span<const RigField> rig_fields();

/// Why a value is not acceptable for a field, or nothing if it is, in the words a rig file's
/// reader (io::TomlTable::number_in) uses: "V is out of range: it must be between L and H".
std::optional<std::string> rig_value_problem(const RigField& field, double value);

/// The paper's reference obstacle (section 2), whose parallax `marsokhod rig` reports: a 30 cm
/// stone 14 m ahead of the rover centre. Every legal rig has it in front of its cameras.
inline constexpr double kReferenceStoneDistanceM = 14.0;
inline constexpr double kReferenceStoneHeightM = 0.3;

/// Why the rig as a whole cannot compute its geometry although each value is in range (the
/// cameras look away from the ground ahead), or nothing if it can.
std::optional<std::string> rig_geometry_problem(const RigParameters& parameters);

} // namespace marsokhod::imaging::detail
