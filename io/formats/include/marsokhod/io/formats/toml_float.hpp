// Writing a double into a TOML file so that it reads back to the same double.
#pragma once

#include <string>

namespace marsokhod::io {

/// The shortest text that reads back to the same double, always a TOML float ("1.0", not "1"),
/// for the files the project writes (rigs, calibrations). `value` must be finite: TOML spells
/// infinities and NaN otherwise.
std::string toml_float(double value);

} // namespace marsokhod::io
