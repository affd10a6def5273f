#include "server/redis_job_store.h"

#include <algorithm>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "meshseg/proto/grpc_status.h"
#include "server/log.h"

namespace meshseg::server {
namespace {

constexpr char kJobs[] = "meshseg:jobs";
constexpr char kFinished[] = "meshseg:finished";
constexpr char kEvents[] = "meshseg:events";
// Bounds how far behind a missed pub/sub message can leave a watcher or a
// cancel: the subscriber re-checks this often regardless.
constexpr absl::Duration kRecheck = absl::Milliseconds(500);

std::string Key(const std::string& id) { return absl::StrCat("meshseg:job:", id); }
std::string Now() { return absl::StrCat(absl::ToUnixMillis(absl::Now())); }

// KEYS: job hash, jobs index, events, request key ("" = none). ARGV: record,
// created ms, id. Returns the id of the job that stands for the upload: a
// known job that claimed the request key, else the new one.
constexpr char kCreate[] = R"(
if KEYS[4] ~= '' then
  local existing = redis.call('GET', KEYS[4])
  if existing and redis.call('EXISTS', 'meshseg:job:' .. existing) == 1 then return existing end
  redis.call('SET', KEYS[4], ARGV[3])
end
redis.call('HSET', KEYS[1], 'record', ARGV[1], 'state', 1, 'attempts', 0, 'request_key', KEYS[4])
redis.call('ZADD', KEYS[2], ARGV[2], ARGV[3])
redis.call('PUBLISH', KEYS[3], ARGV[3])
return ARGV[3])";

// KEYS: job hash, jobs index. ARGV: id. Forgets the job and the request key
// it claimed (if the key still names it).
constexpr char kRemove[] = R"(
local request_key = redis.call('HGET', KEYS[1], 'request_key')
if request_key and request_key ~= '' and redis.call('GET', request_key) == ARGV[1] then
  redis.call('DEL', request_key)
end
redis.call('DEL', KEYS[1])
redis.call('ZREM', KEYS[2], ARGV[1])
return 1)";

// The key of a tenant's request id (tenants hold no ':', so the pair is
// unambiguous).
std::string RequestKey(const std::string& tenant, const std::string& request_id) {
  return request_id.empty() ? "" : absl::StrCat("meshseg:request:", tenant, ":", request_id);
}

// KEYS: job hash, finished index, events. ARGV: max attempts, now, id.
// Returns {outcome (0 not runnable, 1 run, 2 gave up), attempts, record}.
constexpr char kStart[] = R"(
local s = tonumber(redis.call('HGET', KEYS[1], 'state') or '0')
if s ~= 1 and s ~= 2 then return {0, 0, ''} end
if s == 2 and redis.call('HGET', KEYS[1], 'cancel') == '1' then
  -- cancelled while its worker was dying: end it rather than run it again
  redis.call('HSET', KEYS[1], 'state', 5, 'finished_ms', ARGV[2], 'error_code', 1,
    'error_message', 'cancelled by request', 'stage', '')
  redis.call('ZADD', KEYS[2], ARGV[2], ARGV[3])
  redis.call('PUBLISH', KEYS[3], ARGV[3])
  return {0, 0, ''}
end
local a = tonumber(redis.call('HGET', KEYS[1], 'attempts') or '0')
local record = redis.call('HGET', KEYS[1], 'record')
if a >= tonumber(ARGV[1]) then
  redis.call('HSET', KEYS[1], 'state', 4, 'finished_ms', ARGV[2], 'error_code', 10,
    'error_message', 'worker died ' .. a .. ' times running this job (--max-attempts ' ..
    ARGV[1] .. '); not run again', 'stage', '')
  redis.call('ZADD', KEYS[2], ARGV[2], ARGV[3])
  redis.call('PUBLISH', KEYS[3], ARGV[3])
  return {2, a, record}
end
redis.call('HSET', KEYS[1], 'state', 2, 'attempts', a + 1, 'started_ms', ARGV[2], 'stage', '',
  'fraction', 0)
redis.call('PUBLISH', KEYS[3], ARGV[3])
return {1, a + 1, record})";

// KEYS: job hash, events. ARGV: id, stage, fraction.
constexpr char kProgress[] = R"(
if redis.call('HGET', KEYS[1], 'state') ~= '2' then return 0 end
redis.call('HSET', KEYS[1], 'stage', ARGV[2], 'fraction', ARGV[3])
redis.call('PUBLISH', KEYS[2], ARGV[1])
return 1)";

