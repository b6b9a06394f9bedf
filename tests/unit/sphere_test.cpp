// sphere_test.cpp — the analytic sphere of shared/sphere.h: the ray test against a
// double-precision solution at extreme scales and distances, the surface frame and texture
// coordinates, and the spherical light's cone sampling and its pdf.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/chi_square.h"
#include "common/math_constants.h"
#include "shared/ray_offset.h"
#include "shared/rng.h"
#include "shared/sphere.h"

namespace vkpt::sphere_test {
namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr double kFloatEpsilon = 1.1920928955078125e-7;

// ---------------------------------------------------------------------------------------------
// The ray test against the same float inputs solved in double precision.
struct ReferenceRoots {
    bool hit = false;
    double tNear = 0.0, tFar = 0.0;
    double closestDistance = 0.0; // of the line from the centre
};

ReferenceRoots solveInDouble(vec3 origin, vec3 direction, vec3 centre, float radius) {
    dvec3 o(origin), d(direction), c(centre);
    double r = radius, a = glm::dot(d, d);
    dvec3 f = o - c;
    double b = glm::dot(f, d);
    dvec3 l = f - (b / a) * d;
    ReferenceRoots roots;
    roots.closestDistance = glm::length(l);
    double discriminant = a * (r * r - glm::dot(l, l));
    if (discriminant < 0.0) return roots;
    double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = (glm::dot(f, f) - r * r) / q, t1 = q / a;
    roots.hit = true;
    roots.tNear = std::min(t0, t1);
    roots.tFar = std::max(t0, t1);
    return roots;
}

// A ray from `distanceInRadii` radii away aimed at a random point of the disk through the centre
// of radius `aim` radii, with a random length; the sphere sits at `centre`.
struct RayCase {
    vec3 origin, direction;
};

RayCase randomRay(uint32_t i, vec3 centre, float radius, float distanceInRadii, float aim) {
    vec4 u = gpu::randomFloats(31, i, 0, 0, DIM_LIGHT_FIRST);
    vec4 w = gpu::randomFloats(31, i, 0, 1, DIM_LIGHT_FIRST);
    vec3 fromCentre = gpu::sampleUniformSphere(vec2(u.x, u.y));
    vec3 origin = centre + distanceInRadii * radius * fromCentre;
    gpu::Basis frame = gpu::makeBasis(-fromCentre);
    float diskRadius = aim * std::sqrt(u.z), phi = 2.0f * float(kPi) * u.w;
    vec3 target = centre + radius * diskRadius *
                               (std::cos(phi) * frame.tangent + std::sin(phi) * frame.bitangent);
    float length = std::exp2(8.0f * w.x - 4.0f); // 1/16 .. 16
    return {origin, glm::normalize(target - origin) * length};
}

struct HitErrors {
    double worstResidual = 0.0; // | |p − c| − r | / (ε (|o − c| + r))
    double worstT = 0.0;        // |t − t_double| / bound
    int hits = 0, rays = 0;
};

// Bounds, in ε (|o − c| + r) =: E, the scale of what float inputs can resolve at this distance:
// the closest-point vector l errs by a few E, so the hit point is within 16 E of the surface,
// and t errs by a few E/|d| plus what the half chord h = √(r² − |l|²) amplifies, E r/(h |d|).
// Lines within 16 E of tangency may hit or miss.
void checkRays(vec3 centre, float radius, float distanceInRadii, float aim, HitErrors& errors) {
    for (uint32_t i = 0; i < 4000; ++i) {
        RayCase ray =
            randomRay(i + uint32_t(distanceInRadii * 7.0f), centre, radius, distanceInRadii, aim);
        gpu::TriangleHit hit =
            gpu::intersectSphere(ray.origin, ray.direction, centre, radius, 0.0f, VKPT_FAR);
        ReferenceRoots ref = solveInDouble(ray.origin, ray.direction, centre, radius);
        double scale = kFloatEpsilon * (glm::length(dvec3(ray.origin) - dvec3(centre)) + radius);
        bool ambiguous = std::abs(ref.closestDistance - radius) <= 16.0 * scale;
        ++errors.rays;
        double refT = ref.tNear > 0.0 ? ref.tNear : ref.tFar;
        bool refHit = ref.hit && refT > 0.0;
        if (!ambiguous) {
            ASSERT_EQ(hit.hit, refHit) << "ray " << i << " radius " << radius;
        }
        if (!hit.hit || !refHit) continue;
        ++errors.hits;
        dvec3 p = dvec3(ray.origin) + double(hit.t) * dvec3(ray.direction);
        double residual = std::abs(glm::length(p - dvec3(centre)) - radius) / scale;
        errors.worstResidual = std::max(errors.worstResidual, residual);
        ASSERT_LE(residual, 16.0) << "ray " << i << " radius " << radius;
        if (ambiguous) continue;
        double halfChord = std::sqrt(
            std::max(0.0, double(radius) * radius - ref.closestDistance * ref.closestDistance));
        double dLength = glm::length(dvec3(ray.direction));
        double bound = 16.0 * scale / dLength * (1.0 + radius / halfChord);
        double tError = std::abs(double(hit.t) - refT) / bound;
        errors.worstT = std::max(errors.worstT, tError);
        ASSERT_LE(tError, 1.0) << "ray " << i << " radius " << radius << " t " << hit.t
                               << " reference " << refT;
    }
}

// Radii 1e-3, 1 and 1e4; origins from 2 to 1e4 radii away, some spheres far from the world
// origin; aims that hit and miss. Worst figures seen: hit point 1.95 E from the surface, t error
// 0.064 of its bound (E = ε (|o − c| + r)).
TEST(SphereIntersection, MatchesDoublePrecisionAtAllScalesAndDistances) {
    HitErrors errors;
    for (float radius : {1e-3f, 1.0f, 1e4f})
        for (vec3 centre : {vec3(0.0f), vec3(3.0f, -2.0f, 5.0f) * radius * 10.0f})
            for (float distanceInRadii : {2.0f, 30.0f, 1e4f})
                for (float aim : {1.5f, 1.0f})
                    checkRays(centre, radius, distanceInRadii, aim, errors);
    std::printf("sphere hits: %d of %d rays, worst residual %.3f E, worst t error %.3f of bound\n",
                errors.hits, errors.rays, errors.worstResidual, errors.worstT);
    EXPECT_GT(errors.hits, errors.rays / 3);
}

// Rays aimed at the silhouette, 1e-4 radii inside or outside it.
TEST(SphereIntersection, GrazingRaysFollowTheDoubleSolution) {
    HitErrors errors;
    for (float radius : {1e-3f, 1.0f, 1e4f}) {
        checkRays(vec3(0.0f), radius, 10.0f, 1.0001f, errors);
        checkRays(vec3(0.0f), radius, 10.0f, 0.9999f, errors);
    }
    EXPECT_GT(errors.hits, 0);
}

// Haines et al.'s point: for a sphere of radius 1e-3 seen from 10 units away, the textbook
// discriminant b² − ac is a difference of two numbers near 100 (for a unit direction) whose
// rounding, ~1e-5, exceeds the true value, at most r² = 1e-6: with these rays it rejects 668 of
// 2000 central hits. The closest-point form hits all of them.
TEST(SphereIntersection, FarSmallSphereIsHitReliably) {
    int hits = 0;
    for (uint32_t i = 0; i < 2000; ++i) {
        RayCase ray = randomRay(i, vec3(0.0f), 1e-3f, 1e4f, 0.9f);
        if (gpu::intersectSphere(ray.origin, ray.direction, vec3(0.0f), 1e-3f, 0.0f, VKPT_FAR).hit)
            ++hits;
    }
    EXPECT_EQ(hits, 2000);
}

TEST(SphereIntersection, FromInsideHitsTheFarSide) {
    gpu::TriangleHit h = gpu::intersectSphere(vec3(0.5f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f),
                                              vec3(0.0f), 2.0f, 0.0f, VKPT_FAR);
    ASSERT_TRUE(h.hit);
    EXPECT_FLOAT_EQ(h.t, 1.5f);
    h = gpu::intersectSphere(vec3(0.5f, 0.0f, 0.0f), vec3(-2.0f, 0.0f, 0.0f), vec3(0.0f), 2.0f,
                             0.0f, VKPT_FAR);
    ASSERT_TRUE(h.hit);
    EXPECT_FLOAT_EQ(h.t, 1.25f); // t in units of |direction|
    EXPECT_EQ(h.u, 0.0f);
    EXPECT_EQ(h.v, 0.0f);
}

TEST(SphereIntersection, RespectsTheOpenDistanceRange) {
    const vec3 o(0.0f, 0.0f, -5.0f), d(0.0f, 0.0f, 1.0f);
    EXPECT_FLOAT_EQ(gpu::intersectSphere(o, d, vec3(0.0f), 1.0f, 0.0f, VKPT_FAR).t, 4.0f);
    EXPECT_FLOAT_EQ(gpu::intersectSphere(o, d, vec3(0.0f), 1.0f, 4.5f, VKPT_FAR).t, 6.0f);
    EXPECT_FALSE(gpu::intersectSphere(o, d, vec3(0.0f), 1.0f, 0.0f, 4.0f).hit);
    EXPECT_FALSE(gpu::intersectSphere(o, d, vec3(0.0f), 1.0f, 6.0f, VKPT_FAR).hit);
    EXPECT_FALSE(gpu::intersectSphere(o, -d, vec3(0.0f), 1.0f, 0.0f, VKPT_FAR).hit); // behind
    EXPECT_FALSE(gpu::intersectSphere(o, vec3(0.0f), vec3(0.0f), 1.0f, 0.0f, VKPT_FAR).hit);
    EXPECT_EQ(gpu::intersectSphere(o, d, vec3(0.0f), 1.0f, 0.0f, 3.0f).t, 3.0f); // miss: tMax
}

// A ray leaving the surface from a point put back on the sphere and offset along the normal
// (ray_offset.h with sphereCoordinateScale) does not hit the sphere again.
TEST(SphereIntersection, OffsetRaysDoNotReHitTheirSphere) {
    int reHits = 0;
    for (float radius : {1e-3f, 1.0f, 1e4f})
        for (vec3 centre : {vec3(0.0f), vec3(1e3f, -2e3f, 5e2f) * radius}) {
            float scale = gpu::sphereCoordinateScale(centre, radius);
            for (uint32_t i = 0; i < 5000; ++i) {
                vec4 u = gpu::randomFloats(32, i, 0, 0, DIM_BSDF);
                vec3 n = gpu::sampleUniformSphere(vec2(u.x, u.y));
                vec3 p = centre + radius * gpu::sphereNormalAt(centre + radius * n, centre);
                vec3 outward = gpu::sphereNormalAt(p, centre);
                vec3 local = gpu::sampleCosineHemisphere(vec2(u.z, u.w));
                vec3 out = gpu::basisToWorld(gpu::makeBasis(outward), local);
                if (gpu::intersectSphere(gpu::offsetFromSurface(p, outward, scale), out, centre,
                                         radius, 0.0f, VKPT_FAR)
                        .hit)
                    ++reHits;
                // and inside, leaving inwards, the ray meets only the far side
                vec3 in = -out;
                gpu::TriangleHit h = gpu::intersectSphere(
                    gpu::offsetFromSurface(p, -outward, scale), in, centre, radius, 0.0f, VKPT_FAR);
                if (h.hit && h.t < 1e-3f * radius) ++reHits;
            }
        }
    EXPECT_EQ(reHits, 0);
}

// ---------------------------------------------------------------------------------------------
TEST(SphereSurface, NormalIsUnitAndOutwardAtAnyScale) {
    EXPECT_EQ(gpu::sphereNormalAt(vec3(0.0f, 3.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f)),
              vec3(0.0f, 1.0f, 0.0f));
    vec3 tiny = gpu::sphereNormalAt(vec3(1e-30f, 2e-30f, 0.0f), vec3(0.0f));
    EXPECT_NEAR(glm::length(tiny), 1.0f, 1e-6f);
    EXPECT_GT(tiny.y, tiny.x);
    EXPECT_EQ(gpu::sphereNormalAt(vec3(1.0f), vec3(1.0f)), vec3(0.0f, 0.0f, 1.0f));
}

// The convention of sphereUv: v = 0 at +Y, 1 at −Y; u = 1/2 at +X, 1/4 at +Z, 3/4 at −Z, the
// seam u = 0 at −X.
TEST(SphereSurface, TextureCoordinatesFollowTheDocumentedConvention) {
    auto uvNear = [](vec3 n, float u, float v) {
        vec2 uv = gpu::sphereUv(n);
        EXPECT_NEAR(uv.x, u, 1e-6f) << n.x << " " << n.y << " " << n.z;
        EXPECT_NEAR(uv.y, v, 1e-6f) << n.x << " " << n.y << " " << n.z;
    };
    uvNear(vec3(0.0f, 1.0f, 0.0f), 0.5f, 0.0f); // pole: u taken at φ = 0
    uvNear(vec3(0.0f, -1.0f, 0.0f), 0.5f, 1.0f);
    uvNear(vec3(1.0f, 0.0f, 0.0f), 0.5f, 0.5f);
    uvNear(vec3(0.0f, 0.0f, 1.0f), 0.25f, 0.5f);
    uvNear(vec3(0.0f, 0.0f, -1.0f), 0.75f, 0.5f);
    uvNear(vec3(-1.0f, 0.0f, 0.0f), 0.0f, 0.5f);
    uvNear(glm::normalize(vec3(1.0f, 1.0f, 0.0f)), 0.5f, 0.25f);
    // Seen from +Z (right = +X), u grows to the right: the map is not mirrored from outside.
    EXPECT_LT(gpu::sphereUv(glm::normalize(vec3(-0.1f, 0.0f, 1.0f))).x,
              gpu::sphereUv(glm::normalize(vec3(0.1f, 0.0f, 1.0f))).x);
    for (uint32_t i = 0; i < 10000; ++i) {
        vec4 u = gpu::randomFloats(33, i, 0, 0, DIM_BSDF);
        vec2 uv = gpu::sphereUv(gpu::sampleUniformSphere(vec2(u.x, u.y)));
        ASSERT_TRUE(uv.x >= 0.0f && uv.x < 1.0f && uv.y >= 0.0f && uv.y <= 1.0f);
    }
}

TEST(SphereSurface, CoordinateScaleBoundsEveryPointOfTheSphere) {
    EXPECT_EQ(gpu::sphereCoordinateScale(vec3(1.0f, -7.0f, 3.0f), 2.0f), 9.0f);
    EXPECT_EQ(gpu::sphereCoordinateScale(vec3(0.0f), 1e-3f), 1e-3f);
}

// ---------------------------------------------------------------------------------------------
// Light sampling from outside: the direction from the receiver is uniform in the cone, so
// (1 − cos θ)/(1 − cos θmax) about the axis to the centre is uniform in [0, 1] and φ uniform.
// Angles are measured in double from the float sample positions (atan2 of the cross and dot
// products, since 1 − cos θ of a sphere 1e4 radii away is about 1e-8).
struct ConeCase {
    float distanceInRadii;
    float radius;
};

TEST(SphereLight, OutsideSamplesAreUniformInTheConeByChiSquare) {
    // α = 0.01 for the family, Šidák-corrected over the 4 cases.
    const ConeCase cases[] = {{1.05f, 1.0f}, {3.0f, 0.01f}, {100.0f, 2.0f}, {1e4f, 1e-3f}};
    const double perCaseAlpha = 1.0 - std::pow(0.99, 1.0 / 4.0);
    const int n = 100000, thetaBins = 20, phiBins = 16;
    uint32_t seed = 40;
    for (const ConeCase& c : cases) {
        const vec3 centre(0.5f * c.radius, -0.25f * c.radius, 0.0f);
        const vec3 receiver = centre + vec3(0.0f, 0.0f, c.distanceInRadii * c.radius);
        dvec3 axis = glm::normalize(dvec3(centre) - dvec3(receiver));
        gpu::Basis frame = gpu::makeBasis(vec3(axis));
        double sinMax = 1.0 / c.distanceInRadii;
        double oneMinusCosMax = sinMax * sinMax / (1.0 + std::sqrt(1.0 - sinMax * sinMax));
        std::vector<double> observed(size_t(thetaBins * phiBins), 0.0);
        for (uint32_t i = 0; i < uint32_t(n); ++i) {
            vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_LIGHT_FIRST);
            gpu::SphereLightSample s =
                gpu::sampleSphereLight(receiver, centre, c.radius, vec2(u.y, u.z));
            ASSERT_TRUE(s.valid);
            dvec3 w = glm::normalize(dvec3(s.position) - dvec3(receiver));
            double theta = std::atan2(glm::length(glm::cross(w, axis)), glm::dot(w, axis));
            double oneMinusCos = 2.0 * std::sin(0.5 * theta) * std::sin(0.5 * theta);
            double phi =
                std::atan2(glm::dot(w, dvec3(frame.bitangent)), glm::dot(w, dvec3(frame.tangent)));
            if (phi < 0.0) phi += 2.0 * kPi;
            int ti = std::min(thetaBins - 1, int(oneMinusCos / oneMinusCosMax * thetaBins));
            int pi = std::min(phiBins - 1, int(phi / (2.0 * kPi) * phiBins));
            observed[size_t(ti * phiBins + pi)] += 1.0;
        }
        std::vector<double> expected(observed.size(), double(n) / double(observed.size()));
        test::ChiSquareResult r = test::chiSquareTest(observed, expected);
        EXPECT_GT(r.pValue, perCaseAlpha) << "distance " << c.distanceInRadii << " radii: chi2 "
                                          << r.statistic << " dof " << r.degreesOfFreedom;
        ++seed;
    }
}

