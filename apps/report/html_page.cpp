// The report page's HTML: escaping, embedded pictures, tables and the document around them.
#include "report/html_page.hpp"

#include "cli/command.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/text_file.hpp"

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

std::string base64(const std::string& bytes) {
  using namespace boost::archive::iterators;
  using Encoder = base64_from_binary<transform_width<std::string::const_iterator, 6, 8>>;
  std::string text(Encoder(bytes.begin()), Encoder(bytes.end()));
  text.append((3 - bytes.size() % 3) % 3, '=');
  return text;
}

constexpr std::string_view kStyle = R"(
body { font-family: sans-serif; margin: 2em auto; max-width: 75em; color: #222; }
h1 { border-bottom: 2px solid #444; }
h2 { margin-top: 2em; border-bottom: 1px solid #aaa; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; }
th { background: #eee; }
figure { display: inline-block; margin: 0.5em; vertical-align: top; }
figure img { max-width: 36em; border: 1px solid #ccc; }
figcaption { font-size: 0.85em; color: #555; }
.chart { max-width: 50em; margin: 1em 0; }
.pass { color: #060; font-weight: bold; }
.fail { color: #a00; font-weight: bold; }
)";

// The page marks what it drew, for a reader and for the browser test (docs/report.md): each
// chart's canvas the number of points it holds, each picture whether it decoded, and the body
// how long the page took to its load event.
constexpr std::string_view kSelfCheck = R"(
function marsokhodMarkDrawn(chart) {
  let points = 0;
  for (const set of chart.data.datasets) points += set.data.length;
  chart.canvas.dataset.points = String(points);
}
window.addEventListener("load", function() {
  for (const img of document.images)
    img.dataset.loaded = img.complete && img.naturalWidth > 0 ? "yes" : "no";
  document.body.dataset.loadMs = String(Math.round(performance.now()));
});
)";

} // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&#39;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

std::string embedded_png(const std::filesystem::path& png) {
  const std::string bytes = io::read_text_file(png, "picture");
  const std::string name = html_escape(png.filename().string());
  return fmt::format("<figure><img alt=\"{0}\" src=\"data:image/png;base64,{1}\"><figcaption>{0}"
                     "</figcaption></figure>\n",
                     name, base64(bytes));
}

std::string html_table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  std::string html = "<table>\n<tr>";
  for (const std::string& cell : header)
    html += "<th>" + cell + "</th>";
  html += "</tr>\n";
  for (const std::vector<std::string>& row : rows) {
    html += "<tr>";
    for (const std::string& cell : row)
      html += "<td>" + cell + "</td>";
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string inline_chart_library() {
  std::string code;
  try {
    code = io::read_text_file(kChartJsFile, "Chart.js library");
  } catch (const io::InputError& error) {
    throw CommandError(fmt::format("{} (Debian package libjs-chart.js; make run and make test "
                                   "install it)",
                                   error.what()));
  }
  if (code.find("</script") != std::string::npos)
    throw CommandError(
        fmt::format("{}: holds '</script', which would end the page's script", kChartJsFile));
  return "<script>\n" + code + "\n</script>\n";
}

std::string script_json(const nlohmann::json& value) {
  std::string text = value.dump();
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 2))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string chart_canvas(std::string_view id, const nlohmann::json& config) {
  return fmt::format("<div class=\"chart\"><canvas id=\"{0}\"></canvas></div>\n<script>"
                     "marsokhodMarkDrawn(new Chart(document.getElementById(\"{0}\"), {1}));"
                     "</script>\n",
                     html_escape(id), script_json(config));
}

std::string html_document(std::string_view title, std::string_view body) {
  return fmt::format("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<title>{0}</title>\n<style>{1}</style>\n<script>{2}</script>\n</head>\n"
                     "<body>\n<h1>{0}</h1>\n{3}</body>\n</html>\n",
                     html_escape(title), kStyle, kSelfCheck, body);
}

} // namespace marsokhod::apps
