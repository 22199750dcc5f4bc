#pragma once
/// \file
/// Portable transcendental functions: the same bits on every IEEE-754
/// platform.
///
/// The C and C++ standards leave the accuracy of sin, cos, exp, log, pow,
/// atan2 and erf to the library, and libraries differ in the last bit
/// (glibc's libm and musl's, used by emscripten, disagree on a few per
/// cent of arguments). The engine must give the same results natively and
/// in WebAssembly, so src/physics, src/game and src/ai call these instead.
///
/// Each function is built from + - * / and std::sqrt (all correctly
/// rounded by IEEE 754), std::frexp, std::ldexp and std::floor (exact),
/// comparisons, sign and class tests, and integer arithmetic, in a fixed
/// order. With floating-point contraction off (-ffp-contract=off, set for
/// the engine in CMakeLists.txt) every step is one IEEE operation, so the
/// result is a pure function of the argument's bits: the same on every
/// compiler, library and platform with IEEE doubles in round-to-nearest
/// (x86-64 SSE2, AArch64, WebAssembly; not the x87 unit).
///
/// Accuracy: the largest error found, in units in the last place of the
/// exact result, over 3 million random arguments per range (against
/// 113-bit libquadmath; tests/test_detmath.cpp checks the same against
/// the platform's libm and against values computed to 60 digits):
///
///   function   method                                          max error
///   sin, cos   reduction modulo pi/2 in double-double: Cody     0.80 ulp
///              and Waite's with pi/2 in four parts below 2^20,
///              Payne and Hanek's in exact integer arithmetic
///              above (any finite x); Taylor polynomials
///   atan2      ratio in double-double, a table of atan(i/16),   0.50 ulp
///              a Taylor polynomial, quadrants in double-double
///   exp        x = (32 k + j) ln2/32 + r, a table of 2^(j/32),  0.53 ulp
///              a Taylor polynomial for e^r
///   log        x = 2^e m, m ~ i/64, a table of log(64/i), a     0.50 ulp
///              Taylor polynomial for log1p, in double-double
///   pow        exp of y log x, both in double-double            0.53 ulp
///   erf        Taylor series about the nearest quarter, its     0.56 ulp
///              coefficients from the Hermite recurrence, and
///              a table of erf and its slope there; +-1 from 6
///
/// Sin and cos were measured over [-10, 10], [-1e6, 1e6] and every binade
/// up to 1e300, exp over [-745, 709.7], log over every binade, atan2 over
/// all quadrants and operands from 2^-1000 to 2^1000, pow with results
/// over the whole range, erf over [-6, 6]. Results are almost always the
/// correctly rounded double but that is not guaranteed. Results in the
/// subnormal range (exp below -708, atan2 of operands more than 2^1000
/// apart) can be a few units off.
///
/// Special values follow C99 Annex F (the IEEE behaviour of libm):
///   sin(+-0) = +-0, cos(+-0) = 1, sin(+-inf) = cos(+-inf) = NaN;
///   atan2 of zeros and infinities as in Annex F, e.g. atan2(+-0, -0) =
///   +-pi, atan2(+-0, +0) = +-0, atan2(+-inf, -inf) = +-3pi/4;
///   exp(-inf) = +0, exp(+inf) = +inf, overflow gives +inf and underflow +0;
///   log(+-0) = -inf, log(x < 0) = NaN, log(+inf) = +inf;
///   pow(x, +-0) = 1 and pow(1, y) = 1 even for NaN; pow of negative x is
///   NaN unless y is an integer; zeros and infinities as in Annex F;
///   erf(+-0) = +-0, erf(+-inf) = +-1.
/// Every NaN result, from a NaN argument or not, is the same quiet NaN
/// (std::numeric_limits<double>::quiet_NaN(), whose bits do not depend on
/// the hardware, unlike those of 0/0 or inf - inf). Floating-point exception
/// flags are not meant to match libm's.
namespace breakshot::dm {

double sin(double x);
double cos(double x);
/// sin and cos of one argument with one argument reduction; the same bits
/// as sin(x) and cos(x).
void sincos(double x, double& s, double& c);
double atan2(double y, double x);
double exp(double x);
/// Natural logarithm.
double log(double x);
double pow(double x, double y);
/// The error function, 2/sqrt(pi) times the integral of exp(-t^2) from 0
/// to x.
double erf(double x);

}  // namespace breakshot::dm
