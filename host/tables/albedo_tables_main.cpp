// albedo_tables_main.cpp — vkpt-albedo-tables: computes the directional albedo tables of the
// GGX lobe (with F = 1 and with Schlick's weight (1 − V·H)^5), their cosine-weighted averages
// and the Charlie sheen lobe's albedo, and writes them as shared/albedo_tables.h to stdout.
//
//   vkpt-albedo-tables > shaders/shared/albedo_tables.h
//   vkpt-albedo-tables --interpolation-error   (bilinear lookup against fresh quadrature)
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <vector>

#include "albedo_integrals.h"
#include "shared/ggx.h"
#include "shared/iridescence.h"
#include "shared/sheen.h"
#include "table_writer.h"

namespace vkpt::tables {
namespace {

constexpr int kSize = 64;        // nodes per axis
constexpr int kResolution = 256; // quadrature grid per axis
// cos θo = 0 is the limit of grazing views; the node is evaluated just above it.
constexpr double kSmallestCosine = 1e-4;
constexpr double kSheenRoughnessFloor = 0.1; // √VKPT_MIN_SHEEN_ALPHA

// Column i is at √(cos θo) = i/(N − 1): the albedos change fastest at grazing views, where this
// axis puts most nodes. The lobe functions take the axis coordinate x.
double cosineAt(double x) {
    return std::max(x * x, kSmallestCosine);
}

using Lobe = double (*)(double cosThetaO, double roughness);

double ggxPlain(double cosThetaO, double roughness) {
    return ggxAlbedo(cosineAt(cosThetaO), gpu::ggxAlphaOf(float(roughness)), false, kResolution);
}
double ggxFresnel(double cosThetaO, double roughness) {
    return ggxAlbedo(cosineAt(cosThetaO), gpu::ggxAlphaOf(float(roughness)), true, kResolution);
}
// The sheen's rows start at its smallest roughness, √VKPT_MIN_SHEEN_ALPHA = 0.1 (sheen.h), so
// that the clamp below it makes no kink inside a cell: row j is at roughness 0.1 + 0.9 j/(N − 1).
double sheen(double cosThetaO, double y) {
    const double roughness = kSheenRoughnessFloor + (1.0 - kSheenRoughnessFloor) * y;
    return sheenAlbedo(cosineAt(cosThetaO), gpu::sheenAlphaOf(float(roughness)), kResolution);
}

std::vector<double> table2d(Lobe lobe) {
    std::vector<double> values(kSize * kSize);
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
            values[std::size_t(j * kSize + i)] =
                lobe(double(i) / (kSize - 1), double(j) / (kSize - 1));
    return values;
}

// The film nodes' tables (ggxFilmNodeAlbedos), node k's 2D table after node k − 1's: one
// quadrature per cell fills all the nodes.
std::vector<double> filmNodeTables() {
    const std::size_t cells = std::size_t(kSize * kSize);
    std::vector<double> values(cells * VKPT_FILM_NODES);
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const double roughness = double(j) / (kSize - 1);
            const std::vector<double> nodes = ggxFilmNodeAlbedos(
                cosineAt(double(i) / (kSize - 1)), gpu::ggxAlphaOf(float(roughness)), kResolution);
            for (std::size_t k = 0; k < nodes.size(); ++k)
                values[k * cells + std::size_t(j * kSize + i)] = nodes[k];
        }
    return values;
}

// 2 ∫₀¹ E(μ) μ dμ of the E the lookup interpolates between the nodes of row j, linear in
// x = √μ: with μ = x², 2 ∫₀¹ E(x) x² 2x dx, in closed form per segment, so that the average is
// exactly that of what the lookup returns.
std::vector<double> averages(const std::vector<double>& table) {
    std::vector<double> result(kSize);
    for (int j = 0; j < kSize; ++j) {
        double integral = 0.0;
        for (int i = 0; i + 1 < kSize; ++i) {
            const double a = double(i) / (kSize - 1), b = double(i + 1) / (kSize - 1);
            const double ea = table[std::size_t(j * kSize + i)];
            const double eb = table[std::size_t(j * kSize + i + 1)];
            const double slope = (eb - ea) / (b - a);
            // ∫ (ea + slope (x − a)) 2x³ dx over [a, b]
            const double a4 = a * a * a * a, b4 = b * b * b * b;
            integral +=
                2.0 * ((ea - slope * a) * (b4 - a4) / 4.0 + slope * (b4 * b - a4 * a) / 5.0);
        }
        result[std::size_t(j)] = 2.0 * integral;
    }
    return result;
}

// averages() of each film node's table, node k's row after node k − 1's.
std::vector<double> filmNodeAverages(const std::vector<double>& tables) {
    const std::size_t cells = std::size_t(kSize * kSize);
    std::vector<double> result;
    for (std::size_t k = 0; k < VKPT_FILM_NODES; ++k) {
        const std::vector<double> node(tables.begin() + std::ptrdiff_t(k * cells),
                                       tables.begin() + std::ptrdiff_t((k + 1) * cells));
        const std::vector<double> average = averages(node);
        result.insert(result.end(), average.begin(), average.end());
    }
    return result;
}

double bilinear(const std::vector<double>& table, double x, double y) {
    const double fx = x * (kSize - 1), fy = y * (kSize - 1);
    const int i = std::min(int(fx), kSize - 2), j = std::min(int(fy), kSize - 2);
    const double tx = fx - i, ty = fy - j;
    auto at = [&](int jj, int ii) { return table[std::size_t(jj * kSize + ii)]; };
    return (1 - ty) * ((1 - tx) * at(j, i) + tx * at(j, i + 1)) +
           ty * ((1 - tx) * at(j + 1, i) + tx * at(j + 1, i + 1));
}

// The largest |lookup − quadrature| at the centres of the cells (where bilinear interpolation
// errs most) with cos θo above each of a few bounds, over a subset of cells: every cell in the
// first rows and columns (grazing, smooth) and every third elsewhere.
void reportInterpolationError(const char* name, const std::vector<double>& table, Lobe lobe) {
    const double bounds[] = {0.0, 0.01, 0.05, 0.2};
    double worst[4] = {}, worstX[4] = {}, worstY[4] = {};
    for (int j = 0; j + 1 < kSize; ++j)
        for (int i = 0; i + 1 < kSize; ++i) {
            if (i > 3 && j > 3 && (i % 3 != 0 || j % 3 != 0)) continue;
            const double x = (i + 0.5) / (kSize - 1), y = (j + 0.5) / (kSize - 1);
            const double error = std::abs(bilinear(table, x, y) - lobe(x, y));
            for (int b = 0; b < 4; ++b)
                if (x * x > bounds[b] && error > worst[b])
                    worst[b] = error, worstX[b] = x, worstY[b] = y;
        }
    for (int b = 0; b < 4; ++b)
        std::printf("%-22s cos θo > %.2f: max |bilinear − quadrature| %.5f at cos θo %.4f, "
                    "roughness %.4f\n",
                    name, bounds[b], worst[b], worstX[b] * worstX[b], worstY[b]);
}

} // namespace
} // namespace vkpt::tables

