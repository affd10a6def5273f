// File: html_report.h
// -----------------------------------------------------------------------------
// `meshseg report`: one self-contained HTML file (no server, no network) with
// a 3D view of the mesh coloured per region (WebGL 2; client/html_report/),
// hover / click a face for its region's surface, rms and max error, a
// sortable region table, the features, the boundary curves with a toggle,
// the estimates and the timings. The mesh travels as base64 binary buffers
// (float32 positions, uint32 triangles, int32 labels), so a million faces
// load in seconds and stay interactive.
#ifndef MESHSEG_CLIENT_HTML_REPORT_H_
#define MESHSEG_CLIENT_HTML_REPORT_H_

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "client/job_progress.h"
#include "client/report_geometry.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg::cli {

struct ReportInputs {
  std::string title;  // shown as "meshseg report: <title>", e.g. the input's file name
  const v1::SegmentationResult* result = nullptr;
  // The drawn geometry; kind kNone for a report of tables only.
  ReportGeometry geometry;
  // Wall time per stage; empty when not known (a report of a saved result).
  std::vector<StageTime> timings;
};

// Returns the report's HTML. The page reads everything from the file itself;
// when loaded it sets <body data-state="ready" data-region-rows="N"
// data-webgl="yes|no">.
// Errors: INTERNAL if the result cannot be printed as JSON.
absl::StatusOr<std::string> HtmlReport(const ReportInputs& inputs);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_HTML_REPORT_H_