// From inside, points are uniform over the area: the normals are uniform over the unit sphere,
// so z = cos θ is uniform in [−1, 1] and φ uniform (Archimedes), by chi-square at α = 0.01.
TEST(SphereLight, InsideSamplesAreUniformOverTheAreaByChiSquare) {
    const int n = 100000, zBins = 16, phiBins = 16;
    std::vector<double> observed(size_t(zBins * phiBins), 0.0);
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        vec4 u = gpu::randomFloats(36, i, 0, 0, DIM_LIGHT_FIRST);
        gpu::SphereLightSample s =
            gpu::sampleSphereLight(vec3(0.3f, 0.0f, 0.0f), vec3(0.0f), 1.0f, vec2(u.y, u.z));
        ASSERT_TRUE(s.valid);
        double phi = std::atan2(double(s.normal.y), double(s.normal.x));
        if (phi < 0.0) phi += 2.0 * kPi;
        int zi = std::min(zBins - 1, int((double(s.normal.z) + 1.0) * 0.5 * zBins));
        int pi = std::min(phiBins - 1, int(phi / (2.0 * kPi) * phiBins));
        observed[size_t(zi * phiBins + pi)] += 1.0;
    }
    std::vector<double> expected(observed.size(), double(n) / double(observed.size()));
    test::ChiSquareResult r = test::chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

