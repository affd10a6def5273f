// meshseg-server: the segmentation service (proto/meshseg/v1/service.proto).
// Prints "listening on HOST:PORT" once it accepts calls; SIGTERM or SIGINT
// shut it down gracefully; SIGHUP re-reads the --auth-tokens file. Log lines
// (key=value) go to stderr.
#include <csignal>
#include <cstdio>
#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "absl/flags/flag.h"
#include "absl/flags/parse.h"
#include "absl/flags/usage.h"
#include "absl/flags/usage_config.h"
#include "absl/strings/str_cat.h"
#include "server/heap.h"
#include "server/log.h"
#include "server/server.h"
#include "server/usage.h"

namespace {
const meshseg::server::ServerOptions kDefaults;
}  // namespace

ABSL_FLAG(std::string, listen, kDefaults.listen, "HOST:PORT to listen on; port 0 = ephemeral");
ABSL_FLAG(std::string, role, "all",
          "all (accept and run jobs), api (accept uploads, serve jobs and results) or worker "
          "(run jobs only); api and worker need --queue redis://...");
ABSL_FLAG(int, workers, kDefaults.workers,
          "worker threads running jobs; 0 = one per CPU of the container's cgroup quota");
ABSL_FLAG(int, queue_capacity, kDefaults.queue_capacity,
          "max jobs waiting; further uploads get RESOURCE_EXHAUSTED");
ABSL_FLAG(int64_t, max_upload_bytes, kDefaults.max_upload_bytes, "max bytes of one upload");
ABSL_FLAG(std::string, spool_dir, kDefaults.spool_dir,
          "embedded mode: every job's upload, record and result, recovered at start; Redis "
          "mode: local scratch. One server per spool (locked)");
ABSL_FLAG(std::string, queue, kDefaults.queue,
          "empty = embedded (one process); redis://HOST:PORT[/DB] = shared Redis Stream queue "
          "and job records, for any number of api and worker replicas");
ABSL_FLAG(std::string, blob_dir, kDefaults.blob_dir,
          "Redis mode: folder every replica reaches (shared volume) for uploads and results");
ABSL_FLAG(int, max_attempts, kDefaults.max_attempts,
          "a job whose worker died this many times ends FAILED");
ABSL_FLAG(absl::Duration, claim_after, kDefaults.claim_after,
          "Redis mode: a job whose worker stopped heartbeating this long is taken over");
ABSL_FLAG(absl::Duration, result_ttl, kDefaults.result_ttl,
          "how long a finished job and its result are kept, e.g. 24h, 30m");
ABSL_FLAG(absl::Duration, shutdown_grace, kDefaults.shutdown_grace,
          "on SIGTERM/SIGINT, how long running jobs may take before they are cancelled");
ABSL_FLAG(std::string, metrics_listen, kDefaults.metrics_listen,
          "HOST:PORT serving Prometheus metrics at GET /metrics (text format 0.0.4); empty = "
          "off; port 0 = ephemeral (logged as event=metrics_listening)");
ABSL_FLAG(std::string, log_format, "text",
          "text (ts=... event=... key=value) or json (one JSON object per line)");
ABSL_FLAG(std::string, memory_budget, "0",
          "memory the jobs running here may take at once, by their estimated peak, e.g. 6Gi; "
          "a job over it is refused at upload, one that fits later waits; 0 = 85% of the "
          "container's memory limit (cgroup), else of the machine's (role api: not checked)");
ABSL_FLAG(std::string, min_free_disk, "256Mi",
          "free bytes kept on the spool and blob disks: an upload whose declared size would cut "
          "into it, with the uploads in flight, is refused before its data arrives");
ABSL_FLAG(int, max_concurrent_streams, kDefaults.max_concurrent_streams,
          "Upload, WatchJob and GetResult calls open at once, server-wide; more get "
          "RESOURCE_EXHAUSTED");
ABSL_FLAG(std::string, tls_cert, "", "PEM certificate chain of the server; with --tls-key = TLS");
ABSL_FLAG(std::string, tls_key, "", "PEM private key of --tls-cert");
ABSL_FLAG(std::string, tls_client_ca, "",
          "PEM CA certificate(s); set = mutual TLS: clients must present a certificate it "
          "signed");
ABSL_FLAG(std::string, auth_tokens, "",
          "file of \"TOKEN TENANT\" lines: every call but health needs \"authorization: Bearer "
          "TOKEN\" and sees only its tenant's jobs; re-read on SIGHUP");
ABSL_FLAG(bool, insecure, false,
          "without TLS, listen on the --listen address as given (plaintext from the network); "
          "without it a server with no TLS listens on 127.0.0.1 only");
ABSL_FLAG(bool, reflection, false,
          "serve gRPC server reflection (grpcurl lists and calls the API without .proto files)");

