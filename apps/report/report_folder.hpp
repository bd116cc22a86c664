// The output folders `marsokhod report` reads, recognised by the JSON each command writes.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace marsokhod::apps {

/// Which command wrote a folder.
enum class FolderKind {
  world,          ///< world: scene.json
  cycle,          ///< nav or emulate: path.json (emulate's with its trace.json)
  reproduce,      ///< reproduce: reproduce.json
  campaign,       ///< campaign: summary.json naming its campaign, runs.jsonl
  traverse,       ///< traverse: traverse.json
  traverse_sweep, ///< eval traverse: summary.json with by_rocks, trials.jsonl
  terrain,        ///< eval terrain --pictures: terrain.json
  fault,          ///< fault --out: fault.json and its trace.json
};

std::string_view to_string(FolderKind kind);
/// The command that writes such a folder ("eval traverse").
std::string_view writer_of(FolderKind kind);

/// A recognised output folder and the JSON that identified it.
struct ReportFolder {
  std::filesystem::path dir;
  FolderKind kind = FolderKind::world;
  nlohmann::json doc;
};

/// Recognises the folder by its JSON; throws CommandError naming the folder and what a folder
/// must hold when it is none of the kinds (or is not a folder, or its JSON does not parse).
ReportFolder recognise_folder(const std::filesystem::path& dir);

} // namespace marsokhod::apps
