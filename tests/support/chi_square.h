// chi_square.h — Pearson's chi-square goodness-of-fit test for the sampler tests, after
// Mitsuba's chi2 tests: bins with small expected counts are pooled, and the p-value comes
// from the regularised incomplete gamma function.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace vkpt::test {

// Regularised upper incomplete gamma Q(a, x): the power series of P for x < a + 1, else the
// continued fraction for Q evaluated with the modified Lentz method (both standard forms,
// Abramowitz and Stegun 6.5.29 and 6.5.31).
inline double upperIncompleteGammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double logPrefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(logPrefix) * h;
}

struct ChiSquareResult {
    double statistic = 0.0;
    std::size_t degreesOfFreedom = 0;
    double pValue = 0.0;
};

// observed and expected counts per bin; bins expected below minExpected are pooled together
// (the chi-square approximation needs about 5 per bin).
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed,
                                     const std::vector<double>& expected,
                                     double minExpected = 5.0) {
    ChiSquareResult result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    std::size_t bins = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < minExpected) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        double diff = observed[i] - expected[i];
        result.statistic += diff * diff / expected[i];
        ++bins;
    }
    if (pooledExpected > 0.0) {
        double diff = pooledObserved - pooledExpected;
        result.statistic += diff * diff / pooledExpected;
        ++bins;
    }
    result.degreesOfFreedom = bins > 1 ? bins - 1 : 1;
    result.pValue =
        upperIncompleteGammaQ(0.5 * double(result.degreesOfFreedom), 0.5 * result.statistic);
    return result;
}

} // namespace vkpt::test
