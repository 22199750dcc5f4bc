// strtod_check: the wasm build's strtod (web/compat/fast_strtod.cpp,
// fast_float) against musl's (__real_strtod) on 3 million strings: the
// same double bits, the same end pointer and the same errno, or the
// difference is printed. A check of the wasm build, not a ctest test:
//
//   cmake --build build/web --target strtod_check && node build/web/strtod_check.js
//
// Strings: edge cases (zeros, signs, spaces, exponents without digits,
// the largest and smallest doubles and halfway cases around them,
// overflow, subnormals, hexadecimal, inf, nan, no digits, long digit
// strings), then random doubles of every binade printed with 17, 16 and
// 1 to 25 significant digits, random positions on a table and random
// digit strings with exponents from -350 to 349. Exits 1 on a difference.

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

extern "C" double __real_strtod(const char* s, char** end);

namespace {

std::uint64_t checked = 0;
std::uint64_t differ = 0;

struct Rng {  // xorshift64
  std::uint64_t s = 88172645463325252ULL;
  std::uint64_t operator()() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
  }
};

void check(const char* s) {
  char* e1 = nullptr;
  char* e2 = nullptr;
  errno = 0;
  const double a = std::strtod(s, &e1);  // --wrap=strtod: fast_strtod.cpp's
  const int err1 = errno;
  errno = 0;
  const double b = __real_strtod(s, &e2);
  const int err2 = errno;
  std::uint64_t x = 0;
  std::uint64_t y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  ++checked;
  const bool both_nan = a != a && b != b;
  if ((x != y && !both_nan) || e1 != e2 || err1 != err2) {
    if (differ < 20) {
      std::printf("differ: '%s': %.17g / %.17g, end %d / %d, errno %d / %d\n", s, a, b,
                  static_cast<int>(e1 - s), static_cast<int>(e2 - s), err1, err2);
    }
    ++differ;
  }
}

}  // namespace

int main() {
  const char* fixed[] = {
      "0", "-0", "0.0", "0e5", "-0.000e-3", "1", "1.", ".5", "-.5", "+3", " 12", "\t-7.25x",
      "1e", "1e+", "1e-", "2e308", "-2e308", "1e-320", "4.9e-324", "2.5e-324", "2.4e-324",
      "1e-400", "2.2250738585072014e-308", "2.2250738585072011e-308",
      "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308", "inf",
      "-Infinity", "nan", "nan(123)", "0x1p3", "0X1.8p1", "-0x10", ".", "-", "+", "", "e5",
      "1.5e3.2", "12-3", "9007199254740993", "9007199254740992.5", "0.1",
      "0.30000000000000004", "123456789012345678901234567890", "1e22", "1e23",
      "8.988465674311579e307", "1.00000000000000011102230246251565404236316680908203125",
      "1.00000000000000011102230246251565404236316680908203124",
      "1.00000000000000011102230246251565404236316680908203126", "7.4109846876186982e-323",
      "000000000000000000001.5", "1.500000000000000000000000000000000000000000000000000000001",
      "0.00000000000000000000000000000000000000000000000000001e40"};
  for (const char* s : fixed) check(s);
  Rng g;
  char buf[128];
  for (int k = 0; k < 3000000; ++k) {
    const std::uint64_t bits = g();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    if (v != v) continue;
    switch (k % 6) {
      case 0: std::snprintf(buf, sizeof buf, "%.17g", v); break;
      case 1: std::snprintf(buf, sizeof buf, "%.16g", v); break;
      case 2: std::snprintf(buf, sizeof buf, "%.*g", 1 + static_cast<int>(g() % 25), v); break;
      case 3: {
        const double u = static_cast<double>(g() >> 11) * 0x1p-53 * 10.0;
        std::snprintf(buf, sizeof buf, "%.*g", 1 + static_cast<int>(g() % 20), u);
        break;
      }
      case 4: {
        const double u = static_cast<double>(g() >> 11) * 0x1p-53 * 2.54;
        std::snprintf(buf, sizeof buf, "%.17g", u);
        break;
      }
      default: {
        const int len = 1 + static_cast<int>(g() % 40);
        int p = 0;
        if (g() & 1) buf[p++] = '-';
        for (int i = 0; i < len; ++i) {
          buf[p++] = static_cast<char>('0' + g() % 10);
          if (i == 0 && (g() & 1)) buf[p++] = '.';
        }
        std::snprintf(buf + p, sizeof buf - static_cast<std::size_t>(p), "e%d",
                      static_cast<int>(g() % 700) - 350);
        break;
      }
    }
    check(buf);
  }
  std::printf("%llu strings, %llu differ\n", static_cast<unsigned long long>(checked),
              static_cast<unsigned long long>(differ));
  return differ == 0 ? 0 : 1;
}
