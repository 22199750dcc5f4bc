// strtod for the wasm build only (web/CMakeLists.txt links with
// -Wl,--wrap=strtod, so every call of strtod, nlohmann/json's number
// reading and web/compat/portable_charconv.hpp's included, comes here).
//
// musl's strtod reads through 128-bit long double, which wasm emulates
// in software (fmodl, __multf3, __addtf3): about a microsecond a number,
// a third of bs_playback_new's time on a 16-ball scenario. A plain
// decimal ([+|-] digits [. digits] [(e|E) [+|-] digits]) whose value is
// a normal double is read here with fast_float (Debian's
// libfast-float-dev, the Eisel-Lemire algorithm with an exact fallback):
// correctly rounded, as musl's strtod and glibc's are, so the double is
// the same bits. Everything else (hexadecimal, inf, nan, no digits,
// results that overflow or are subnormal or zero from nonzero digits,
// where strtod also sets errno) goes to musl's strtod as before.

#include <cctype>
#include <cfloat>
#include <cmath>
#include <system_error>

#include <fast_float/fast_float.h>

extern "C" double __real_strtod(const char* s, char** end);

extern "C" double __wrap_strtod(const char* s, char** end) {
  const char* p = s;
  while (std::isspace(static_cast<unsigned char>(*p))) ++p;
  bool neg = false;
  if (*p == '+' || *p == '-') {
    neg = *p == '-';
    ++p;
  }
  const char* first = p;
  const bool digit = (*p >= '0' && *p <= '9') || (*p == '.' && p[1] >= '0' && p[1] <= '9');
  const bool hex = *p == '0' && (p[1] == 'x' || p[1] == 'X');
  if (digit && !hex) {
    // The longest run that can belong to the number: fast_float stops
    // where the number ends, as strtod does.
    const char* last = p;
    while ((*last >= '0' && *last <= '9') || *last == '.' || *last == 'e' || *last == 'E' ||
           *last == '+' || *last == '-') {
      ++last;
    }
    double v = 0.0;
    const auto r = fast_float::from_chars(first, last, v, fast_float::chars_format::general);
    if (r.ec == std::errc() && std::isfinite(v) && v >= DBL_MIN) {
      if (end != nullptr) *end = const_cast<char*>(r.ptr);
      return neg ? -v : v;
    }
    // A zero written as zero ("0", "0.000", "0e5") is exact and sets no
    // errno either.
    if (r.ec == std::errc() && v == 0.0) {
      bool nonzero = false;
      for (const char* q = first; q != r.ptr && *q != 'e' && *q != 'E'; ++q) {
        nonzero = nonzero || (*q >= '1' && *q <= '9');
      }
      if (!nonzero) {
        if (end != nullptr) *end = const_cast<char*>(r.ptr);
        return neg ? -0.0 : 0.0;
      }
    }
  }
  return __real_strtod(s, end);
}
