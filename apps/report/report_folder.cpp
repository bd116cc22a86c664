// Recognising a command's output folder by the JSON it wrote.
#include "report/report_folder.hpp"

#include "cli/command.hpp"

#include "marsokhod/io/formats/json_file.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

std::optional<nlohmann::json> json_in(const fs::path& dir, const char* name) {
  const fs::path file = dir / name;
  std::error_code error;
  if (!fs::is_regular_file(file, error))
    return std::nullopt;
  try {
    return io::parse_json_file(file, name);
  } catch (const std::exception& failure) {
    throw CommandError(failure.what());
  }
}

bool holds(const std::optional<nlohmann::json>& doc, const char* key) {
  return doc && doc->is_object() && doc->contains(key);
}

} // namespace

namespace {

struct KindTexts {
  std::string_view name;
  std::string_view writer; ///< the command that writes such a folder
};

KindTexts texts_of(FolderKind kind) {
  switch (kind) {
  case FolderKind::world:
    return {"world", "world"};
  case FolderKind::cycle:
    return {"navigation cycle", "nav and emulate"};
  case FolderKind::reproduce:
    return {"reproduce", "reproduce"};
  case FolderKind::campaign:
    return {"campaign", "campaign"};
  case FolderKind::traverse:
    return {"traverse", "traverse"};
  case FolderKind::traverse_sweep:
    return {"traverse sweep", "eval traverse"};
  case FolderKind::terrain:
    return {"terrain evaluation", "eval terrain"};
  case FolderKind::fault:
    break;
  }
  return {"fault run", "fault"};
}

} // namespace

std::string_view to_string(FolderKind kind) {
  return texts_of(kind).name;
}

std::string_view writer_of(FolderKind kind) {
  return texts_of(kind).writer;
}

ReportFolder recognise_folder(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw CommandError(fmt::format("{}: not a folder; report reads the output folders of nav, "
                                   "emulate, world, reproduce, fault --out, campaign, traverse, "
                                   "eval traverse and eval terrain --pictures",
                                   dir.string()));
  if (auto doc = json_in(dir, "traverse.json"); holds(doc, "outcome"))
    return {dir, FolderKind::traverse, std::move(*doc)};
  if (auto doc = json_in(dir, "reproduce.json"); holds(doc, "figures"))
    return {dir, FolderKind::reproduce, std::move(*doc)};
  if (auto doc = json_in(dir, "summary.json"); holds(doc, "campaign") || holds(doc, "by_rocks"))
    return {dir, holds(doc, "campaign") ? FolderKind::campaign : FolderKind::traverse_sweep,
            std::move(*doc)};
  if (auto doc = json_in(dir, "fault.json"); holds(doc, "outcome"))
    return {dir, FolderKind::fault, std::move(*doc)};
  if (auto doc = json_in(dir, "terrain.json"); holds(doc, "per_seed"))
    return {dir, FolderKind::terrain, std::move(*doc)};
  if (auto doc = json_in(dir, "path.json"); holds(doc, "found"))
    return {dir, FolderKind::cycle, std::move(*doc)};
  if (auto doc = json_in(dir, "scene.json"); holds(doc, "terrain"))
    return {dir, FolderKind::world, std::move(*doc)};
  throw CommandError(fmt::format(
      "{}: not an output folder report knows: it looks for traverse.json (traverse), "
      "reproduce.json (reproduce), summary.json (campaign, eval traverse), fault.json (fault "
      "--out), terrain.json (eval terrain --pictures), path.json (nav, emulate) or scene.json "
      "(world)",
      dir.string()));
}

} // namespace marsokhod::apps
