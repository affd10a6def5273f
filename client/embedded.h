// File: embedded.h
// -----------------------------------------------------------------------------
// Files compiled into the `meshseg` binary (client/embed_file.cmake), so it
// needs none at run time: the HTML report's template, style and scripts, and
// the progress stage weights.
#ifndef MESHSEG_CLIENT_EMBEDDED_H_
#define MESHSEG_CLIENT_EMBEDDED_H_

namespace meshseg::cli::embedded {

extern const char kReportHtml[];      // client/html_report/report.html
extern const char kReportCss[];       // client/html_report/report.css
extern const char kReportGlJs[];      // client/html_report/gl.js
extern const char kReportViewerJs[];  // client/html_report/viewer.js
extern const char kReportPageJs[];    // client/html_report/page.js
extern const char kProgressStages[];  // client/progress_stages.txt

}  // namespace meshseg::cli::embedded

#endif  // MESHSEG_CLIENT_EMBEDDED_H_
