#pragma once
// kSanitizedBuild: true in an AddressSanitizer build (gcc defines __SANITIZE_ADDRESS__, clang
// answers __has_feature). Such builds cannot take ulimit -v (ASan reserves terabytes of
// address space): tests bound memory with ASan's hard_rss_limit_mb there instead.
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
// A sanitizer build with assertions on (Debug): many times slower than Release, where the
// largest inputs are left out. CI's sanitizer build is optimised (NDEBUG) and runs them all.
#if defined(RIGIDFOLD_TEST_ASAN) && !defined(NDEBUG)
inline constexpr bool kSlowSanitizedBuild = true;
#else
inline constexpr bool kSlowSanitizedBuild = false;
#endif
}  // namespace rigidfold::test
