// albedo_integrals.cpp — quadratures of the lobes' directional albedo, evaluating the lobes with
// the shared code itself, so that the tables describe exactly what the renderers compute.
#include "albedo_integrals.h"

#include <cmath>

#include "shared/ggx.h"
#include "shared/iridescence.h"
#include "shared/sheen.h"

namespace vkpt::tables {
namespace {

glm::vec3 viewAt(double cosThetaO) {
    const double sinThetaO = std::sqrt(std::max(0.0, 1.0 - cosThetaO * cosThetaO));
    return glm::vec3(float(sinThetaO), 0.0f, float(cosThetaO));
}

// The GGX reflection lobe's quadrature at view cos θo: a resolution² grid over the visible-normal
// sampler's square, each sample that reflects above the surface handed to `add` with its
// direction, half vector and weight f·cos θi / pdf (the integral is the mean of the weights).
template <typename AddSample>
void forEachGgxReflection(double cosThetaO, double alpha, int resolution, AddSample add) {
    const glm::vec3 wo = viewAt(cosThetaO);
    const float a = float(alpha);
    for (int i = 0; i < resolution; ++i)
        for (int j = 0; j < resolution; ++j) {
            const glm::vec2 u((float(i) + 0.5f) / float(resolution),
                              (float(j) + 0.5f) / float(resolution));
            const glm::vec3 h = gpu::sampleGgxVisibleNormal(wo, a, u);
            const glm::vec3 wi = glm::normalize(2.0f * glm::dot(wo, h) * h - wo);
            if (!(wi.z > 0.0f)) continue;
            const double pdf = gpu::ggxReflectionPdf(wo, h, a);
            if (!(pdf > 0.0)) continue;
            add(wo, wi, h, double(gpu::ggxReflection(wo, wi, h, a)) * double(wi.z) / pdf);
        }
}

} // namespace

double ggxAlbedo(double cosThetaO, double alpha, bool fresnelWeighted, int resolution) {
    double sum = 0.0;
    forEachGgxReflection(
        cosThetaO, alpha, resolution,
        [&](const glm::vec3& wo, const glm::vec3& wi, const glm::vec3& h, double weight) {
            if (fresnelWeighted) weight *= double(gpu::halfVectorFresnelWeight(wo, wi, h));
            sum += weight;
        });
    return sum / (double(resolution) * double(resolution));
}

std::vector<double> ggxFilmNodeAlbedos(double cosThetaO, double alpha, int resolution) {
    std::vector<double> sums(VKPT_FILM_NODES, 0.0);
    forEachGgxReflection(
        cosThetaO, alpha, resolution,
        [&](const glm::vec3& wo, const glm::vec3& wi, const glm::vec3& h, double weight) {
            // V·H as the lobe takes it (ggx.h, halfVectorFresnelWeight), shared between the
            // two nodes around it as the lobe's interpolated film term shares it.
            const gpu::FilmInterval at =
                gpu::filmIntervalOf(0.5f * (glm::dot(wo, h) + glm::dot(wi, h)));
            sums[std::size_t(at.node)] += weight * (1.0 - double(at.t));
            sums[std::size_t(at.node + 1)] += weight * double(at.t);
        });
    for (double& sum : sums)
        sum /= double(resolution) * double(resolution);
    return sums;
}

double sheenAlbedo(double cosThetaO, double alpha, int resolution) {
    const glm::vec3 wo = viewAt(cosThetaO);
    const double pi = 3.14159265358979323846;
    double sum = 0.0;
    // dω = d(cos θ) dφ; the lobe is symmetric about the plane of wo, so φ covers [0, π] twice.
    for (int i = 0; i < resolution; ++i) {
        const double cosThetaI = (i + 0.5) / resolution;
        const double sinThetaI = std::sqrt(1.0 - cosThetaI * cosThetaI);
        for (int j = 0; j < resolution; ++j) {
            const double phi = pi * (j + 0.5) / resolution;
            const glm::vec3 wi(float(sinThetaI * std::cos(phi)), float(sinThetaI * std::sin(phi)),
                               float(cosThetaI));
            sum += double(gpu::sheenReflection(wo, wi, float(alpha))) * cosThetaI;
        }
    }
    return 2.0 * sum * (1.0 / resolution) * (pi / resolution);
}

} // namespace vkpt::tables
