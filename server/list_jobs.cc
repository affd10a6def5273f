#include <algorithm>
#include <optional>
#include <tuple>

#include "absl/strings/escaping.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "meshseg/proto/grpc_status.h"
#include "server/service.h"

namespace meshseg::server {
namespace {

constexpr int kDefaultPageSize = 100;
// A page of 1000 jobs is ~0.2 MB: far below the 4 MiB message limit.
constexpr int kMaxPageSize = 1000;

// A job's place in the listing: creation time, then id (ids are unique).
using Position = std::tuple<int64_t, std::string>;

Position PositionOf(const v1::Job& job) { return {job.created_unix_ms(), job.job_id()}; }

// The page token is the position of the last job sent, "MS/ID" in web-safe
// base64: opaque to clients, and it stays valid when jobs before or after it
// end or expire.
std::string TokenOf(const Position& p) {
  return absl::WebSafeBase64Escape(absl::StrCat(std::get<0>(p), "/", std::get<1>(p)));
}

absl::StatusOr<Position> ParseToken(const std::string& token) {
  const absl::Status bad =
      absl::InvalidArgumentError("list: page_token is not a next_page_token this server returned");
  std::string text;
  if (!absl::WebSafeBase64Unescape(token, &text)) return bad;
  const std::pair<std::string, std::string> parts = absl::StrSplit(text, absl::MaxSplits('/', 1));
  int64_t ms = 0;
  if (!absl::SimpleAtoi(parts.first, &ms) || parts.second.empty()) return bad;
  return Position{ms, parts.second};
}

}  // namespace

grpc::Status SegmentationService::ListJobs(grpc::ServerContext* context,
                                           const v1::ListJobsRequest* request,
                                           v1::ListJobsResponse* response) {
  if (request->page_size() < 0 || request->page_size() > kMaxPageSize) {
    return ToGrpcStatus(absl::InvalidArgumentError(
        absl::StrCat("list: page_size must be in [0, ", kMaxPageSize, "] (0 = ", kDefaultPageSize,
                     "), got ", request->page_size())));
  }
  if (!v1::JobState_IsValid(request->state())) {
    return ToGrpcStatus(absl::InvalidArgumentError(
        absl::StrCat("list: state ", request->state(), " is not a JobState")));
  }
  std::optional<Position> after;
  if (!request->page_token().empty()) {
    absl::StatusOr<Position> parsed = ParseToken(request->page_token());
    if (!parsed.ok()) return ToGrpcStatus(parsed.status());
    after = *std::move(parsed);
  }
  const absl::StatusOr<std::string> tenant = TenantOf(*context);
  if (!tenant.ok()) return ToGrpcStatus(tenant.status());
  absl::StatusOr<std::vector<v1::Job>> jobs = store_.List();
  if (!jobs.ok()) return ToGrpcStatus(jobs.status());

  std::vector<v1::Job*> mine;
  for (v1::Job& job : *jobs) {
    if (job.tenant() != *tenant) continue;
    if (request->state() != v1::JOB_STATE_UNSPECIFIED && job.state() != request->state()) continue;
    if (after.has_value() && PositionOf(job) <= *after) continue;
    mine.push_back(&job);
  }
  std::sort(mine.begin(), mine.end(),
            [](const v1::Job* a, const v1::Job* b) { return PositionOf(*a) < PositionOf(*b); });
  const std::size_t page =
      request->page_size() == 0 ? kDefaultPageSize : static_cast<std::size_t>(request->page_size());
  for (std::size_t i = 0; i < std::min(page, mine.size()); ++i) {
    *response->add_jobs() = std::move(*mine[i]);
  }
  if (mine.size() > page) {
    response->set_next_page_token(TokenOf(PositionOf(*response->jobs().rbegin())));
  }
  return grpc::Status::OK;
}

}  // namespace meshseg::server
