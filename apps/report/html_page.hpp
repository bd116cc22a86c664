// A self-contained HTML page: text escaped, pictures embedded, no reference outside the file.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::apps {

/// Text made safe inside HTML elements and attribute values.
std::string html_escape(std::string_view text);

/// An <img> whose source is the PNG file itself, base64-encoded into a data: URI, with its
/// file name as caption; io::InputError naming the file when it cannot be read.
std::string embedded_png(const std::filesystem::path& png);

/// A table: a header row and rows of cells, each cell already HTML.
std::string html_table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows);

/// Debian's Chart.js (package libjs-chart.js), which the page carries inlined.
inline constexpr const char* kChartJsFile = "/usr/share/javascript/chart.js/chart.min.js";

/// A <script> holding Chart.js itself; CommandError naming the file and its package when it
/// cannot be read.
std::string inline_chart_library();

/// `value` as JSON text that can stand inside a <script>: "</" is written "<\/", so that no
/// string it holds can end the script element early.
std::string script_json(const nlohmann::json& value);

/// A chart drawn by Chart.js in the page: a <canvas> and the script that draws `config` (a
/// Chart.js configuration) on it.
std::string chart_canvas(std::string_view id, const nlohmann::json& config);

/// The whole page: <title> and <h1> `title`, then `body`; styles inlined.
std::string html_document(std::string_view title, std::string_view body);

} // namespace marsokhod::apps
