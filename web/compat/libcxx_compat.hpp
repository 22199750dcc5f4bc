// Force-included (-include) into every source of the wasm build only
// (web/CMakeLists.txt). Emscripten 3.1.6 (Debian) ships libc++ 13, which
// lacks two C++20 pieces the engine uses:
//  - std::bit_cast (libc++ 14): given here by clang's __builtin_bit_cast;
//  - std::to_chars / std::from_chars for double: given here by
//    web/compat/portable_charconv.hpp, which gives the same bytes as
//    libstdc++'s (tests/test_web_api.cpp checks it on millions of values),
//    so result files and noise specs are the same text native and wasm.
// Declaring overloads in namespace std is not something a program may do
// in general; here it fills in what the standard says this library
// should already have, for one known library version, and each piece
// steps aside when the library has it (feature-test macros below).
#pragma once

#include <bit>
#include <charconv>
#include <version>

#include "portable_charconv.hpp"

namespace std {

#if !defined(__cpp_lib_bit_cast)
template <class To, class From>
constexpr To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From), "bit_cast: sizes differ");
  return __builtin_bit_cast(To, from);
}
#endif

#if !defined(__cpp_lib_to_chars)
inline to_chars_result to_chars(char* first, char* last, double value) {
  return breakshot_compat::to_chars_shortest(first, last, value);
}
inline to_chars_result to_chars(char* first, char* last, double value, chars_format fmt,
                                int precision) {
  return breakshot_compat::to_chars_precision(first, last, value, fmt, precision);
}
inline from_chars_result from_chars(const char* first, const char* last, double& value,
                                    chars_format fmt = chars_format::general) {
  return breakshot_compat::from_chars_decimal(first, last, value, fmt);
}
#endif

}  // namespace std
