#pragma once
// Whether this test binary runs under AddressSanitizer (scripts/test_sanitize.sh builds with
// address,undefined; GCC defines __SANITIZE_ADDRESS__, Clang answers __has_feature). There a
// step costs 20-50 times what it costs in Release, and the scenes that take over 8 s in Release
// run a shorter version of themselves: the sanitizers look for memory errors and undefined
// behaviour on the same code paths; the physics at full length is the Release suite's.
namespace wirepack::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

}  // namespace wirepack::testing
