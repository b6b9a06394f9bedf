// bsdf_chi_square.h — the BSDF tests' check that a sampler draws from its pdf (after Mitsuba's
// chi2 tests): draw sampleBsdf n times into the cells of a grid over directions, integrate
// bsdfPdf over each cell, and compare by Pearson's chi-square (chi_square.h), with one more
// outcome for invalid samples, whose expected share is what the pdf's integral lacks.
//
// A grid is any type with
//     int cells() const;                                   the number of cells
//     int cellOf(glm::vec3 direction) const;               the cell a direction falls in
//     template <typename G> double integrateCell(int cell, const G& g) const;   ∫ g dω over it
// (bsdf_test.cpp: cells about the mirror direction; SphereGrid below: the whole sphere).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "chi_square.h"
#include "shared/bsdf.h"
#include "shared/rng.h"

namespace vkpt::test {

// Cells over the whole sphere, uniform in cos θ ∈ [−1, 1] (so both hemispheres) and in φ, each
// integrated by the midpoint rule on Sub × Sub sub-cells (dω = d cos θ dφ, so the rule is exact
// for a g constant on sub-cells).
template <int CosBins, int PhiBins, int Sub> class SphereGrid {
public:
    int cells() const { return CosBins * PhiBins; }

    int cellOf(glm::vec3 w) const {
        int ci = std::clamp(int((double(w.z) + 1.0) * 0.5 * CosBins), 0, CosBins - 1);
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        int pi = std::clamp(int(phi / (2.0 * std::numbers::pi) * PhiBins), 0, PhiBins - 1);
        return ci * PhiBins + pi;
    }

    template <typename G> double integrateCell(int cell, const G& g) const {
        const double dCos = 2.0 / CosBins / Sub;
        const double dPhi = 2.0 * std::numbers::pi / PhiBins / Sub;
        int ci = cell / PhiBins, pi = cell % PhiBins;
        double sum = 0.0;
        for (int a = 0; a < Sub; ++a)
            for (int b = 0; b < Sub; ++b) {
                double z = -1.0 + (ci * Sub + a + 0.5) * dCos;
                double phi = (pi * Sub + b + 0.5) * dPhi;
                double s = std::sqrt(std::max(0.0, 1.0 - z * z));
                sum += g(glm::vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
            }
        return sum * dCos * dPhi;
    }
};

// One material at one view, drawn n times, and its pdf integrated over every cell.
struct SamplingAnalysis {
    std::vector<double> observed;      // per cell, then the invalid samples last
    std::vector<double> probabilities; // ∫ pdf per cell
    double integral = 0.0;             // Σ probabilities: ∫ pdf over the grid
    double invalidFraction = 0.0;
    int samples = 0;
};

// `samples` draws of stream `seed` (sample index i, dimension DIM_BSDF).
template <typename Grid>
SamplingAnalysis analyseSampling(const gpu::ShadingMaterial& m, glm::vec3 wo, const Grid& grid,
                                 int samples, std::uint32_t seed) {
    SamplingAnalysis r;
    r.samples = samples;
    r.observed.assign(std::size_t(grid.cells() + 1), 0.0);
    for (std::uint32_t i = 0; i < std::uint32_t(samples); ++i) {
        const glm::vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        const gpu::BsdfSample s = gpu::sampleBsdf(m, wo, glm::vec2(u.x, u.y), u.w);
        r.observed[s.valid ? std::size_t(grid.cellOf(s.direction)) : std::size_t(grid.cells())] +=
            1.0;
    }
    r.invalidFraction = r.observed.back() / samples;
    auto pdf = [&](glm::vec3 wi) { return double(gpu::bsdfPdf(m, wo, wi)); };
    for (int cell = 0; cell < grid.cells(); ++cell) {
        r.probabilities.push_back(grid.integrateCell(cell, pdf));
        r.integral += r.probabilities.back();
    }
    return r;
}

// The analyses of a test file's cases, each made on first use and kept for the other tests.
class SamplingAnalyses {
public:
    SamplingAnalyses(std::vector<std::string> names, std::function<SamplingAnalysis(int)> analyse)
        : names_(std::move(names)), analyses_(names_.size()), analyse_(std::move(analyse)) {}

    int size() const { return int(analyses_.size()); }
    const std::string& name(int index) const { return names_[std::size_t(index)]; }

    const SamplingAnalysis& operator[](int index) {
        SamplingAnalysis& a = analyses_[std::size_t(index)];
        if (a.samples == 0) a = analyse_(index);
        return a;
    }

private:
    std::vector<std::string> names_;
    std::vector<SamplingAnalysis> analyses_;
    std::function<SamplingAnalysis(int)> analyse_;
};

// The analyses of `cases` (each with a `name`, `material()` and the view `wo()`), case k drawn
// `samples` times from stream firstSeed + k (independent streams) into the cells of
// gridOf(case).
template <typename Case, std::size_t N, typename GridOf>
SamplingAnalyses samplingAnalysesOf(const Case (&cases)[N], std::uint32_t firstSeed, GridOf gridOf,
                                    int samples = 200000) {
    std::vector<std::string> names;
    for (const Case& c : cases)
        names.push_back(c.name);
    return SamplingAnalyses(std::move(names), [&cases, firstSeed, gridOf, samples](int k) {
        const Case& c = cases[k];
        return analyseSampling(c.material(), c.wo(), gridOf(c), samples,
                               firstSeed + std::uint32_t(k));
    });
}

// Every case at once, with family-wise false-alarm rate `familyAlpha`: Šidák's per-case level
// 1 − (1 − α)^(1/cases). Cells expecting fewer than 5 samples are pooled (chi_square.h).
inline void expectSamplesFollowThePdf(SamplingAnalyses& analyses, double familyAlpha = 0.01) {
    const double perCaseAlpha = 1.0 - std::pow(1.0 - familyAlpha, 1.0 / analyses.size());
    for (int k = 0; k < analyses.size(); ++k) {
        const SamplingAnalysis& a = analyses[k];
        std::vector<double> expected;
        for (double p : a.probabilities)
            expected.push_back(p * a.samples);
        expected.push_back(std::max(0.0, 1.0 - a.integral) * a.samples);
        const ChiSquareResult r = chiSquareTest(a.observed, expected);
        EXPECT_GT(r.pValue, perCaseAlpha)
            << analyses.name(k) << ": chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    }
}

// ∫ pdf + the invalid share = 1, within 4 binomial σ of that share (the sampled share's noise)
// plus `quadratureError`, the bound on the cells' integration.
inline void expectPdfIntegratesToOneLessTheInvalidShare(SamplingAnalyses& analyses,
                                                        double quadratureError) {
    for (int k = 0; k < analyses.size(); ++k) {
        const SamplingAnalysis& a = analyses[k];
        const double p = a.invalidFraction;
        const double tolerance =
            4.0 * std::sqrt(std::max(p * (1.0 - p), 1e-12) / a.samples) + quadratureError;
        EXPECT_NEAR(a.integral + p, 1.0, tolerance) << analyses.name(k);
    }
}

// For `samples` draws of stream `seed`: a unit direction, s.pdf equal to bsdfPdf's within
// `pdfRelative`, and the weight f·|cos θi|/pdf within `weightRelative`·max(1, value) per
// channel; `check(sample)` adds what the case requires of every valid sample. Stops at the
// first failure (use under ASSERT_NO_FATAL_FAILURE).
template <typename Check>
void expectSamplesAgreeWithEvaluation(const gpu::ShadingMaterial& m, glm::vec3 wo, int samples,
                                      std::uint32_t seed, float pdfRelative, float weightRelative,
                                      const std::string& name, const Check& check) {
    for (std::uint32_t i = 0; i < std::uint32_t(samples); ++i) {
        const glm::vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        const gpu::BsdfSample s = gpu::sampleBsdf(m, wo, glm::vec2(u.x, u.y), u.w);
        if (!s.valid) continue;
        ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f) << name;
        check(s);
        if (::testing::Test::HasFatalFailure()) return;
        const float pdf = gpu::bsdfPdf(m, wo, s.direction);
        ASSERT_NEAR(s.pdf, pdf, pdfRelative * pdf) << name;
        const glm::vec3 expected =
            gpu::evaluateBsdf(m, wo, s.direction) * (std::abs(s.direction.z) / pdf);
        for (int ch = 0; ch < 3; ++ch)
            ASSERT_NEAR(s.weight[ch], expected[ch], weightRelative * std::max(1.0f, expected[ch]))
                << name;
    }
}

} // namespace vkpt::test
