// File: metrics.h
// -----------------------------------------------------------------------------
// The Prometheus metrics of one meshseg-server process, and the text
// exposition format 0.0.4 they are served in (metrics_listener.h serves
// GET /metrics). A small writer of our own: prometheus-cpp is not packaged
// for Debian 12.
//
// Counters and histograms count what happened in THIS process (Prometheus
// adds them up over replicas): an api replica counts uploads and jobs
// cancelled while queued, a worker counts attempts, claims, stage and job
// durations and terminal states. The gauges are read when scraped:
//   meshseg_jobs_queued   jobs waiting in the queue (embedded: this server's;
//                         Redis: the shared stream's backlog, the same on
//                         every replica, so take max(), not sum());
//   meshseg_jobs_running  jobs running on this process's workers;
//   meshseg_admission_reserved_bytes  memory reserved by admission control
//                         (0 until admission control exists, issue #30).
//
// Hooks are one call where the event happens (JobStarted in the worker, ...);
// all are thread-safe and cheap (one mutex, no allocation but a first stage
// name). The registry is process-wide, like a Prometheus client's default
// registry.
#ifndef MESHSEG_SERVER_METRICS_H_
#define MESHSEG_SERVER_METRICS_H_

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/status.h"
#include "absl/time/time.h"

namespace meshseg::server {

// A histogram with fixed upper bounds (the +Inf bucket is implied).
class Histogram {
 public:
  explicit Histogram(std::vector<double> bounds);
  void Observe(double value);

  const std::vector<double>& bounds() const { return bounds_; }
  // Observations <= bounds()[i], per bucket (not cumulative); the last entry
  // counts those above every bound.
  const std::vector<uint64_t>& counts() const { return counts_; }
  double sum() const { return sum_; }
  uint64_t count() const { return count_; }

 private:
  std::vector<double> bounds_;
  std::vector<uint64_t> counts_;
  double sum_ = 0.0;
  uint64_t count_ = 0;
};

// Writes metric families in the text exposition format 0.0.4: a HELP and a
// TYPE line per family, then its samples; label values and help escaped.
class ExpositionWriter {
 public:
  using Labels = std::vector<std::pair<std::string, std::string>>;
  // Starts a family; `type` is counter, gauge, histogram or untyped.
  void Family(std::string_view name, std::string_view type, std::string_view help);
  void Sample(std::string_view name, const Labels& labels, double value);
  // The _bucket (cumulative, le="+Inf" last), _sum and _count samples.
  void HistogramSamples(std::string_view name, const Labels& labels, const Histogram& histogram);
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

class Metrics {
 public:
  // The process-wide registry.
  static Metrics& Global();

  // What the scrape-time gauges read; each function may be empty. queued
  // returns nullopt when the queue cannot be reached (the sample is left
  // out). Set by the server when it starts, cleared when it stops.
  struct Gauges {
    std::function<std::optional<int64_t>()> queued;
    std::function<int64_t()> running;
    std::function<int64_t()> admission_reserved_bytes;
  };
  void SetGauges(Gauges gauges);
  // Labels of meshseg_build_info besides the version.
  void SetBuildInfo(std::string_view role, std::string_view backend);

  // An upload was accepted as a job of `bytes` bytes.
  void UploadAccepted(int64_t bytes);
  // An upload was refused with `code` (meshseg_uploads_rejected_total{code}).
  void UploadRejected(absl::StatusCode code);
  // A worker here started an attempt of a job accepted at `accepted`; the
  // first attempt's wait is the queue wait.
  void JobStarted(absl::Time accepted, int attempt);
  // A worker here took over a job whose worker stopped heartbeating.
  void JobClaimed();
  // A job ended in `state` (SUCCEEDED, FAILED, CANCELLED) after running for
  // `run_time` here (nullopt: it did not run here, e.g. cancelled while
  // queued or given up after its worker died).
  void JobFinished(std::string_view state, std::optional<absl::Duration> run_time);
  // A pipeline stage of a job ran for `duration`.
  void StageDone(std::string_view stage, absl::Duration duration);
  // A worker here wrote a result of `bytes` bytes.
  void ResultWritten(int64_t bytes);

  // The text of GET /metrics.
  std::string Exposition() const;

  // Forgets every observation (tests).
  void ResetForTest();

 private:
  Metrics();
  struct State;
  State* state_;  // never freed: hooks may run during static destruction
};

// Times the stages of one job from its progress callbacks: Enter(stage) on
// every callback, Finish() when the job ends; each span of one stage is
// reported to Metrics::StageDone and to the log (event stage_done).
class StageTimer {
 public:
  explicit StageTimer(std::string job_id) : job_id_(std::move(job_id)) {}
  ~StageTimer() { Finish(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  void Enter(std::string_view stage);
  void Finish();

 private:
  std::string job_id_;
  std::string stage_;
  absl::Time since_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_METRICS_H_
