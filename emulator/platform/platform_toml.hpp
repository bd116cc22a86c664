// Platform and processor files as TOML: parsed through the bounded reader, read a table at a time.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/io/formats/toml_table.hpp"

#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace marsokhod::emulator::detail {

/// One table of a platform or processor file, whose errors are PlatformErrors ending in
/// " (WHERE)": `where` is "[platform]", "a [[node]]", "the processor file".
io::TomlTable platform_table(const toml::table& table, std::string file, std::string where);

/// A file that could not be read at all (missing, a directory, a FIFO, too large), as opposed
/// to one whose text is wrong; lets a platform say which of its keys named the file.
class UnreadableFileError : public PlatformError {
public:
  using PlatformError::PlatformError;
};

/// Parses a TOML file through the bounded reader (regular files of at most 16 MiB only: a
/// directory, FIFO or device is refused, never read), turning syntax errors and unreadable
/// files into PlatformError. `kind` names the file in messages ("platform file").
toml::table parse_toml_file(const std::string& file, std::string_view kind);

} // namespace marsokhod::emulator::detail
