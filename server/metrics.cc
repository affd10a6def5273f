#include "server/metrics.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "server/heap.h"
#include "server/log.h"

#ifndef MESHSEG_VERSION
#define MESHSEG_VERSION "unknown"
#endif

namespace meshseg::server {
namespace {

// Bucket bounds in seconds. Jobs run from a fraction of a second (small
// parts) to tens of minutes (CT scans of millions of faces); stages from
// milliseconds; queue waits from none to an hour of backlog.
const std::vector<double> kJobBounds = {0.1, 0.25, 0.5, 1, 2.5, 5, 10, 25, 50, 100, 250, 500,
                                        1000, 2500};
const std::vector<double> kStageBounds = {0.001, 0.005, 0.01, 0.05, 0.1, 0.5, 1, 5, 10, 50, 100,
                                          500};
const std::vector<double> kWaitBounds = {0.01, 0.05, 0.1, 0.5, 1, 5, 10, 30, 60, 300, 900, 3600};

// Stage names come from the pipeline (a fixed set); past this many distinct
// ones, further names count as "other" so a bug cannot explode the series.
constexpr size_t kMaxStages = 32;

std::string Number(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
  if (value == std::floor(value) && std::abs(value) < 9.0e15) {
    return absl::StrCat(static_cast<int64_t>(value));
  }
  // The shortest of 15 or 17 significant digits that reads back exactly.
  const std::string shorter = absl::StrFormat("%.15g", value);
  return std::strtod(shorter.c_str(), nullptr) == value ? shorter : absl::StrFormat("%.17g", value);
}

// Label values escape backslash, double quote and newline; help text
// backslash and newline (format 0.0.4).
std::string Escaped(std::string_view text, bool quote) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '"' && quote) {
      out += "\\\"";
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::string LabelText(const ExpositionWriter::Labels& labels) {
  if (labels.empty()) return "";
  std::string out = "{";
  for (size_t i = 0; i < labels.size(); ++i) {
    absl::StrAppend(&out, i ? "," : "", labels[i].first, "=\"", Escaped(labels[i].second, true),
                    "\"");
  }
  return out + "}";
}

// Resident set size of this process in bytes (0 if /proc is unreadable).
int64_t ResidentBytes() {
  std::ifstream statm("/proc/self/statm");
  int64_t pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * sysconf(_SC_PAGESIZE);
}

}  // namespace

Histogram::Histogram(std::vector<double> bounds)
    : bounds_(std::move(bounds)), counts_(bounds_.size() + 1, 0) {}

void Histogram::Observe(double value) {
  const auto bucket = std::lower_bound(bounds_.begin(), bounds_.end(), value) - bounds_.begin();
  ++counts_[bucket];
  sum_ += value;
  ++count_;
}

void ExpositionWriter::Family(std::string_view name, std::string_view type,
                              std::string_view help) {
  const std::string family(name);
  absl::StrAppend(&text_, "# HELP ", family, " ", Escaped(help, false), "\n# TYPE ", family, " ",
                  std::string(type), "\n");
}

void ExpositionWriter::Sample(std::string_view name, const Labels& labels, double value) {
  absl::StrAppend(&text_, std::string(name), LabelText(labels), " ", Number(value), "\n");
}

void ExpositionWriter::HistogramSamples(std::string_view name, const Labels& labels,
                                        const Histogram& histogram) {
  const std::string family(name);
  uint64_t cumulative = 0;
  for (size_t i = 0; i <= histogram.bounds().size(); ++i) {
    cumulative += histogram.counts()[i];
    Labels with_le = labels;
    with_le.emplace_back("le", i < histogram.bounds().size() ? Number(histogram.bounds()[i])
                                                             : std::string("+Inf"));
    Sample(absl::StrCat(family, "_bucket"), with_le, static_cast<double>(cumulative));
  }
  Sample(absl::StrCat(family, "_sum"), labels, histogram.sum());
  Sample(absl::StrCat(family, "_count"), labels, static_cast<double>(histogram.count()));
}

struct Metrics::State {
  mutable std::mutex mu;
  Gauges gauges;
  std::string role = "all";
  std::string backend = "embedded";
  // Terminal states in the order the API defines them.
  std::map<std::string, uint64_t> jobs_by_state = {
      {"succeeded", 0}, {"failed", 0}, {"cancelled", 0}};
  std::map<std::string, uint64_t> rejected_by_code;
  uint64_t accepted = 0;
  uint64_t upload_bytes = 0;
  uint64_t result_bytes = 0;
  uint64_t attempts = 0;
  uint64_t claims = 0;
  Histogram job_duration{kJobBounds};
  Histogram queue_wait{kWaitBounds};
  std::map<std::string, Histogram> stage_duration;
};

Metrics::Metrics() : state_(new State) {}

Metrics& Metrics::Global() {
  static Metrics* metrics = new Metrics();  // never destroyed: see state_
  return *metrics;
}

void Metrics::SetGauges(Gauges gauges) {
  std::lock_guard<std::mutex> lock(state_->mu);
  state_->gauges = std::move(gauges);
}

void Metrics::SetBuildInfo(std::string_view role, std::string_view backend) {
  std::lock_guard<std::mutex> lock(state_->mu);
  state_->role = std::string(role);
  state_->backend = std::string(backend);
}

void Metrics::UploadAccepted(int64_t bytes) {
  std::lock_guard<std::mutex> lock(state_->mu);
  ++state_->accepted;
  state_->upload_bytes += static_cast<uint64_t>(std::max<int64_t>(bytes, 0));
}

void Metrics::UploadRejected(absl::StatusCode code) {
  std::lock_guard<std::mutex> lock(state_->mu);
  ++state_->rejected_by_code[absl::StatusCodeToString(code)];
}

void Metrics::JobStarted(absl::Time accepted, int attempt) {
  std::lock_guard<std::mutex> lock(state_->mu);
  ++state_->attempts;
  if (attempt <= 1 && accepted != absl::UnixEpoch()) {
    state_->queue_wait.Observe(std::max(0.0, absl::ToDoubleSeconds(absl::Now() - accepted)));
  }
}

void Metrics::JobClaimed() {
  std::lock_guard<std::mutex> lock(state_->mu);
  ++state_->claims;
}

void Metrics::JobFinished(std::string_view state, std::optional<absl::Duration> run_time) {
  std::lock_guard<std::mutex> lock(state_->mu);
  ++state_->jobs_by_state[absl::AsciiStrToLower(std::string(state))];
  if (run_time) state_->job_duration.Observe(absl::ToDoubleSeconds(*run_time));
}

void Metrics::StageDone(std::string_view stage, absl::Duration duration) {
  std::lock_guard<std::mutex> lock(state_->mu);
  auto it = state_->stage_duration.find(std::string(stage));
  if (it == state_->stage_duration.end()) {
    const std::string name =
        state_->stage_duration.size() < kMaxStages ? std::string(stage) : std::string("other");
    it = state_->stage_duration.try_emplace(name, kStageBounds).first;
  }
  it->second.Observe(absl::ToDoubleSeconds(duration));
}

void Metrics::ResultWritten(int64_t bytes) {
  std::lock_guard<std::mutex> lock(state_->mu);
  state_->result_bytes += static_cast<uint64_t>(std::max<int64_t>(bytes, 0));
}

void Metrics::ResetForTest() {
  std::lock_guard<std::mutex> lock(state_->mu);
  State& s = *state_;
  for (auto& [state, n] : s.jobs_by_state) n = 0;
  s.rejected_by_code.clear();
  s.accepted = s.upload_bytes = s.result_bytes = s.attempts = s.claims = 0;
  s.job_duration = Histogram(kJobBounds);
  s.queue_wait = Histogram(kWaitBounds);
  s.stage_duration.clear();
}

std::string Metrics::Exposition() const {
  // Gauges are read before taking the lock: they may call Redis.
  Gauges gauges;
  {
    std::lock_guard<std::mutex> lock(state_->mu);
    gauges = state_->gauges;
  }
  const std::optional<int64_t> queued = gauges.queued ? gauges.queued() : std::nullopt;
  const int64_t running = gauges.running ? gauges.running() : 0;
  const int64_t reserved = gauges.admission_reserved_bytes ? gauges.admission_reserved_bytes() : 0;

  std::lock_guard<std::mutex> lock(state_->mu);
  const State& s = *state_;
  ExpositionWriter w;
  w.Family("meshseg_build_info", "gauge", "Always 1; the labels say which build and role runs.");
  w.Sample("meshseg_build_info",
           {{"version", MESHSEG_VERSION}, {"role", s.role}, {"backend", s.backend}}, 1);
  w.Family("meshseg_jobs_total", "counter",
           "Jobs that reached a terminal state in this process, by state.");
  for (const auto& [state, n] : s.jobs_by_state) {
    w.Sample("meshseg_jobs_total", {{"state", state}}, static_cast<double>(n));
  }
  w.Family("meshseg_jobs_accepted_total", "counter", "Uploads accepted as jobs by this process.");
  w.Sample("meshseg_jobs_accepted_total", {}, static_cast<double>(s.accepted));
  w.Family("meshseg_uploads_rejected_total", "counter",
           "Uploads refused by this process, by gRPC status code.");
  for (const auto& [code, n] : s.rejected_by_code) {
    w.Sample("meshseg_uploads_rejected_total", {{"code", code}}, static_cast<double>(n));
  }
  w.Family("meshseg_jobs_queued", "gauge",
           "Jobs waiting in the queue (Redis mode: the shared queue, same on every replica).");
  if (queued) w.Sample("meshseg_jobs_queued", {}, static_cast<double>(*queued));
  w.Family("meshseg_jobs_running", "gauge", "Jobs running on this process's workers.");
  w.Sample("meshseg_jobs_running", {}, static_cast<double>(running));
  w.Family("meshseg_job_duration_seconds", "histogram",
           "Run time of a job attempt on this process's workers, start to terminal state.");
  w.HistogramSamples("meshseg_job_duration_seconds", {}, s.job_duration);
  w.Family("meshseg_stage_duration_seconds", "histogram",
           "Time a job spent in each pipeline stage, by stage.");
  for (const auto& [stage, histogram] : s.stage_duration) {
    w.HistogramSamples("meshseg_stage_duration_seconds", {{"stage", stage}}, histogram);
  }
  w.Family("meshseg_queue_wait_seconds", "histogram",
           "Time from a job's acceptance to the start of its first attempt.");
  w.HistogramSamples("meshseg_queue_wait_seconds", {}, s.queue_wait);
  w.Family("meshseg_upload_bytes_total", "counter", "Bytes of uploads accepted as jobs.");
  w.Sample("meshseg_upload_bytes_total", {}, static_cast<double>(s.upload_bytes));
  w.Family("meshseg_result_bytes_total", "counter",
           "Bytes of results written by this process's workers.");
  w.Sample("meshseg_result_bytes_total", {}, static_cast<double>(s.result_bytes));
  w.Family("meshseg_admission_reserved_bytes", "gauge",
           "Memory reserved by admission control for admitted jobs.");
  w.Sample("meshseg_admission_reserved_bytes", {}, static_cast<double>(reserved));
  w.Family("meshseg_worker_attempts_total", "counter",
           "Job attempts started by this process's workers (a retried job counts again).");
  w.Sample("meshseg_worker_attempts_total", {}, static_cast<double>(s.attempts));
  w.Family("meshseg_worker_claims_total", "counter",
           "Jobs this process's workers took over from a worker that stopped heartbeating "
           "(Redis mode).");
  w.Sample("meshseg_worker_claims_total", {}, static_cast<double>(s.claims));
  w.Family("process_resident_memory_bytes", "gauge", "Resident memory size in bytes.");
  w.Sample("process_resident_memory_bytes", {}, static_cast<double>(ResidentBytes()));
  if (const std::optional<HeapUsage> heap = ReadHeapUsage()) {
    w.Family("meshseg_heap_in_use_bytes", "gauge",
             "Heap memory allocated and not freed (grows with a leak).");
    w.Sample("meshseg_heap_in_use_bytes", {}, static_cast<double>(heap->in_use_bytes));
    w.Family("meshseg_heap_free_bytes", "gauge",
             "Heap memory freed but kept by malloc for reuse (resident unless returned).");
    w.Sample("meshseg_heap_free_bytes", {}, static_cast<double>(heap->free_bytes));
  }
  return w.text();
}

void StageTimer::Enter(std::string_view stage) {
  if (stage == stage_) return;
  const absl::Time now = absl::Now();
  if (!stage_.empty()) {
    Metrics::Global().StageDone(stage_, now - since_);
    Log("stage_done", {{"job", job_id_},
                       {"stage", stage_},
                       {"seconds", absl::StrFormat("%.3f", absl::ToDoubleSeconds(now - since_))}});
  }
  stage_ = std::string(stage);
  since_ = now;
}

void StageTimer::Finish() { Enter(""); }

}  // namespace meshseg::server
