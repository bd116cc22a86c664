// Writing an output file so that a reader never sees half of it and a failed write is an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace marsokhod::io {

/// Writes `bytes` to a temporary beside `path`, then renames it over `path`. A full disk, a
/// missing folder or a failed close is an OutputError naming the file.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

} // namespace marsokhod::io
