// Platform and processor files as TOML: their tables throw PlatformError.

#include "platform/platform_toml.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <utility>

namespace marsokhod::emulator::detail {

io::TomlTable platform_table(const toml::table& table, std::string file, std::string where) {
  return io::TomlTable(table, std::move(file), std::move(where), io::throw_keyed<PlatformError>);
}

toml::table parse_toml_file(const std::string& file, std::string_view kind) {
  try {
    return io::parse_toml_file(file, kind);
  } catch (const io::InputError& error) {
    // A syntax error has a line; a file that could not be read has none.
    if (error.line() > 0)
      throw PlatformError(file, error.line(), "", error.problem());
    throw UnreadableFileError(file, 0, "", error.problem());
  }
}

} // namespace marsokhod::emulator::detail
