// student_t_test.cpp — Student's t tail and the incomplete beta against closed forms and
// published table values.
#include <gtest/gtest.h>

#include <cmath>

#include "image/student_t.h"

namespace vkpt::student_t_test {
namespace {

TEST(StudentT, OneDegreeOfFreedomIsTheCauchyTail) {
    // P(|T| >= t) = 1 − (2/π)·atan(t) for df = 1.
    for (double t : {0.1, 1.0, 3.0, 50.0})
        EXPECT_NEAR(studentTwoSidedPValue(t, 1.0), 1.0 - 2.0 / M_PI * std::atan(t), 1e-12);
}

TEST(StudentT, TwoDegreesOfFreedomHaveAClosedForm) {
    // P(|T| >= t) = 1 − t / sqrt(2 + t²) for df = 2.
    for (double t : {0.5, 2.0, 10.0})
        EXPECT_NEAR(studentTwoSidedPValue(t, 2.0), 1.0 - t / std::sqrt(2.0 + t * t), 1e-12);
}

TEST(StudentT, MatchesTableValues) {
    // Two-sided 5 % and 1 % critical values of standard t tables.
    EXPECT_NEAR(studentTwoSidedPValue(2.228139, 10.0), 0.05, 1e-6);
    EXPECT_NEAR(studentTwoSidedPValue(3.169273, 10.0), 0.01, 1e-6);
    EXPECT_NEAR(studentTwoSidedPValue(2.039513, 31.0), 0.05, 1e-6);
}

TEST(StudentT, ManyDegreesOfFreedomApproachTheNormalTail) {
    EXPECT_NEAR(studentTwoSidedPValue(1.959964, 1e7), 0.05, 1e-6);
    EXPECT_NEAR(studentTwoSidedPValue(4.0, 1e7), std::erfc(4.0 / std::sqrt(2.0)), 1e-8);
}

TEST(StudentT, IncompleteBetaIsSymmetricAndBounded) {
    for (double x : {0.01, 0.3, 0.7, 0.99}) {
        EXPECT_NEAR(regularizedIncompleteBeta(2.5, 0.5, x) +
                        regularizedIncompleteBeta(0.5, 2.5, 1.0 - x),
                    1.0, 1e-12);
    }
    EXPECT_EQ(regularizedIncompleteBeta(3.0, 4.0, 0.0), 0.0);
    EXPECT_EQ(regularizedIncompleteBeta(3.0, 4.0, 1.0), 1.0);
    // I_x(1, 1) = x.
    EXPECT_NEAR(regularizedIncompleteBeta(1.0, 1.0, 0.37), 0.37, 1e-14);
}

} // namespace
} // namespace vkpt::student_t_test
