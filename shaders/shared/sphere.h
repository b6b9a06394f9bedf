// sphere.h — analytic spheres: the ray test, the surface frame and texture coordinates, and
// sampling a spherical emitter by the cone of directions it subtends.
#ifndef VKPT_SPHERE_H
#define VKPT_SPHERE_H

#include "host_device.h"
#include "intersect.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Roots of |f + t·d|² = r² (f = origin − centre), written a t² + 2 b t + c = 0 with a = d·d,
// b = f·d, c = f·f − r². Haines et al., "Precision Improvements for Ray/Sphere Intersection"
// (Ray Tracing Gems, ch. 7, 2019): the discriminant b² − a c cancels catastrophically when the
// origin is far away (both terms ~|f|⁴ while their difference is ~r²|f|²), so it is computed as
// a (r² − |l|²) with l = f − (b/a) d, the vector from the centre to the line's closest point,
// which is accurate to a few ulps of |f|. The roots then come from the form that never
// subtracts nearly equal numbers: q = −(b + sign(b)·√disc), t = c/q and t = q/a.
// direction need not be unit (t is in units of |direction|); the nearest root in (tMin, tMax)
// is the hit, from outside or inside; u and v are 0.
VKPT_FN TriangleHit intersectSphere(vec3 origin, vec3 direction, vec3 centre, float radius,
                                    float tMin, float tMax) {
    TriangleHit result = triangleMiss(tMax);
    float a = dot(direction, direction);
    if (!(a > 0.0f)) return result;
    vec3 f = origin - centre;
    float b = dot(f, direction);
    vec3 l = f - (b / a) * direction;
    float discriminant = a * (radius * radius - dot(l, l));
    if (discriminant < 0.0f) return result;
    float c = dot(f, f) - radius * radius;
    float q = -(b + (b >= 0.0f ? sqrt(discriminant) : -sqrt(discriminant)));
    // q = 0 only for b = 0 and a tangent line, whose one root is then t = 0 (c = 0).
    float t0 = q != 0.0f ? c / q : 0.0f;
    float t1 = q / a;
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    float t = tNear > tMin && tNear < tMax ? tNear : tFar;
    if (!(t > tMin && t < tMax)) return result;
    result.t = t;
    result.hit = true;
    return result;
}

// The unit outward normal at a point on (or near) the sphere, scaled by its largest component
// before normalising so that tiny spheres do not underflow; +z for the centre itself.
VKPT_FN vec3 sphereNormalAt(vec3 point, vec3 centre) {
    vec3 v = point - centre;
    float largest = largestMagnitude(v);
    return largest > 0.0f ? normalize(v / largest) : vec3(0.0f, 0.0f, 1.0f);
}

// GLSL spells the two-argument arctangent atan(y, x); the pole (x = y = 0), undefined there,
// is taken as 0 on both sides.
VKPT_FN float sphereAtan2(float y, float x) {
    return (x == 0.0f && y == 0.0f) ? 0.0f : atan(y, x);
}

// Equirectangular texture coordinates of a unit outward normal, +Y up:
//   v = θ/π with θ the angle from +Y: v = 0 at +Y (the image's top row), 1 at −Y;
//   u = 1/2 − φ/(2π) with φ = atan2(z, x): u = 1/2 at +X, 1/4 at +Z, 3/4 at −Z, and the seam
//   (u = 0) at −X.
// This is environment.h's map mirrored in u: the environment is seen from inside, a sphere from
// outside, and both then show the image unmirrored (a camera on +Z looking at the sphere sees
// u grow to its right, towards +X). u lies in [0, 1), v in [0, 1].
VKPT_FN vec2 sphereUv(vec3 unitOutwardNormal) {
    vec3 n = unitOutwardNormal;
    float theta = sphereAtan2(length(vec2(n.x, n.z)), n.y); // atan2 keeps the poles accurate
    float u = 0.5f - sphereAtan2(n.z, n.x) * (0.5f * VKPT_INV_PI);
    if (u >= 1.0f) u -= 1.0f;
    return vec2(u, theta * VKPT_INV_PI);
}

// The coordinate magnitude for offsetFromSurface (ray_offset.h), like triangleCoordinateScale:
// every point of the sphere has coordinates within |centre| + radius. It bounds the rounding
// of a hit point put back on the surface as centre + radius·sphereNormalAt(p, centre); o + t·d
// itself errs by ulps of the ray origin's distance, which can be far larger.
VKPT_FN float sphereCoordinateScale(vec3 centre, float radius) {
    return largestMagnitude(centre) + abs(radius);
}

struct SphereLightSample {
    vec3 position;       // on the sphere
    vec3 normal;         // unit, outward
    float pdfSolidAngle; // with respect to the direction from the receiver
    bool valid;
};

VKPT_FN SphereLightSample invalidSphereLightSample() {
    SphereLightSample s;
    s.position = vec3(0.0f);
    s.normal = vec3(0.0f, 0.0f, 1.0f);
    s.pdfSolidAngle = 0.0f;
    s.valid = false;
    return s;
}