// KEYS: job hash, finished index, events. ARGV: id, state, now, code,
// message, result size, faces, regions, STEP size, result sha256.
constexpr char kFinish[] = R"(
if redis.call('HGET', KEYS[1], 'state') ~= '2' then return 0 end
redis.call('HSET', KEYS[1], 'state', ARGV[2], 'finished_ms', ARGV[3], 'error_code', ARGV[4],
  'error_message', ARGV[5], 'result_size', ARGV[6], 'face_count', ARGV[7],
  'region_count', ARGV[8], 'step_size', ARGV[9], 'result_sha256', ARGV[10])
if ARGV[2] == '3' then redis.call('HSET', KEYS[1], 'fraction', 1) end
redis.call('HDEL', KEYS[1], 'cancel')
redis.call('ZADD', KEYS[2], ARGV[3], ARGV[1])
redis.call('PUBLISH', KEYS[3], ARGV[1])
return 1)";

// KEYS: job hash, events. ARGV: id.
constexpr char kRelease[] = R"(
if redis.call('HGET', KEYS[1], 'state') ~= '2' then return 0 end
local a = tonumber(redis.call('HGET', KEYS[1], 'attempts') or '1')
redis.call('HSET', KEYS[1], 'state', 1, 'attempts', math.max(a - 1, 0), 'stage', '',
  'fraction', 0, 'started_ms', 0)
redis.call('PUBLISH', KEYS[2], ARGV[1])
return 1)";

// KEYS: job hash, finished index, events. ARGV: id, now, reason.
// Returns 0 unknown, 1 was queued (now CANCELLED), 2 running (flag set),
// else 10 + the terminal state.
constexpr char kCancel[] = R"(
local s = tonumber(redis.call('HGET', KEYS[1], 'state') or '0')
if s == 0 then return 0 end
if s == 1 then
  redis.call('HSET', KEYS[1], 'state', 5, 'finished_ms', ARGV[2], 'error_code', 1,
    'error_message', ARGV[3])
  redis.call('ZADD', KEYS[2], ARGV[2], ARGV[1])
  redis.call('PUBLISH', KEYS[3], ARGV[1])
  return 1
end
if s == 2 then
  redis.call('HSET', KEYS[1], 'cancel', 1)
  redis.call('PUBLISH', KEYS[3], ARGV[1])
  return 2
end
return 10 + s)";

absl::StatusOr<RedisValue> Eval(RedisPool& pool, const char* script, std::vector<std::string> keys,
                                std::vector<std::string> args) {
  std::vector<std::string> command = {"EVAL", script, absl::StrCat(keys.size())};
  command.insert(command.end(), keys.begin(), keys.end());
  command.insert(command.end(), args.begin(), args.end());
  return pool.Command(command);
}

int64_t ToInt(const std::string& text) {
  int64_t v = 0;
  (void)absl::SimpleAtoi(text, &v);
  return v;
}

}  // namespace

RedisJobStore::RedisJobStore(RedisPool& pool, const JobQueue& queue) : pool_(pool), queue_(queue) {
  subscriber_ = std::jthread([this](std::stop_token stop) { Subscribe(stop); });
}

RedisJobStore::~RedisJobStore() {
  subscriber_.request_stop();
  if (subscriber_.joinable()) subscriber_.join();
}

absl::StatusOr<std::string> RedisJobStore::Create(JobRecord record) {
  record.set_format_version(1);
  record.mutable_job()->set_state(v1::JOB_STATE_QUEUED);
  const std::string id = record.job().job_id();
  absl::StatusOr<RedisValue> reply =
      Eval(pool_, kCreate,
           {Key(id), kJobs, kEvents, RequestKey(record.job().tenant(), record.job().request_id())},
           {record.SerializeAsString(), absl::StrCat(record.job().created_unix_ms()), id});
  if (!reply.ok()) return reply.status();
  return reply->str;
}

absl::StatusOr<std::optional<std::string>> RedisJobStore::FindRequest(
    const std::string& tenant, const std::string& request_id) const {
  if (request_id.empty()) return std::nullopt;
  absl::StatusOr<RedisValue> id = pool_.Command({"GET", RequestKey(tenant, request_id)});
  if (!id.ok()) return id.status();
  if (id->str.empty()) return std::nullopt;
  absl::StatusOr<RedisValue> exists = pool_.Command({"EXISTS", Key(id->str)});
  if (!exists.ok()) return exists.status();
  if (exists->integer != 1) return std::nullopt;
  return id->str;
}