// Every sample lies on the sphere, is the first point a ray from the receiver meets there,
// faces the receiver when outside, and its pdf is sphereLightPdf's.
TEST(SphereLight, SamplesAreVisibleSurfacePointsWithTheirPdf) {
    const float radius = 2.0f;
    const vec3 centre(10.0f, -3.0f, 4.0f);
    for (float distanceInRadii : {0.0f, 0.5f, 0.999f, 1.5f, 10.0f, 1e3f}) {
        const vec3 receiver = centre + vec3(0.6f, 0.0f, 0.8f) * (distanceInRadii * radius);
        for (uint32_t i = 0; i < 5000; ++i) {
            vec4 u = gpu::randomFloats(34, i, 0, 0, DIM_LIGHT_FIRST);
            gpu::SphereLightSample s =
                gpu::sampleSphereLight(receiver, centre, radius, vec2(u.y, u.z));
            ASSERT_TRUE(s.valid) << distanceInRadii;
            ASSERT_NEAR(glm::length(s.position - centre), radius, 1e-5f * 16.0f);
            ASSERT_NEAR(glm::length(s.normal), 1.0f, 1e-6f);
            float pdf = gpu::sphereLightPdf(receiver, centre, radius, s.position);
            ASSERT_NEAR(pdf, s.pdfSolidAngle, 1e-5f * s.pdfSolidAngle) << distanceInRadii;
            vec3 toSample = s.position - receiver;
            gpu::TriangleHit hit =
                gpu::intersectSphere(receiver, toSample, centre, radius, 0.0f, VKPT_FAR);
            ASSERT_TRUE(hit.hit);
            ASSERT_NEAR(hit.t, 1.0f, 1e-3f) << distanceInRadii; // the first hit, not the far side
            if (distanceInRadii > 1.0f) {
                ASSERT_LT(glm::dot(s.normal, toSample), 0.0f);
            }
        }
    }
}