namespace {

// Returns argv with "--spool-dir=x" spelled "--spool_dir=x": the documented
// flags use hyphens, absl flag names use underscores.
std::vector<char*> UnderscoreFlagNames(int argc, char** argv, std::vector<std::string>& storage) {
  storage.assign(argv, argv + argc);
  for (std::string& arg : storage) {
    if (arg.rfind("--", 0) != 0) continue;
    const std::size_t end = std::min(arg.find('='), arg.size());
    for (std::size_t i = 2; i < end; ++i) {
      if (arg[i] == '-') arg[i] = '_';
    }
  }
  std::vector<char*> out;
  for (std::string& arg : storage) out.push_back(arg.data());
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kSynopsis[] = "meshseg-server --listen HOST:PORT [flags]";
  if (meshseg::server::WantsHelp(argc, argv)) {
    std::fputs(meshseg::server::UsageText(kSynopsis).c_str(), stdout);
    return 0;
  }
  absl::SetProgramUsageMessage(kSynopsis);
  absl::FlagsUsageConfig usage_config;
  usage_config.version_string = [] { return std::string("meshseg-server " MESHSEG_VERSION "\n"); };
  absl::SetFlagsUsageConfig(usage_config);
  std::vector<std::string> storage;
  std::vector<char*> args = UnderscoreFlagNames(argc, argv, storage);
  absl::ParseCommandLine(static_cast<int>(args.size()), args.data());
  absl::StatusOr<meshseg::server::LogFormat> log_format =
      meshseg::server::ParseLogFormat(absl::GetFlag(FLAGS_log_format));
  if (!log_format.ok()) {
    std::fprintf(stderr, "meshseg-server: %s\n", std::string(log_format.status().message()).c_str());
    return 1;
  }
  meshseg::server::SetLogFormat(*log_format);
  // A job's large buffers go back to the system when freed (server/heap.h).
  meshseg::server::MapLargeBlocks();

  // Block the shutdown signals in every thread; this one waits for them.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  meshseg::server::ServerOptions options;
  absl::StatusOr<meshseg::server::Role> role =
      meshseg::server::ParseRole(absl::GetFlag(FLAGS_role));
  if (!role.ok()) {
    std::fprintf(stderr, "meshseg-server: %s\n", std::string(role.status().message()).c_str());
    return 1;
  }
  options.role = *role;
  options.queue = absl::GetFlag(FLAGS_queue);
  options.blob_dir = absl::GetFlag(FLAGS_blob_dir);
  options.max_attempts = absl::GetFlag(FLAGS_max_attempts);
  options.claim_after = absl::GetFlag(FLAGS_claim_after);
  options.listen = absl::GetFlag(FLAGS_listen);
  options.workers = absl::GetFlag(FLAGS_workers);
  options.queue_capacity = absl::GetFlag(FLAGS_queue_capacity);
  options.max_upload_bytes = absl::GetFlag(FLAGS_max_upload_bytes);
  options.spool_dir = absl::GetFlag(FLAGS_spool_dir);
  options.result_ttl = absl::GetFlag(FLAGS_result_ttl);
  options.shutdown_grace = absl::GetFlag(FLAGS_shutdown_grace);
  options.metrics_listen = absl::GetFlag(FLAGS_metrics_listen);
  options.max_concurrent_streams = absl::GetFlag(FLAGS_max_concurrent_streams);
  for (const auto& [flag, text, out] :
       {std::tuple{"--memory-budget", absl::GetFlag(FLAGS_memory_budget), &options.memory_budget},
        std::tuple{"--min-free-disk", absl::GetFlag(FLAGS_min_free_disk),
                   &options.min_free_disk}}) {
    absl::StatusOr<int64_t> bytes = meshseg::server::ParseByteSize(text, flag);
    if (!bytes.ok()) {
      std::fprintf(stderr, "meshseg-server: %s\n", std::string(bytes.status().message()).c_str());
      return 1;
    }
    *out = *bytes;
  }
  options.security.tls_cert = absl::GetFlag(FLAGS_tls_cert);
  options.security.tls_key = absl::GetFlag(FLAGS_tls_key);
  options.security.tls_client_ca = absl::GetFlag(FLAGS_tls_client_ca);
  options.security.auth_tokens = absl::GetFlag(FLAGS_auth_tokens);
  options.security.insecure = absl::GetFlag(FLAGS_insecure);
  options.reflection = absl::GetFlag(FLAGS_reflection);

  auto server = meshseg::server::Server::Start(options);
  if (!server.ok()) {
    std::fprintf(stderr, "meshseg-server: %s\n", std::string(server.status().message()).c_str());
    return 1;
  }
  std::printf("listening on %s\n", (*server)->address().c_str());
  std::fflush(stdout);

  int signal_number = 0;
  while (sigwait(&signals, &signal_number) == 0 && signal_number == SIGHUP) {
    meshseg::server::Log("signal", {{"signal", "SIGHUP"}});
    (void)(*server)->ReloadTokens();  // logs the outcome; a bad file keeps the old tokens
  }
  meshseg::server::Log("signal", {{"signal", signal_number == SIGTERM ? "SIGTERM" : "SIGINT"}});
  (*server)->Shutdown();
  return 0;
}
