// Whether this build runs under AddressSanitizer (gcc defines __SANITIZE_ADDRESS__, clang answers
// __has_feature): tests that bound time or memory loosen or skip those bounds there, since the
// sanitizer slows the work and keeps freed memory in quarantine.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define VIBRO_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VIBRO_UNDER_ASAN 1
#endif
#endif

namespace vibro::testing {

#ifdef VIBRO_UNDER_ASAN
inline constexpr bool kUnderAsan = true;
#else
inline constexpr bool kUnderAsan = false;
#endif

}  // namespace vibro::testing
