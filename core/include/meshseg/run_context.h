// File: run_context.h
// -----------------------------------------------------------------------------
// RunContext carries cooperative cancellation and progress reporting into
// long-running core stages. core/ starts no threads and never prints: stages
// call ctx.Progress(stage, fraction) and poll ctx.stop_requested(); on stop
// they return absl::CancelledError and let nothing partial escape.
#ifndef MESHSEG_RUN_CONTEXT_H_
#define MESHSEG_RUN_CONTEXT_H_

#include <functional>
#include <stop_token>
#include <string>
#include <string_view>

#include "absl/status/status.h"

namespace meshseg {

struct RunContext {
  // Requests a stop when its stop_source is triggered. Default: never stops.
  std::stop_token stop;
  // Called with the stage name and the fraction of that stage done, in [0, 1].
  // May be called from the calling thread only (stages report between
  // parallel sections, never from inside them). Empty = no reporting.
  std::function<void(std::string_view stage, double fraction)> on_progress;

  bool stop_requested() const { return stop.stop_requested(); }

  void Progress(std::string_view stage, double fraction) const {
    if (on_progress) on_progress(stage, fraction);
  }

  // Returns CancelledError naming `stage` when a stop was requested, else OK.
  absl::Status CheckStop(std::string_view stage) const {
    if (!stop_requested()) return absl::OkStatus();
    // append, not std::string + "...": GCC 12 reports a false -Warray-bounds
    // on the inlined operator+ (its moved temporary) where this is inlined.
    std::string message(stage);
    message.append(": stop requested");
    return absl::CancelledError(message);
  }
};

}  // namespace meshseg

#endif  // MESHSEG_RUN_CONTEXT_H_
