// A self-contained HTML page: text escaped, pictures embedded, no reference outside the file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::apps {

/// Text made safe inside HTML elements and attribute values.
std::string html_escape(std::string_view text);

/// An <img> whose source is the PNG file itself, base64-encoded into a data: URI, with its
/// file name as caption; CommandError naming the file when it cannot be read.
std::string embedded_png(const std::filesystem::path& png);

/// A table: a header row and rows of cells, each cell already HTML.
std::string html_table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows);

/// The whole page: <title> and <h1> `title`, then `body`; styles inlined.
std::string html_document(std::string_view title, std::string_view body);

} // namespace marsokhod::apps
