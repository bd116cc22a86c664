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
  double low;   ///< smallest allowed value (excluded when low_excluded)
  double high;  ///< largest allowed value
  bool low_excluded;
  double (*get)(const RigParameters&);
  void (*set)(RigParameters&, double);
};

/// Every key of the rig file, in file order.
std::span<const RigField> rig_fields();

/// Why a value is not acceptable for a field, or nothing if it is.
std::optional<std::string> rig_value_problem(const RigField& field, double value);

} // namespace marsokhod::imaging::detail
