// The study's report page: DIR/index.html, a static page that opens offline (file://).
// Tables, pictures, the comparison sliders and the videos are plain HTML written here;
// the charts are drawn by Chart.js (third_party/chartjs, vendored and copied beside the
// page) from the results embedded in the page as JSON; report.js and report.css
// (src/report/assets/) hold the page's own script and style. All three files are built
// into the program (report/assets.h), so `compare` works from any folder.
#pragma once

#include <string>

#include "report/results.h"

namespace sg {

std::string report_html(const StudyResults& r);

// index.html and the assets (chart.umd.min.js and its licence, report.js, report.css).
void write_report_html(const StudyResults& r, const std::string& out_dir);

// &, <, >, " and ' as HTML entities.
std::string html_escape(const std::string& s);

}  // namespace sg
