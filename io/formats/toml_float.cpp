// TOML floats as the project's writers spell them.
#include "marsokhod/io/formats/toml_float.hpp"

#include <fmt/format.h>

namespace marsokhod::io {

std::string toml_float(double value) {
  // fmt's "{}" is the shortest round-trip text; an integral value gets no point of its own.
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eE") == std::string::npos)
    text += ".0";
  return text;
}

} // namespace marsokhod::io
