// student_t.h — tail probabilities of Student's t distribution, for Welch's test of two
// renders whose per-pixel variances are estimated from few samples.
#pragma once

namespace vkpt {

// Regularised incomplete beta function I_x(a, b) for a, b > 0 and x in [0, 1].
double regularizedIncompleteBeta(double a, double b, double x);

// P(|T| >= |t|) for T ~ Student's t with df > 0 degrees of freedom (df may be fractional,
// as Welch–Satterthwaite gives it). Tends to the normal tail as df grows.
double studentTwoSidedPValue(double t, double df);

} // namespace vkpt
