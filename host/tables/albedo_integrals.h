// albedo_integrals.h — the directional albedos of the GGX and Charlie sheen lobes (shared/ggx.h,
// shared/sheen.h) by deterministic quadrature, the values the albedo tables store.
#pragma once

#include <vector>

namespace vkpt::tables {

// ∫ f cos θi dωi of the GGX lobe with F = 1 (fresnelWeighted false) or with F = (1 − V·H)^5
// (true), for cos θo = cosThetaO and α = alpha. Visible-normal sampling (Heitz 2018) maps the
// unit square onto the lobe with weight G2/G1(wo), which is smooth there, so a midpoint rule on
// a `resolution`² grid of the square converges fast (1e-6 at 512²).
double ggxAlbedo(double cosThetaO, double alpha, bool fresnelWeighted, int resolution);

// The GGX lobe's albedo with F = the hat function of each film node (shared/iridescence.h,
// filmIntervalOf): node k's entry is ∫ hat_k(V·H) f cos θi dωi, so that a film term
// interpolated between its values F_k at the nodes has the albedo Σ F_k · entry k, and the
// entries sum to the albedo with F = 1.
std::vector<double> ggxFilmNodeAlbedos(double cosThetaO, double alpha, int resolution);

// ∫ D V cos θi dωi of the white Charlie sheen lobe: midpoint rule over cos θi and φi.
double sheenAlbedo(double cosThetaO, double alpha, int resolution);

} // namespace vkpt::tables
