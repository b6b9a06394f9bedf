// adaptive_simpson.h — the tests' numerical integrator: adaptive Simpson quadrature in one
// dimension (Kuncir 1962; Lyness 1969), which the BSDF tests nest for integrals over directions.
// The integrand returns a double, or a glm::dvec2 for two integrals over the same points: an
// interval is then halved until both components meet the tolerance.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <glm/vec2.hpp>

namespace vkpt::test {

// The size that the tolerance bounds: |v|, or the larger component's for two integrals.
inline double simpsonMagnitude(double v) {
    return std::abs(v);
}
inline double simpsonMagnitude(const glm::dvec2& v) {
    return std::max(std::abs(v.x), std::abs(v.y));
}

struct SimpsonOptions {
    static constexpr int kMaxPanels = 64;
    int panels = 4; // first split of [a, b], 1 to kMaxPanels; each panel then refines on its own
    // The tolerance over [a, b]: max(relative · |first estimate|, absolute), where the first
    // estimate is Simpson's rule on the panels.
    double relativeTolerance = 1e-5;
    double absoluteTolerance = 1e-12;
    int maxDepth = 12; // halvings per panel at most
};

namespace detail {

// One interval [a, b] with f at its ends and middle and Simpson's estimate `whole`: halves it
// until the two halves agree with the whole within 15·eps, then adds Richardson's correction.
template <typename F, typename V>
V simpsonStep(const F& f, double a, double b, V fa, V fm, V fb, V whole, double eps, int depth) {
    const double m = 0.5 * (a + b);
    const V flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    const V left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const V right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const V delta = left + right - whole;
    if (depth <= 0 || simpsonMagnitude(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return simpsonStep(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           simpsonStep(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

} // namespace detail

// ∫ f over [a, b]; the tolerance is shared equally among the first panels.
template <typename F>
auto adaptiveSimpson(const F& f, double a, double b, const SimpsonOptions& options = {}) {
    using V = std::decay_t<decltype(f(a))>;
    const int panels = options.panels;
    if (panels < 1 || panels > SimpsonOptions::kMaxPanels)
        throw std::invalid_argument("adaptiveSimpson: panels out of range");
    const double h = (b - a) / panels;
    // On the stack: nested integrals call this once per outer point.
    std::array<V, 2 * SimpsonOptions::kMaxPanels + 1> values;
    std::array<V, SimpsonOptions::kMaxPanels> wholes;
    for (int i = 0; i <= 2 * panels; ++i)
        values[std::size_t(i)] = f(a + 0.5 * h * i);
    V estimate(0.0);
    for (int p = 0; p < panels; ++p) {
        const std::size_t i = std::size_t(2 * p);
        wholes[std::size_t(p)] = h / 6.0 * (values[i] + 4.0 * values[i + 1] + values[i + 2]);
        estimate += wholes[std::size_t(p)];
    }
    const double eps = std::max(options.relativeTolerance * simpsonMagnitude(estimate),
                                options.absoluteTolerance) /
                       panels;
    V sum(0.0);
    for (int p = 0; p < panels; ++p) {
        const std::size_t i = std::size_t(2 * p);
        sum += detail::simpsonStep(f, a + h * p, a + h * (p + 1), values[i], values[i + 1],
                                   values[i + 2], wholes[std::size_t(p)], eps, options.maxDepth);
    }
    return sum;
}

} // namespace vkpt::test
