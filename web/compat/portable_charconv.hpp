// Floating-point <charconv> for a standard library that lacks it
// (emscripten 3.1.6 ships libc++ 13: no std::to_chars / std::from_chars for
// double). web/compat/libcxx_compat.hpp puts these functions into std for
// the wasm build only; natively the engine uses libstdc++'s, and
// tests/test_web_api.cpp checks that these give the same bytes.
//
// Everything here rests on the C library's correctly rounded conversions,
// which glibc and musl both provide: snprintf("%.*e") rounds a double to
// p significant digits exactly (round half to even on exact ties), and
// strtod reads a decimal back to the nearest double.
//
// Shortest form (to_chars(first, last, double)), as libstdc++ (Ryu) gives
// it: the fewest significant digits that read back as the same double
// and, among those, the closest to it. For a normal double:
//  - 15 digits: any decimal of at most 15 digits that reads back as v is
//    v rounded to 15 digits (DBL_DIG), trailing zeros removed; so if the
//    15-digit rounding reads back, it is the answer.
//  - 16 digits: the nearest 16-digit decimal, else one of its two
//    neighbours (the rounding interval is narrower than 1.5 units of the
//    16th digit, and it is convex, so at most one neighbour can work).
//  - 17 digits always read back.
// Subnormals have fewer digits of precision: every p from 1 is tried the
// same way. The text is then the shorter of the fixed and the scientific
// forms (fixed on a tie), exponents with at least two digits; a fixed
// form of an integral value is printed as its exact integer ("%.0f"),
// as libstdc++ does (1.2345678901234568e20 -> "123456789012345683968").
#pragma once

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>

namespace breakshot_compat {

namespace detail {

/// v > 0 rounded to p significant digits: digits[0..p) and the decimal
/// exponent of the first digit.
inline void round_to(double v, int p, char* digits, int& exponent) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", p - 1, v);
  int n = 0;
  const char* s = buf;
  for (; *s != 'e'; ++s) {
    if (*s >= '0' && *s <= '9') digits[n++] = *s;
  }
  exponent = std::atoi(s + 1);
}

/// The double that digits[0..p) x 10^(exponent - p + 1) reads back as.
inline double read_back(const char* digits, int p, int exponent) {
  char buf[64];
  std::memcpy(buf, digits, static_cast<std::size_t>(p));
  std::snprintf(buf + p, sizeof buf - static_cast<std::size_t>(p), "e%d", exponent - p + 1);
  return std::strtod(buf, nullptr);
}

/// digits +- one unit in the last place (p digits); false if the result
/// would change the number of digits (then it is not a candidate here:
/// a carry to 10...0 or a borrow to 0...9 has another exponent, and is
/// tried as the rounding at that exponent instead).
inline bool step(char* digits, int p, int dir) {
  int i = p - 1;
  if (dir > 0) {
    while (i >= 0 && digits[i] == '9') digits[i--] = '0';
    if (i < 0) return false;
    ++digits[i];
  } else {
    while (i >= 0 && digits[i] == '0') digits[i--] = '9';
    if (i < 0) return false;
    --digits[i];
    if (digits[0] == '0') return false;
  }
  return true;
}

/// Tries p digits: the nearest decimal, then its neighbours. On success
/// digits/exponent hold the decimal (p digits).
inline bool try_digits(double v, int p, char* digits, int& exponent) {
  round_to(v, p, digits, exponent);
  if (read_back(digits, p, exponent) == v) return true;
  for (const int dir : {1, -1}) {
    char d[32];
    std::memcpy(d, digits, static_cast<std::size_t>(p));
    if (step(d, p, dir) && read_back(d, p, exponent) == v) {
      std::memcpy(digits, d, static_cast<std::size_t>(p));
      return true;
    }
  }
  return false;
}

/// Shortest digits of v > 0 (finite): returns their count.
inline int shortest_digits(double v, char* digits, int& exponent) {
  int p = 17;
  if (v >= 2.2250738585072014e-308) {  // DBL_MIN: normal
    round_to(v, 15, digits, exponent);
    if (read_back(digits, 15, exponent) == v) {
      p = 15;
    } else if (try_digits(v, 16, digits, exponent)) {
      p = 16;
    } else {
      round_to(v, 17, digits, exponent);
    }
  } else {
    for (p = 1; p < 17; ++p) {
      if (try_digits(v, p, digits, exponent)) break;
    }
    if (p == 17) round_to(v, 17, digits, exponent);
  }
  while (p > 1 && digits[p - 1] == '0') --p;
  return p;
}

inline std::to_chars_result put(char* first, char* last, const char* text, std::size_t n) {
  if (static_cast<std::size_t>(last - first) < n) return {last, std::errc::value_too_large};
  std::memcpy(first, text, n);
  return {first + n, std::errc()};
}

}  // namespace detail

