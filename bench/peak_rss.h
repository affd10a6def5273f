// Peak resident set and CPU time of this process so far, for the timing tools' reports.
#ifndef MESHSEG_BENCH_PEAK_RSS_H_
#define MESHSEG_BENCH_PEAK_RSS_H_

#include <sys/resource.h>

namespace meshseg::bench {

// Mebibytes (Linux reports ru_maxrss in KiB).
inline double PeakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// CPU seconds of this process so far (user + system, all threads): on a
// shared machine the wall time says more about the neighbours.
inline double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace meshseg::bench

#endif  // MESHSEG_BENCH_PEAK_RSS_H_
