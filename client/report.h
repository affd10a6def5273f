// File: report.h
// -----------------------------------------------------------------------------
// What the CLI prints for people: the region table of a result and one line
// per job.
#ifndef MESHSEG_CLIENT_REPORT_H_
#define MESHSEG_CLIENT_REPORT_H_

#include <string>

#include "meshseg/v1/service.pb.h"

namespace meshseg::cli {

// Returns a summary line and a table: id, type, faces, key parameters, rms.
std::string RegionTable(const v1::SegmentationResult& result);

// Returns two lines counting curves (by geometry, sharp/smooth), loops (by
// kind), corners and adjacent region pairs, then one line per feature.
std::string TopologySummary(const v1::SegmentationResult& result);

// Returns a line on the B-rep written to STEP (faces, closed solid or shell,
// validity, volume, edges, tolerances) and one line per face not built; or
// the line saying why no STEP file was written.
std::string BrepSummary(const v1::BrepReport& brep);

// Returns one line: id, state, file, progress or error.
std::string JobLine(const v1::Job& job);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_REPORT_H_