/// std::to_chars(first, last, v): the shortest round-trip text.
inline std::to_chars_result to_chars_shortest(char* first, char* last, double v) {
  char out[400];
  std::size_t n = 0;
  if (std::signbit(v)) {
    out[n++] = '-';
    v = -v;
  }
  if (std::isnan(v)) return detail::put(first, last, out, (std::memcpy(out + n, "nan", 3), n + 3));
  if (std::isinf(v)) return detail::put(first, last, out, (std::memcpy(out + n, "inf", 3), n + 3));
  if (v == 0.0) {
    out[n++] = '0';
    return detail::put(first, last, out, n);
  }
  char digits[32];
  int e = 0;
  const int p = detail::shortest_digits(v, digits, e);

  // Lengths of the two forms (without the sign).
  const int exp_digits = std::abs(e) >= 100 ? 3 : 2;
  const int sci_len = p + (p > 1 ? 1 : 0) + 2 + exp_digits;
  int fixed_len = 0;
  if (e >= 0) {
    fixed_len = p <= e + 1 ? e + 1 : p + 1;
  } else {
    fixed_len = 2 + (-e - 1) + p;
  }

  if (fixed_len <= sci_len) {
    if (e >= 0 && p <= e + 1) {
      // Integral: its exact value.
      const int k = std::snprintf(out + n, sizeof out - n, "%.0f", v);
      n += static_cast<std::size_t>(k);
    } else if (e >= 0) {
      std::memcpy(out + n, digits, static_cast<std::size_t>(e + 1));
      n += static_cast<std::size_t>(e + 1);
      out[n++] = '.';
      std::memcpy(out + n, digits + e + 1, static_cast<std::size_t>(p - e - 1));
      n += static_cast<std::size_t>(p - e - 1);
    } else {
      out[n++] = '0';
      out[n++] = '.';
      for (int i = 0; i < -e - 1; ++i) out[n++] = '0';
      std::memcpy(out + n, digits, static_cast<std::size_t>(p));
      n += static_cast<std::size_t>(p);
    }
  } else {
    out[n++] = digits[0];
    if (p > 1) {
      out[n++] = '.';
      std::memcpy(out + n, digits + 1, static_cast<std::size_t>(p - 1));
      n += static_cast<std::size_t>(p - 1);
    }
    const int k = std::snprintf(out + n, sizeof out - n, "e%c%02d", e < 0 ? '-' : '+', std::abs(e));
    n += static_cast<std::size_t>(k);
  }
  return detail::put(first, last, out, n);
}

/// std::to_chars(first, last, v, fmt, precision) for fixed and scientific
/// (printf's %.*f and %.*e, which is what the standard specifies).
inline std::to_chars_result to_chars_precision(char* first, char* last, double v,
                                               std::chars_format fmt, int precision) {
  if (precision < 0) precision = 6;
  const char* spec = fmt == std::chars_format::scientific ? "%.*e"
                     : fmt == std::chars_format::fixed    ? "%.*f"
                                                          : "%.*g";
  const int k = std::snprintf(nullptr, 0, spec, precision, v);
  if (k < 0 || last - first < k) return {last, std::errc::value_too_large};
  // snprintf writes a terminating zero: format into a buffer of k + 1.
  char small[512];
  char* buf = k < static_cast<int>(sizeof small) ? small : static_cast<char*>(std::malloc(static_cast<std::size_t>(k) + 1));
  if (buf == nullptr) return {last, std::errc::value_too_large};
  std::snprintf(buf, static_cast<std::size_t>(k) + 1, spec, precision, v);
  std::memcpy(first, buf, static_cast<std::size_t>(k));
  if (buf != small) std::free(buf);
  return {first + k, std::errc()};
}

/// std::from_chars(first, last, v, fmt) for fixed, scientific and general
/// decimal text: [-] digits [. digits] [(e|E) [+|-] digits], read with
/// strtod (correctly rounded). "inf", "infinity" and "nan" are accepted
/// as the standard says. Out of range: result_out_of_range, v unchanged.
inline std::from_chars_result from_chars_decimal(const char* first, const char* last, double& v,
                                                 std::chars_format fmt = std::chars_format::general) {
  const char* s = first;
  bool neg = false;
  if (s != last && *s == '-') {
    neg = true;
    ++s;
  }
  const auto word = [&](const char* w) {
    const std::size_t n = std::strlen(w);
    if (static_cast<std::size_t>(last - s) < n) return false;
    for (std::size_t i = 0; i < n; ++i) {
      const char c = s[i];
      if ((c | 0x20) != w[i]) return false;
    }
    return true;
  };
  if (word("infinity") || word("inf")) {
    const std::size_t n = word("infinity") ? 8 : 3;
    v = neg ? -HUGE_VAL : HUGE_VAL;
    return {s + n, std::errc()};
  }
  if (word("nan")) {
    const char* e = s + 3;
    if (e != last && *e == '(') {
      const char* q = e + 1;
      while (q != last && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
      if (q != last && *q == ')') e = q + 1;
    }
    v = neg ? -std::nan("") : std::nan("");
    return {e, std::errc()};
  }
  const char* p = s;
  std::size_t mantissa_digits = 0;
  while (p != last && *p >= '0' && *p <= '9') ++p, ++mantissa_digits;
  if (p != last && *p == '.') {
    ++p;
    while (p != last && *p >= '0' && *p <= '9') ++p, ++mantissa_digits;
  }
  if (mantissa_digits == 0) return {first, std::errc::invalid_argument};
  const char* end = p;
  const bool allow_exp = fmt != std::chars_format::fixed;
  if (allow_exp && p != last && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    if (q != last && (*q == '+' || *q == '-')) ++q;
    const char* digits = q;
    while (q != last && *q >= '0' && *q <= '9') ++q;
    if (q != digits) end = q;
  }
  if (fmt == std::chars_format::scientific && end == p) return {first, std::errc::invalid_argument};
  const std::size_t n = static_cast<std::size_t>(end - first);
  char small[128];
  char* buf = n < sizeof small ? small : static_cast<char*>(std::malloc(n + 1));
  if (buf == nullptr) return {first, std::errc::not_enough_memory};
  std::memcpy(buf, first, n);
  buf[n] = '\0';
  errno = 0;
  const double r = std::strtod(buf, nullptr);
  const bool range = errno == ERANGE;
  if (buf != small) std::free(buf);
  if (range && (std::isinf(r) || r == 0.0)) return {end, std::errc::result_out_of_range};
  v = r;
  return {end, std::errc()};
}

}  // namespace breakshot_compat