int main(int argc, char** argv) {
    using namespace vkpt::tables;
    const bool checkOnly = argc > 1 && std::strcmp(argv[1], "--interpolation-error") == 0;
    const std::vector<double> plain = table2d(ggxPlain);
    const std::vector<double> fresnel = table2d(ggxFresnel);
    const std::vector<double> sheenTable = table2d(sheen);
    const std::vector<double> filmNodes = filmNodeTables();
    if (checkOnly) {
        reportInterpolationError("GGX, F = 1", plain, ggxPlain);
        reportInterpolationError("GGX, F = (1 − V·H)^5", fresnel, ggxFresnel);
        reportInterpolationError("Charlie sheen", sheenTable, sheen);
        return 0;
    }
    const std::vector<NamedTable> tables = {
        {"ggxAlbedoTable",
         "E(cos θo, roughness) = ∫ D G2 / (4 cos θo cos θi) cos θi dωi, the GGX lobe with F = 1\n"
         "(ggx.h; α = ggxAlphaOf(roughness)).",
         plain},
        {"ggxFresnelAlbedoTable",
         "The same lobe weighted by Schlick's (1 − V·H)^5: with F = F0 + (1 − F0)(1 − V·H)^5 the\n"
         "albedo is F0 · ggxAlbedoTable + (1 − F0) · ggxFresnelAlbedoTable (linear in F0).",
         fresnel},
        {"ggxAverageAlbedoTable", "2 ∫ E(μ) μ dμ of ggxAlbedoTable's interpolated rows.",
         averages(plain)},
        {"ggxFresnelAverageAlbedoTable",
         "2 ∫ E(μ) μ dμ of ggxFresnelAlbedoTable's interpolated rows.", averages(fresnel)},
        {"sheenAlbedoTable",
         "∫ D V cos θi dωi of the white Charlie sheen lobe (sheen.h), row j at sheen roughness\n"
         "0.1 + 0.9 j/(N − 1) (α = roughness², at least VKPT_MIN_SHEEN_ALPHA = 0.1²).",
         sheenTable},
        {"ggxFilmNodeAlbedoTable",
         "KHR_materials_iridescence: the GGX lobe with F = the hat function of film node k\n"
         "(iridescence.h, filmIntervalOf), node k's 2D table after node k − 1's. A film term\n"
         "interpolated between its values F_k at the nodes has the albedo Σ F_k · table k.",
         filmNodes},
        {"ggxFilmNodeAverageAlbedoTable",
         "2 ∫ E(μ) μ dμ of each film node's interpolated rows, node k's after node k − 1's.",
         filmNodeAverages(filmNodes)},
    };
    writeTablesHeader(std::cout, kSize, tables);
    return 0;
}