// 1 − cos θmax of the cone a sphere subtends from a point outside it, as sin²/(1 + cos): the
// difference 1 − cos θmax is below float resolution for a sphere 1e4 radii away.
VKPT_FN float sphereConeOneMinusCos(float distanceSquared, float radiusSquared) {
    float sin2ThetaMax = radiusSquared / distanceSquared;
    return sin2ThetaMax / (1.0f + sqrt(max(0.0f, 1.0f - sin2ThetaMax)));
}

// A receiver inside or on the sphere samples its area uniformly; the solid-angle pdf is the area
// pdf 1/(4π r²) times distance² / |cos θ at the light|.
VKPT_FN float sphereAreaPdfToSolidAngle(vec3 receiver, vec3 centre, float radius, vec3 point) {
    vec3 toPoint = point - receiver;
    float distanceSquared = dot(toPoint, toPoint);
    if (!(distanceSquared > 0.0f)) return 0.0f;
    // |cos θ| · distance², the distance divided out once
    float cosTimesDistance = abs(dot(sphereNormalAt(point, centre), toPoint));
    float denominator = cosTimesDistance * 4.0f * VKPT_PI * radius * radius;
    return denominator > 0.0f ? distanceSquared * sqrt(distanceSquared) / denominator : 0.0f;
}

// Uniform in the cone of directions the sphere subtends from an outside receiver (pbrt-v3,
// Sphere::Sample(ref, u), §14.2.2), written for precision: 1 − cos θ is drawn uniformly in
// [0, 1 − cos θmax] and kept as such, and the point is placed by its angle α at the centre,
// away from the receiver's axis, from cos α = sin²θ/sin θmax + cos θ √(1 − sin²θ/sin²θmax)
// and sin α = s sin θ / r with s = (d² − r²)/(d cos θ + √(r² − d² sin²θ)) the distance to the
// near intersection. The point is computed at the sphere's scale, not from the receiver.
VKPT_FN SphereLightSample sampleSphereLight(vec3 receiver, vec3 centre, float radius, vec2 u) {
    SphereLightSample s = invalidSphereLightSample();
    vec3 toCentre = centre - receiver;
    float distanceSquared = dot(toCentre, toCentre);
    float radiusSquared = radius * radius;
    if (!(radiusSquared > 0.0f)) return s;
    if (distanceSquared <= radiusSquared) {
        s.normal = sampleUniformSphere(u);
        s.position = centre + radius * s.normal;
        s.pdfSolidAngle = sphereAreaPdfToSolidAngle(receiver, centre, radius, s.position);
        s.valid = s.pdfSolidAngle > 0.0f;
        return s;
    }
    float centreDistance = sqrt(distanceSquared);
    float oneMinusCosMax = sphereConeOneMinusCos(distanceSquared, radiusSquared);
    if (!(oneMinusCosMax > 0.0f)) return s;
    float sin2ThetaMax = radiusSquared / distanceSquared;
    float oneMinusCos = u.x * oneMinusCosMax;
    float sin2Theta = oneMinusCos * (2.0f - oneMinusCos);
    float cosTheta = 1.0f - oneMinusCos;
    float sinTheta = sqrt(sin2Theta);
    float chordRoot = radius * sqrt(max(0.0f, 1.0f - sin2Theta / sin2ThetaMax));
    float nearDistance =
        (distanceSquared - radiusSquared) / (centreDistance * cosTheta + chordRoot);
    float cosAlpha = sin2Theta / sqrt(sin2ThetaMax) +
                     cosTheta * sqrt(max(0.0f, 1.0f - sin2Theta / sin2ThetaMax));
    float sinAlpha = nearDistance * sinTheta / radius;
    float phi = 2.0f * VKPT_PI * u.y;
    Basis frame = makeBasis(-toCentre / centreDistance); // z: from the centre towards the receiver
    s.normal =
        normalize(basisToWorld(frame, vec3(sinAlpha * cos(phi), sinAlpha * sin(phi), cosAlpha)));
    s.position = centre + radius * s.normal;
    s.pdfSolidAngle = 1.0f / (2.0f * VKPT_PI * oneMinusCosMax);
    s.valid = true;
    return s;
}

// The solid-angle pdf sampleSphereLight has for the direction from receiver to pointOnSphere
// (a point a ray from receiver hits first, as a light sample is).
VKPT_FN float sphereLightPdf(vec3 receiver, vec3 centre, float radius, vec3 pointOnSphere) {
    vec3 toCentre = centre - receiver;
    float distanceSquared = dot(toCentre, toCentre);
    float radiusSquared = radius * radius;
    if (!(radiusSquared > 0.0f)) return 0.0f;
    if (distanceSquared <= radiusSquared)
        return sphereAreaPdfToSolidAngle(receiver, centre, radius, pointOnSphere);
    float oneMinusCosMax = sphereConeOneMinusCos(distanceSquared, radiusSquared);
    return oneMinusCosMax > 0.0f ? 1.0f / (2.0f * VKPT_PI * oneMinusCosMax) : 0.0f;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SPHERE_H
