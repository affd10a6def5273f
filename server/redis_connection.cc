#include "server/redis_connection.h"

#include <hiredis/hiredis.h>
#include <poll.h>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"

namespace meshseg::server {
namespace {

RedisValue Copy(const redisReply& reply) {
  RedisValue v;
  switch (reply.type) {
    case REDIS_REPLY_INTEGER:
      v.type = RedisValue::Type::kInteger;
      v.integer = reply.integer;
      break;
    case REDIS_REPLY_STRING:
    case REDIS_REPLY_STATUS:
    case REDIS_REPLY_ERROR:
      v.type = RedisValue::Type::kString;
      v.str.assign(reply.str, reply.len);
      break;
    case REDIS_REPLY_ARRAY:
      v.type = RedisValue::Type::kArray;
      for (size_t i = 0; i < reply.elements; ++i) v.elements.push_back(Copy(*reply.element[i]));
      break;
    default:
      break;
  }
  return v;
}

// Takes ownership of `raw` and converts it; an error reply becomes INTERNAL.
absl::StatusOr<RedisValue> Convert(void* raw, absl::string_view command) {
  std::unique_ptr<redisReply, void (*)(void*)> reply(static_cast<redisReply*>(raw),
                                                     freeReplyObject);
  if (reply->type == REDIS_REPLY_ERROR) {
    return absl::InternalError(
        absl::StrCat("redis: ", command, ": ", absl::string_view(reply->str, reply->len)));
  }
  return Copy(*reply);
}

// hiredis' view of `args`: pointers and lengths (binary-safe).
struct Argv {
  explicit Argv(const std::vector<std::string>& args) {
    for (const std::string& a : args) {
      ptrs.push_back(a.data());
      lens.push_back(a.size());
    }
  }
  int argc() const { return static_cast<int>(ptrs.size()); }
  std::vector<const char*> ptrs;
  std::vector<size_t> lens;
};

}  // namespace

absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url) {
  absl::string_view rest = url;
  if (!absl::ConsumePrefix(&rest, "redis://")) {
    return absl::InvalidArgumentError(
        absl::StrCat("--queue must be redis://HOST:PORT[/DB], got \"", url, "\""));
  }
  RedisAddress address;
  const std::size_t slash = rest.find('/');
  if (slash != absl::string_view::npos) {
    const absl::string_view db = rest.substr(slash + 1);
    if (!db.empty() && (!absl::SimpleAtoi(db, &address.db) || address.db < 0)) {
      return absl::InvalidArgumentError(
          absl::StrCat("--queue: database \"", db, "\" in \"", url, "\" is not a number >= 0"));
    }
    rest = rest.substr(0, slash);
  }
  const std::size_t colon = rest.rfind(':');
  address.host = std::string(rest.substr(0, colon));
  if (colon != absl::string_view::npos) {
    const absl::string_view port = rest.substr(colon + 1);
    if (!absl::SimpleAtoi(port, &address.port) || address.port < 1 || address.port > 65535) {
      return absl::InvalidArgumentError(
          absl::StrCat("--queue: port \"", port, "\" in \"", url, "\" is not in [1, 65535]"));
    }
  }
  if (address.host.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("--queue: no host in \"", url, "\""));
  }
  address.text = absl::StrCat(address.host, ":", address.port, "/", address.db);
  return address;
}

RedisConnection::RedisConnection(RedisAddress address, absl::Duration timeout)
    : address_(std::move(address)), timeout_(timeout) {}

RedisConnection::~RedisConnection() { Reset(); }

void RedisConnection::Reset() {
  if (context_ != nullptr) redisFree(context_);
  context_ = nullptr;
}

absl::Status RedisConnection::Broken(absl::string_view what) {
  const std::string error =
      context_ != nullptr && context_->errstr[0] != '\0' ? context_->errstr : "connection lost";
  Reset();
  return absl::UnavailableError(
      absl::StrCat("redis at ", address_.text, " unreachable (", what, ": ", error, ")"));
}

