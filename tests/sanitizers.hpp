// Whether the tests are built under AddressSanitizer (the asan preset),
// for the long tests that run a smaller count there: GCC defines
// __SANITIZE_ADDRESS__, clang answers __has_feature(address_sanitizer).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define BREAKSHOT_TESTS_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BREAKSHOT_TESTS_UNDER_ASAN 1
#endif
#endif

inline constexpr bool kUnderSanitizers =
#if defined(BREAKSHOT_TESTS_UNDER_ASAN)
    true;
#else
    false;
#endif