// From inside, the solid-angle pdf (area pdf · d²/|cos|) integrates to one over all directions:
// E[pdf(ω) · 4π] over uniform directions ω, each meeting the sphere at one point.
TEST(SphereLight, InsidePdfIntegratesToOne) {
    const float radius = 1.5f;
    const vec3 centre(1.0f, 2.0f, 3.0f);
    for (vec3 offset : {vec3(0.0f), vec3(0.0f, 1.2f, 0.0f), vec3(0.9f, 0.0f, -0.9f)}) {
        const vec3 receiver = centre + offset;
        const int n = 200000;
        double sum = 0.0, sumSquares = 0.0;
        for (uint32_t i = 0; i < uint32_t(n); ++i) {
            vec4 u = gpu::randomFloats(35, i, 0, 0, DIM_BSDF);
            vec3 w = gpu::sampleUniformSphere(vec2(u.x, u.y));
            gpu::TriangleHit hit =
                gpu::intersectSphere(receiver, w, centre, radius, 0.0f, VKPT_FAR);
            ASSERT_TRUE(hit.hit);
            double value =
                4.0 * kPi * gpu::sphereLightPdf(receiver, centre, radius, receiver + hit.t * w);
            sum += value;
            sumSquares += value * value;
        }
        double mean = sum / n;
        double sigma = std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / n);
        EXPECT_NEAR(mean, 1.0, 4.0 * sigma + 1e-4) << offset.x << " " << offset.y;
    }
}

