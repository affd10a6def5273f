// File: redis_connection.h
// -----------------------------------------------------------------------------
// hiredis (a plain C library) behind two small RAII classes: one connection
// that reconnects on demand, and a thread-safe pool handing each concurrent
// caller its own connection (a blocking XREADGROUP holds one for its wait).
// Replies are copied into RedisValue; a Redis error reply is INTERNAL, an
// unreachable or broken connection is UNAVAILABLE naming the address.
#ifndef MESHSEG_SERVER_REDIS_CONNECTION_H_
#define MESHSEG_SERVER_REDIS_CONNECTION_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

struct redisContext;

namespace meshseg::server {

struct RedisAddress {
  std::string host;
  int port = 6379;
  int db = 0;
  std::string text;  // "HOST:PORT/DB", for messages
};

// Parses "redis://HOST:PORT[/DB]" (PORT defaults to 6379, DB to 0).
// Errors: INVALID_ARGUMENT naming the URL and what is wrong.
absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url);

// One reply. Strings, status replies and bulk strings are `str`.
struct RedisValue {
  enum class Type { kNil, kInteger, kString, kArray };
  Type type = Type::kNil;
  int64_t integer = 0;
  std::string str;
  std::vector<RedisValue> elements;

  bool is_nil() const { return type == Type::kNil; }
};

class RedisConnection {
 public:
  // Connects lazily, on the first command. `timeout` bounds connecting and
  // each reply (a blocking command must block for less).
  RedisConnection(RedisAddress address, absl::Duration timeout);
  ~RedisConnection();
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  // Runs one command (binary-safe arguments).
  absl::StatusOr<RedisValue> Command(const std::vector<std::string>& args);

  // Sends a command without reading its reply (SUBSCRIBE).
  absl::Status Send(const std::vector<std::string>& args);
  // Waits up to `wait` for the next pushed reply (a pub/sub message);
  // nullopt if none came.
  absl::StatusOr<std::optional<RedisValue>> Receive(absl::Duration wait);

  // Drops the connection (the next call reconnects).
  void Reset();

 private:
  absl::Status Connect();
  absl::Status Broken(absl::string_view what);

  const RedisAddress address_;
  const absl::Duration timeout_;
  redisContext* context_ = nullptr;
};

class RedisPool {
 public:
  RedisPool(RedisAddress address, absl::Duration timeout)
      : address_(std::move(address)), timeout_(timeout) {}

  // Runs one command on a free connection (a new one if none is free).
  absl::StatusOr<RedisValue> Command(const std::vector<std::string>& args);

  const RedisAddress& address() const { return address_; }

 private:
  const RedisAddress address_;
  const absl::Duration timeout_;
  absl::Mutex mu_;
  std::vector<std::unique_ptr<RedisConnection>> idle_ ABSL_GUARDED_BY(mu_);
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_REDIS_CONNECTION_H_
