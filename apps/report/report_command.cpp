// `marsokhod report DIR... [--out FILE.html] [--title T]`: every result of a run in one
// self-contained HTML page (docs/report.md).

#include "cli/command.hpp"
#include "report/html_page.hpp"
#include "report/report_folder.hpp"
#include "report/report_sections.hpp"

#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct ReportCli {
  std::vector<fs::path> folders;
  fs::path out = "report.html";
  std::string title = "marsokhod: results";
};

int run_report(const ReportCli& cli) {
  std::vector<ReportSection> sections;
  for (const fs::path& dir : cli.folders)
    sections.push_back(report_section(recognise_folder(dir), static_cast<int>(sections.size())));
  std::string summary = "<h2>Summary</h2>\n<ul>\n";
  std::string body;
  for (const ReportSection& section : sections) {
    summary += "<li>" + section.headline + "</li>\n";
    body += section.body;
  }
  summary += "</ul>\n";
  const bool charts = std::any_of(sections.begin(), sections.end(),
                                  [](const ReportSection& s) { return s.charts; });
  const std::string page =
      html_document(cli.title, (charts ? inline_chart_library() : std::string()) + summary + body);
  io::write_file_atomically(cli.out, page);
  fmt::print("wrote {} ({} folders, {:.1f} MB): open it in a browser\n", cli.out.string(),
             sections.size(), static_cast<double>(page.size()) / 1e6);
  return kSuccess;
}

} // namespace

Command make_report_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "report", "Write one self-contained HTML page (pictures embedded, nothing fetched) with "
                "every result of the given output folders of world, nav, emulate, reproduce, "
                "campaign, traverse and eval traverse: a summary, then a section per folder.");
  auto cli = std::make_shared<ReportCli>();
  app->add_option("DIR", cli->folders, "Output folders, each recognised by the JSON it holds")
      ->required();
  app->add_option("--out", cli->out, "The HTML file to write")->capture_default_str();
  app->add_option("--title", cli->title, "The page's title")->capture_default_str();
  return {app, [cli] { return run_report(*cli); }};
}

} // namespace marsokhod::apps