// From outside the pdf is constant over the cone and 2π(1 − cos θmax) · pdf = 1; far away it
// stays finite and positive although 1 − cos θmax is below float resolution of cos θmax.
TEST(SphereLight, OutsidePdfIsTheReciprocalConeSolidAngle) {
    const vec3 receiver(0.0f);
    for (double d : {1.5, 10.0, 1e4, 1e7}) {
        const vec3 centre(0.0f, 0.0f, float(d));
        double sin2 = 1.0 / (d * d);
        double oneMinusCos = sin2 / (1.0 + std::sqrt(1.0 - sin2));
        float pdf = gpu::sphereLightPdf(receiver, centre, 1.0f, vec3(0.0f, 0.0f, float(d) - 1.0f));
        EXPECT_NEAR(pdf * 2.0 * kPi * oneMinusCos, 1.0, 1e-5) << d;
        gpu::SphereLightSample s = gpu::sampleSphereLight(receiver, centre, 1.0f, vec2(0.3f, 0.6f));
        EXPECT_TRUE(s.valid && std::isfinite(s.pdfSolidAngle) && s.pdfSolidAngle > 0.0f);
        EXPECT_FLOAT_EQ(s.pdfSolidAngle, pdf);
    }
}

TEST(SphereLight, DegenerateInputsAreInvalid) {
    EXPECT_FALSE(gpu::sampleSphereLight(vec3(0.0f), vec3(1.0f), 0.0f, vec2(0.5f)).valid);
    EXPECT_EQ(gpu::sphereLightPdf(vec3(0.0f), vec3(1.0f), 0.0f, vec3(1.0f)), 0.0f);
    // A receiver at the point it samples: no direction, no pdf.
    EXPECT_EQ(gpu::sphereLightPdf(vec3(0.0f, 0.0f, 1.0f), vec3(0.0f), 1.0f, vec3(0.0f, 0.0f, 1.0f)),
              0.0f);
}

} // namespace
} // namespace vkpt::sphere_test
