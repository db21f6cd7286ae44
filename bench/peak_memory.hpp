#pragma once
// Peak resident memory of the benchmark process, reported beside the times.
#include <sys/resource.h>

namespace wirepack::bench {

// Peak resident set size so far [MiB] (Linux reports ru_maxrss in KiB).
inline double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

}  // namespace wirepack::bench