void RedisJobStore::Remove(const std::string& id) {
  (void)Eval(pool_, kRemove, {Key(id), kJobs}, {id});
}

absl::StatusOr<JobRecord> RedisJobStore::Read(const std::string& id) const {
  absl::StatusOr<RedisValue> fields = pool_.Command({"HGETALL", Key(id)});
  if (!fields.ok()) return fields.status();
  std::map<std::string, std::string> f;
  for (size_t i = 0; i + 1 < fields->elements.size(); i += 2) {
    f[fields->elements[i].str] = fields->elements[i + 1].str;
  }
  JobRecord record;
  if (!f.contains("record") || !record.ParseFromString(f["record"])) return JobNotFound(id);
  v1::Job& job = *record.mutable_job();
  job.set_state(static_cast<v1::JobState>(ToInt(f["state"])));
  job.set_attempts(static_cast<int>(ToInt(f["attempts"])));
  job.set_stage(f["stage"]);
  double fraction = 0;
  (void)absl::SimpleAtod(f["fraction"], &fraction);
  job.set_fraction(fraction);
  job.set_started_unix_ms(ToInt(f["started_ms"]));
  job.set_finished_unix_ms(ToInt(f["finished_ms"]));
  job.set_error_code(static_cast<int>(ToInt(f["error_code"])));
  job.set_error_message(f["error_message"]);
  job.set_result_size(ToInt(f["result_size"]));
  job.set_result_sha256(f["result_sha256"]);
  job.set_face_count(ToInt(f["face_count"]));
  job.set_region_count(static_cast<int>(ToInt(f["region_count"])));
  job.set_step_size(ToInt(f["step_size"]));
  return record;
}

absl::StatusOr<v1::Job> RedisJobStore::Get(const std::string& id) const {
  absl::StatusOr<JobRecord> record = Read(id);
  if (!record.ok()) return record.status();
  v1::Job job = record->job();
  job.set_queue_position(job.state() == v1::JOB_STATE_QUEUED ? queue_.Position(id) : -1);
  return job;
}

absl::StatusOr<std::vector<v1::Job>> RedisJobStore::List() const {
  absl::StatusOr<RedisValue> ids = pool_.Command({"ZRANGE", kJobs, "0", "-1"});
  if (!ids.ok()) return ids.status();
  std::vector<v1::Job> jobs;
  for (const RedisValue& id : ids->elements) {
    absl::StatusOr<v1::Job> job = Get(id.str);
    if (job.ok()) jobs.push_back(*std::move(job));
    if (!job.ok() && job.status().code() == absl::StatusCode::kUnavailable) return job.status();
  }
  return jobs;
}

absl::StatusOr<JobStore::Started> RedisJobStore::Start(const std::string& id, int max_attempts) {
  absl::StatusOr<RedisValue> reply =
      Eval(pool_, kStart, {Key(id), kFinished, kEvents}, {absl::StrCat(max_attempts), Now(), id});
  if (!reply.ok()) return reply.status();
  Started out;
  if (reply->elements.size() != 3 || reply->elements[0].integer == 0) return out;
  absl::StatusOr<JobRecord> record = Read(id);  // with the fields just set
  if (!record.ok()) return record.status();
  out.spec.record = *std::move(record);
  if (reply->elements[0].integer == 2) {
    out.outcome = StartOutcome::kGaveUp;
  } else {
    out.outcome = StartOutcome::kRun;
    out.spec.stop = running_.Add(id);
  }
  return out;
}

void RedisJobStore::Progress(const std::string& id, std::string_view stage, double fraction) {
  // Best effort: progress lost while Redis is down is superseded by the next.
  (void)Eval(pool_, kProgress, {Key(id), kEvents},
             {id, std::string(stage), absl::StrCat(std::clamp(fraction, 0.0, 1.0))});
}

absl::Status RedisJobStore::Finish(const std::string& id, const absl::Status& status,
                                   const JobOutput& output) {
  const absl::StatusOr<RedisValue> reply =
      Eval(pool_, kFinish, {Key(id), kFinished, kEvents},
           {id, absl::StrCat(static_cast<int>(TerminalState(status))), Now(),
            absl::StrCat(static_cast<int>(status.code())), WireMessage(status),
            absl::StrCat(output.result_size), absl::StrCat(output.face_count),
            absl::StrCat(output.region_count), absl::StrCat(output.step_size),
            output.result_sha256});
  if (reply.ok()) running_.Erase(id);
  return reply.status();
}

