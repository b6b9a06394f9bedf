// normal_quantile.cpp — the standard normal quantile behind the z-test's critical value, which
// must stay accurate far into the tail because the per-pixel alpha shrinks with image size.
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "image/image_compare.h"

namespace vkpt {

namespace {

// Peter J. Acklam, "An algorithm for computing the inverse normal cumulative distribution
// function" (2003; published on his web page, archived copies widely cited): a rational
// approximation of the lower-tail quantile with relative error below 1.15e-9, central region
// for p in [0.02425, 0.97575], tail formulas in q = sqrt(-2 log p) outside it.
constexpr std::array<double, 6> kCentralNum = {-3.969683028665376e+01, 2.209460984245205e+02,
                                               -2.759285104469687e+02, 1.383577518672690e+02,
                                               -3.066479806614716e+01, 2.506628277459239e+00};
constexpr std::array<double, 5> kCentralDen = {-5.447609879822406e+01, 1.615858368580409e+02,
                                               -1.556989798598866e+02, 6.680131188771972e+01,
                                               -1.328068155288572e+01};
constexpr std::array<double, 6> kTailNum = {-7.784894002430293e-03, -3.223964580411365e-01,
                                            -2.400758277161838e+00, -2.549732539343734e+00,
                                            4.374664141464968e+00,  2.938163982698783e+00};
constexpr std::array<double, 4> kTailDen = {7.784695709041462e-03, 3.224671290700398e-01,
                                            2.445134137142996e+00, 3.754408661907416e+00};
constexpr double kCentralLimit = 0.02425;

// Horner's rule; with leadingOne the polynomial gains a final constant term 1.
template <std::size_t N>
double polynomial(const std::array<double, N>& coefficients, double x, bool leadingOne) {
    double sum = 0.0;
    for (double c : coefficients)
        sum = sum * x + c;
    return leadingOne ? sum * x + 1.0 : sum;
}

double acklamTail(double p) {
    const double q = std::sqrt(-2.0 * std::log(p));
    return polynomial(kTailNum, q, false) / polynomial(kTailDen, q, true);
}

// Acklam's estimate of x with Φ(x) = p, for p in (0, 1).
double acklamLowerQuantile(double p) {
    if (p < kCentralLimit) return acklamTail(p);
    if (p > 1.0 - kCentralLimit) return -acklamTail(1.0 - p);
    const double q = p - 0.5;
    const double r = q * q;
    return q * polynomial(kCentralNum, r, false) / polynomial(kCentralDen, r, true);
}

double upperTail(double z) {
    return 0.5 * std::erfc(z / std::numbers::sqrt2);
}

double normalDensity(double z) {
    return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}

// One Newton step on log Q(z) = log p, where Q is the upper tail: Q(z) and φ(z) are both tiny
// far in the tail, but their ratio and the difference of logarithms are not, so the step stays
// accurate down to p ≈ 1e-300 where Φ(x) − p itself would underflow into subnormals.
double refineUpperQuantile(double z, double p) {
    const double tail = upperTail(z);
    const double density = normalDensity(z);
    if (tail <= 0.0 || density <= 0.0) return z; // out of double range; keep the estimate
    return z + (std::log(tail) - std::log(p)) * tail / density;
}

} // namespace

double normalUpperQuantile(double p) {
    if (std::isnan(p)) return std::numeric_limits<double>::quiet_NaN();
    if (p <= 0.0) return std::numeric_limits<double>::infinity();
    if (p >= 1.0) return -std::numeric_limits<double>::infinity();
    // Q(z) = p  <=>  Φ(−z) = p. Acklam gives ~1e-9; two Newton steps bring it to rounding error
    // (the first would nearly suffice, as the error is squared).
    double z = -acklamLowerQuantile(p);
    for (int step = 0; step < 2; ++step)
        z = refineUpperQuantile(z, p);
    return z;
}

} // namespace vkpt
