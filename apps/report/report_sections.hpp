// What the report says of each recognised folder: a headline for the summary and a section.
#pragma once

#include "report/report_folder.hpp"

#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// One folder in the report.
struct ReportSection {
  std::string headline; ///< one line of HTML for the summary at the top
  std::string body;     ///< the folder's section: its figures, charts and pictures
  bool charts = false;  ///< the body draws with Chart.js
};

/// The folder's section; `index`, its place in the page, keeps its charts' ids apart.
ReportSection report_section(const ReportFolder& folder, int index);

/// Whether a model figure matches a figure the paper states as text such as "takes 8 sec" or
/// "1.3 min": within half a unit of the paper's last digit (8 s: 7.5..8.5 s; 1.3 min:
/// 75..81 s), the precision the paper gives. Nothing when the text holds no such figure.
struct PaperCheck {
  double low_s = 0.0;
  double high_s = 0.0;
  bool pass = false;
};
std::optional<PaperCheck> check_against_paper(const std::string& paper_says, double model_s);

} // namespace marsokhod::apps
