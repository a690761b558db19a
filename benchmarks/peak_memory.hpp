#pragma once
// Peak resident memory of the running benchmark process, for the benchmarks' peak_rss_mb
// counter (bench_report.sh runs each scaling_bench benchmark in its own process, so that the
// figure is that benchmark's own).
#include <sys/resource.h>

namespace rigidfold::bench {

// getrusage's peak resident memory of this process so far, in MiB.
inline double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kilobytes on Linux
}

}  // namespace rigidfold::bench
