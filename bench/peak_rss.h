// Peak resident set of this process so far, for the timing tools' reports.
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

}  // namespace meshseg::bench

#endif  // MESHSEG_BENCH_PEAK_RSS_H_
