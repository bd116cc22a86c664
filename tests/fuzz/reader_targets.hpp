// The registry of file readers under mutation: one table line per reader.
#pragma once

#include "fuzz/mutation_engine.hpp"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::fuzz {

/// A valid example input of a reader.
struct Seed {
  std::string label;
  Bytes bytes;
};

/// What a reader returned that no valid file can give (a NaN, a size beyond the limits). Not
/// derived from std::exception, so that no reader can throw it by accident.
struct Garbage {
  std::string problem;
};

/// Seeds from files of the source tree, labelled by their paths relative to it; throws
/// std::runtime_error for a missing or empty one.
std::vector<Seed> shipped(std::initializer_list<const char*> paths);

/// Throws Garbage{problem} unless `ok`; the read calls use it to check what they got.
void expect(bool ok, const std::string& problem);

/// One reader: how its input is named, which seeds and companion files it needs, and the call.
struct ReaderTarget {
  /// Name on command lines and in test names ([a-z0-9_]).
  std::string_view name;
  /// The input's file name inside its work folder.
  std::string_view file_name;
  Syntax syntax;
  /// Valid examples to mutate.
  std::vector<Seed> (*seeds)();
  /// Writes files the input needs beside it (a processor file, images), or nullptr.
  void (*prepare)(const std::filesystem::path& folder);
  /// Reads the input and checks what it returned, throwing Garbage for impossible results.
  void (*read)(const std::filesystem::path& input);
  /// Another file of the folder a message may name instead of the input, or empty (the
  /// platform file whose processor file is the input).
  std::string_view also_named;
};

/// Every registered reader.
const std::vector<ReaderTarget>& reader_targets();

/// The reader called `name`, or nullptr.
const ReaderTarget* find_reader(std::string_view name);

/// The bytes of a file (for seeds and replays); empty when it cannot be read.
Bytes file_bytes(const std::filesystem::path& path);

/// Writes `bytes` to `path`, replacing it; throws std::runtime_error when it cannot.
void write_bytes(const std::filesystem::path& path, const Bytes& bytes);

} // namespace marsokhod::fuzz
