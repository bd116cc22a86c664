// Reading a whole text input file (TOML, JSON, TSV) with every way it can go wrong bounded.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace marsokhod::io {

/// The largest text input any reader accepts unless it states its own limit: far above any
/// real platform, rig, scene or index file, far below what could exhaust memory.
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{16} << 20;

/// The whole of `path`, which must be a regular file of at most `max_bytes` bytes. `kind`
/// names the file for the user ("rig file"). Never blocks on a FIFO or device and never
/// allocates more than max_bytes; every failure is an InputError naming the file.
std::string read_text_file(const std::filesystem::path& path, std::string_view kind,
                           std::size_t max_bytes = kMaxTextFileBytes);

/// "16 MiB", "4096 bytes": a byte count as a limit is stated in a message.
std::string byte_count_text(std::size_t bytes);

} // namespace marsokhod::io
