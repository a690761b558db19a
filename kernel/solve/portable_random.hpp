#pragma once
// A pseudo-random stream that is the same on every platform and compiler (splitmix64), for
// the deterministic multistart searches (general verdict starts, tangent-cone lines): the
// standard distributions are implementation-defined, so a fixed seed would not give the
// same answer everywhere.
#include <cstdint>

namespace rigidfold {

struct SplitMix64 {
  std::uint64_t state = 0;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }                 // [0, 1)
  double open_uniform() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }    // (0, 1)
};

}  // namespace rigidfold