absl::Status RedisConnection::Connect() {
  if (context_ != nullptr && context_->err == 0) return absl::OkStatus();
  Reset();
  context_ =
      redisConnectWithTimeout(address_.host.c_str(), address_.port, absl::ToTimeval(timeout_));
  if (context_ == nullptr || context_->err != 0) return Broken("connect");
  redisSetTimeout(context_, absl::ToTimeval(timeout_));
  redisEnableKeepAlive(context_);
  if (address_.db != 0) {
    absl::StatusOr<RedisValue> selected = Command({"SELECT", absl::StrCat(address_.db)});
    if (!selected.ok()) return selected.status();
  }
  return absl::OkStatus();
}

absl::StatusOr<RedisValue> RedisConnection::Command(const std::vector<std::string>& args) {
  // Between a reply and the next command nothing is pending on a
  // request/reply connection, so input waiting now is the server's close
  // (Redis restarted while this connection sat idle in a pool). Reconnect
  // instead of failing the command on a socket hiredis still thinks is open.
  if (context_ != nullptr && context_->err == 0) {
    pollfd p{.fd = context_->fd, .events = POLLIN, .revents = 0};
    if (poll(&p, 1, 0) != 0) Reset();
  }
  if (absl::Status s = Connect(); !s.ok()) return s;
  Argv argv(args);
  void* reply = redisCommandArgv(context_, argv.argc(), argv.ptrs.data(), argv.lens.data());
  if (reply == nullptr) return Broken(args.empty() ? "" : args[0]);
  return Convert(reply, args.empty() ? "" : args[0]);
}

absl::Status RedisConnection::Send(const std::vector<std::string>& args) {
  if (absl::Status s = Connect(); !s.ok()) return s;
  Argv argv(args);
  if (redisAppendCommandArgv(context_, argv.argc(), argv.ptrs.data(), argv.lens.data()) !=
      REDIS_OK) {
    return Broken(args[0]);
  }
  int done = 0;
  while (!done) {
    if (redisBufferWrite(context_, &done) != REDIS_OK) return Broken(args[0]);
  }
  return absl::OkStatus();
}

absl::StatusOr<std::optional<RedisValue>> RedisConnection::Receive(absl::Duration wait) {
  if (context_ == nullptr || context_->err != 0) return Broken("receive");
  void* reply = nullptr;
  // A reply may already be buffered from an earlier read.
  if (redisGetReplyFromReader(context_, &reply) != REDIS_OK) return Broken("receive");
  if (reply == nullptr) {
    pollfd p{.fd = context_->fd, .events = POLLIN, .revents = 0};
    const int ready = poll(&p, 1, static_cast<int>(absl::ToInt64Milliseconds(wait)));
    if (ready == 0) return std::nullopt;
    if (ready < 0 || redisBufferRead(context_) != REDIS_OK) return Broken("receive");
    if (redisGetReplyFromReader(context_, &reply) != REDIS_OK) return Broken("receive");
    if (reply == nullptr) return std::nullopt;
  }
  absl::StatusOr<RedisValue> value = Convert(reply, "receive");
  if (!value.ok()) return value.status();
  return std::optional<RedisValue>(*std::move(value));
}

absl::StatusOr<RedisValue> RedisPool::Command(const std::vector<std::string>& args) {
  std::unique_ptr<RedisConnection> connection;
  {
    absl::MutexLock lock(&mu_);
    if (!idle_.empty()) {
      connection = std::move(idle_.back());
      idle_.pop_back();
    }
  }
  if (!connection) connection = std::make_unique<RedisConnection>(address_, timeout_);
  absl::StatusOr<RedisValue> reply = connection->Command(args);
  if (reply.ok() || reply.status().code() != absl::StatusCode::kUnavailable) {
    absl::MutexLock lock(&mu_);
    idle_.push_back(std::move(connection));
  }
  return reply;
}

}  // namespace meshseg::server
