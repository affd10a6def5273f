// File: retry.h
// -----------------------------------------------------------------------------
// Retries a call while it answers UNAVAILABLE (the shared store is down),
// with exponential backoff from 100 ms to 5 s, logging the outage once when
// it starts and once when it ends, until the call answers anything else or
// `stop` is requested. Never spins.
#ifndef MESHSEG_SERVER_RETRY_H_
#define MESHSEG_SERVER_RETRY_H_

#include <algorithm>
#include <stop_token>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/time/clock.h"
#include "server/log.h"

namespace meshseg::server {

template <typename Call>
auto RetryWhileUnavailable(std::string_view what, const std::string& job_id, std::stop_token stop,
                           Call call) -> decltype(call()) {
  absl::Duration backoff = absl::Milliseconds(100);
  bool logged = false;
  while (true) {
    auto result = call();
    absl::Status status;
    if constexpr (std::is_same_v<decltype(result), absl::Status>) {
      status = result;
    } else {
      status = result.status();
    }
    if (status.code() != absl::StatusCode::kUnavailable || stop.stop_requested()) {
      if (logged) Log("store_reachable_again", {{"call", std::string(what)}, {"job", job_id}});
      return result;
    }
    if (!logged) {
      Log("store_unavailable_retrying",
          {{"call", std::string(what)}, {"job", job_id}, {"error", std::string(status.message())}});
      logged = true;
    }
    absl::SleepFor(backoff);
    backoff = std::min(backoff * 2, absl::Seconds(5));
  }
}

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_RETRY_H_
