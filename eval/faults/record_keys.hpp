// Reading a record's keys back with the key named in every error (private to the layer).
#pragma once

#include "marsokhod/eval/faults/record_error.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace marsokhod::eval::detail {

/// `json[key]` as a T; RecordError naming the key when it is missing or of another kind.
template <typename T>
T record_value(const nlohmann::json& json, const char* key) {
  if (!json.is_object() || !json.contains(key))
    throw RecordError(std::string("the record has no '") + key + "'");
  try {
    return json.at(key).get<T>();
  } catch (const nlohmann::json::exception& error) {
    throw RecordError(std::string("the record's '") + key + "': " + error.what());
  }
}

/// `json[key]` as a T, nothing when it is null or (with `may_be_absent`) missing.
template <typename T>
std::optional<T> optional_record_value(const nlohmann::json& json, const char* key,
                                       bool may_be_absent = false) {
  if (json.is_object() && (json.contains(key) ? json.at(key).is_null() : may_be_absent))
    return std::nullopt;
  return record_value<T>(json, key);
}

/// A JSON null for nothing, the value otherwise.
template <typename T>
nlohmann::ordered_json or_null(const std::optional<T>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

} // namespace marsokhod::eval::detail
