#pragma once
// kSanitizedBuild: true in an AddressSanitizer build (gcc defines __SANITIZE_ADDRESS__, clang
// answers __has_feature). Such builds run several times slower and cannot take ulimit -v, so
// a few tests narrow what they run there; the Release run covers the rest.
#if defined(__SANITIZE_ADDRESS__)
#define RIGIDFOLD_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RIGIDFOLD_TEST_ASAN 1
#endif
#endif

namespace rigidfold::test {
#ifdef RIGIDFOLD_TEST_ASAN
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
}  // namespace rigidfold::test