absl::Status RedisJobStore::Release(const std::string& id) {
  const absl::StatusOr<RedisValue> reply = Eval(pool_, kRelease, {Key(id), kEvents}, {id});
  if (reply.ok()) running_.Erase(id);
  return reply.status();
}

absl::StatusOr<JobStore::CancelOutcome> RedisJobStore::Cancel(const std::string& id,
                                                              std::string_view reason) {
  absl::StatusOr<RedisValue> reply =
      Eval(pool_, kCancel, {Key(id), kFinished, kEvents},
           {id, Now(), WireMessage(absl::CancelledError(std::string(reason)))});
  if (!reply.ok()) return reply.status();
  switch (reply->integer) {
    case 0:
      return JobNotFound(id);
    case 1:
      return CancelOutcome::kWasQueued;
    case 2:
      running_.Stop(id, StopReason::kCancelled);  // if it runs here, at once
      return CancelOutcome::kStopRequested;
    default:
      return absl::FailedPreconditionError(
          absl::StrCat("job \"", id, "\" already finished (",
                       v1::JobState_Name(static_cast<v1::JobState>(reply->integer - 10)), ")"));
  }
}

std::vector<std::string> RedisJobStore::Expire(absl::Time cutoff) {
  std::vector<std::string> expired;
  absl::StatusOr<RedisValue> ids =
      pool_.Command({"ZRANGEBYSCORE", kFinished, "-inf",
                     absl::StrCat("(", absl::ToUnixMillis(cutoff)), "LIMIT", "0", "100"});
  if (!ids.ok()) return expired;
  for (const RedisValue& id : ids->elements) {
    // Whichever replica removes the index entry owns the cleanup.
    absl::StatusOr<RedisValue> removed = pool_.Command({"ZREM", kFinished, id.str});
    if (!removed.ok() || removed->integer != 1) continue;
    Remove(id.str);
    expired.push_back(id.str);
  }
  for (const std::string& id : expired) job_changes_.Bump(id);
  if (!expired.empty()) changes_.Bump();
  return expired;
}

int64_t RedisJobStore::generation() const { return changes_.value(); }

void RedisJobStore::AwaitChange(int64_t seen, absl::Duration timeout) const {
  changes_.Await(seen, timeout);
}

void RedisJobStore::CheckCancel(const std::string& id) {
  absl::StatusOr<RedisValue> flag = pool_.Command({"HGET", Key(id), "cancel"});
  if (flag.ok() && flag->str == "1") running_.Stop(id, StopReason::kCancelled);
}

void RedisJobStore::Subscribe(std::stop_token stop) {
  RedisConnection connection(pool_.address(), absl::Seconds(2));
  bool subscribed = false;
  absl::Duration backoff = absl::Milliseconds(100);
  absl::Time next_check = absl::Now();
  while (!stop.stop_requested()) {
    if (!subscribed) {
      subscribed = connection.Send({"SUBSCRIBE", kEvents}).ok();
      if (!subscribed) {
        absl::SleepFor(backoff);
        backoff = std::min(backoff * 2, absl::Seconds(2));
        continue;
      }
      backoff = absl::Milliseconds(100);
      changes_.Bump();  // watchers re-read what changed while unsubscribed
      job_changes_.BumpAll();
    }
    absl::StatusOr<std::optional<RedisValue>> message = connection.Receive(absl::Milliseconds(250));
    if (!message.ok()) {
      subscribed = false;
      connection.Reset();
      continue;
    }
    if (message->has_value()) {
      const RedisValue& m = **message;
      if (m.elements.size() == 3 && m.elements[0].str == "message") {
        changes_.Bump();
        // The message names the job; any event may move the queue (a start,
        // a cancel, a release), so queued jobs' watchers re-read too.
        job_changes_.Bump(m.elements[2].str);
        job_changes_.BumpQueued();
        const std::vector<std::string> here = running_.Ids();
        if (std::find(here.begin(), here.end(), m.elements[2].str) != here.end()) {
          CheckCancel(m.elements[2].str);
        }
      }
    }
    if (absl::Now() >= next_check) {
      for (const std::string& id : running_.Ids()) CheckCancel(id);
      next_check = absl::Now() + kRecheck;
    }
  }
}

}  // namespace meshseg::server
