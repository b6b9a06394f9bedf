// albedo_lookup.h — reads the directional albedo tables of albedo_tables.h: bilinear in
// (√cos θo, √α), the axes along which the tables were computed (host/tables), and linear in √α
// for the averages, which are exactly the cosine-weighted means of what the 2D lookup returns.
//
// The seven tables lie end to end in one array of VKPT_ALBEDO_ENTRIES floats. The reference
// reads albedoTableEntries below; the kernels read the same numbers from the storage buffer
// albedoTables (BINDING_ALBEDO_TABLES, uploaded from albedoTableEntries), which
// lib/scene_arrays.glsl declares from its row of shared/scene_array_table.h before this
// header. As GLSL constants the tables made lavapipe's compiler take minutes and gigabytes per
// kernel; as a buffer they cost a load each, like any scene array.
#ifndef VKPT_ALBEDO_LOOKUP_H
#define VKPT_ALBEDO_LOOKUP_H

#include "host_device.h"
#include "iridescence.h"

#define VKPT_ALBEDO_TABLE_SIZE 64 // nodes per axis
#define VKPT_ALBEDO_2D_ENTRIES (VKPT_ALBEDO_TABLE_SIZE * VKPT_ALBEDO_TABLE_SIZE)
// Where each table starts in the array, in the order albedo_tables.h lists them.
#define VKPT_GGX_ALBEDO 0u
#define VKPT_GGX_FRESNEL_ALBEDO 4096u
#define VKPT_GGX_AVERAGE_ALBEDO 8192u
#define VKPT_GGX_FRESNEL_AVERAGE_ALBEDO 8256u
#define VKPT_SHEEN_ALBEDO 8320u
// KHR_materials_iridescence's film nodes last, so that a scene without a film uploads only what
// comes before them.
#define VKPT_GGX_FILM_NODE_ALBEDO 12416u
#define VKPT_ALBEDO_ENTRIES_WITHOUT_FILM 12416u
#define VKPT_GGX_FILM_NODE_AVERAGE_ALBEDO 77952u // + VKPT_FILM_NODES 2D tables
#define VKPT_ALBEDO_ENTRIES 78976u               // + VKPT_FILM_NODES 1D tables

#ifdef __cplusplus
#include <array>
#include <cstddef>

#include "albedo_tables.h"

namespace vkpt::gpu {

static_assert(std::size(ggxAlbedoTable) == VKPT_ALBEDO_2D_ENTRIES &&
              std::size(ggxFresnelAlbedoTable) == VKPT_ALBEDO_2D_ENTRIES &&
              std::size(ggxAverageAlbedoTable) == VKPT_ALBEDO_TABLE_SIZE &&
              std::size(ggxFresnelAverageAlbedoTable) == VKPT_ALBEDO_TABLE_SIZE &&
              std::size(sheenAlbedoTable) == VKPT_ALBEDO_2D_ENTRIES &&
              std::size(ggxFilmNodeAlbedoTable) == VKPT_FILM_NODES * VKPT_ALBEDO_2D_ENTRIES &&
              std::size(ggxFilmNodeAverageAlbedoTable) ==
                  VKPT_FILM_NODES * VKPT_ALBEDO_TABLE_SIZE &&
              VKPT_GGX_FILM_NODE_AVERAGE_ALBEDO ==
                  VKPT_GGX_FILM_NODE_ALBEDO + VKPT_FILM_NODES * VKPT_ALBEDO_2D_ENTRIES &&
              VKPT_ALBEDO_ENTRIES ==
                  VKPT_GGX_FILM_NODE_AVERAGE_ALBEDO + VKPT_FILM_NODES * VKPT_ALBEDO_TABLE_SIZE);

// The tables end to end, as the device's buffer holds them. Copied when the program starts, not
// at compile time: as a constant expression the copy of 78 976 floats cost every translation
// unit that includes this header 3 s of compilation.
inline std::array<float, VKPT_ALBEDO_ENTRIES> concatenatedAlbedoTables() {
    std::array<float, VKPT_ALBEDO_ENTRIES> all{};
    std::size_t n = 0;
    for (float v : ggxAlbedoTable)
        all[n++] = v;
    for (float v : ggxFresnelAlbedoTable)
        all[n++] = v;
    for (float v : ggxAverageAlbedoTable)
        all[n++] = v;
    for (float v : ggxFresnelAverageAlbedoTable)
        all[n++] = v;
    for (float v : sheenAlbedoTable)
        all[n++] = v;
    for (float v : ggxFilmNodeAlbedoTable)
        all[n++] = v;
    for (float v : ggxFilmNodeAverageAlbedoTable)
        all[n++] = v;
    return all;
}

inline const std::array<float, VKPT_ALBEDO_ENTRIES> albedoTableEntries = concatenatedAlbedoTables();

inline float albedoEntry(uint i) {
    return albedoTableEntries[i];
}
#else
float albedoEntry(uint i) {
    return albedoTables[i];
}
#endif

// The four nodes around a point of a 2D table and its weights along each axis.
struct AlbedoCell {
    uint index; // the node below and left: row · size + column
    float tx;   // weight of the next column
    float ty;   // weight of the next row
};

// Node coordinate of an axis value in [0, 1]: the cell's first node and the fraction past it.
VKPT_FN float albedoAxis(float value) {
    return clamp(value, 0.0f, 1.0f) * float(VKPT_ALBEDO_TABLE_SIZE - 1);
}

VKPT_FN uint albedoNode(float coordinate) {
    return min(uint(coordinate), uint(VKPT_ALBEDO_TABLE_SIZE - 2));
}

// rows: the row axis' value in [0, 1] (√α for the GGX tables).
VKPT_FN AlbedoCell albedoCell(float cosTheta, float rows) {
    float x = albedoAxis(sqrt(clamp(cosTheta, 0.0f, 1.0f)));
    float y = albedoAxis(rows);
    uint i = albedoNode(x);
    uint j = albedoNode(y);
    AlbedoCell c;
    c.index = j * uint(VKPT_ALBEDO_TABLE_SIZE) + i;
    c.tx = x - float(i);
    c.ty = y - float(j);
    return c;
}

// The 2D table starting at `table`, interpolated in cell c.
VKPT_FN float albedoBilinear(uint table, AlbedoCell c) {
    uint i = table + c.index;
    uint row = uint(VKPT_ALBEDO_TABLE_SIZE);
    return mix(mix(albedoEntry(i), albedoEntry(i + 1u), c.tx),
               mix(albedoEntry(i + row), albedoEntry(i + row + 1u), c.tx), c.ty);
}

// The 1D table starting at `table`, interpolated at row coordinate `rows` in [0, 1].
VKPT_FN float albedoLinear(uint table, float rows) {
    float y = albedoAxis(rows);
    uint j = albedoNode(y);
    return mix(albedoEntry(table + j), albedoEntry(table + j + 1u), y - float(j));
}

// E of the GGX lobe with F = 1, and with Schlick's weight (1 − V·H)^5, at cos θo for α.
VKPT_FN float ggxAlbedo(float cosTheta, float alpha) {
    return albedoBilinear(VKPT_GGX_ALBEDO, albedoCell(cosTheta, sqrt(alpha)));
}

VKPT_FN float ggxFresnelAlbedo(float cosTheta, float alpha) {
    return albedoBilinear(VKPT_GGX_FRESNEL_ALBEDO, albedoCell(cosTheta, sqrt(alpha)));
}

// E of the white Charlie sheen lobe at cos θo for the sheen α, whose rows run from roughness
// √VKPT_MIN_SHEEN_ALPHA = 0.1 to 1.
VKPT_FN float sheenAlbedo(float cosTheta, float alpha) {
    return albedoBilinear(VKPT_SHEEN_ALBEDO, albedoCell(cosTheta, (sqrt(alpha) - 0.1f) / 0.9f));
}

// 2 ∫ E(μ) μ dμ of the two GGX lookups above, for α.
VKPT_FN float ggxAverageAlbedo(float alpha) {
    return albedoLinear(VKPT_GGX_AVERAGE_ALBEDO, sqrt(alpha));
}

VKPT_FN float ggxFresnelAverageAlbedo(float alpha) {
    return albedoLinear(VKPT_GGX_FRESNEL_AVERAGE_ALBEDO, sqrt(alpha));
}

// The albedo of the GGX lobe with F = the hat function of film node k (iridescence.h), in cell
// c of α's table, and its cosine-weighted average for α.
VKPT_FN float filmNodeAlbedo(int k, AlbedoCell c) {
    return albedoBilinear(VKPT_GGX_FILM_NODE_ALBEDO + uint(k) * uint(VKPT_ALBEDO_2D_ENTRIES), c);
}

VKPT_FN float filmNodeAverageAlbedo(int k, float alpha) {
    return albedoLinear(VKPT_GGX_FILM_NODE_AVERAGE_ALBEDO + uint(k) * uint(VKPT_ALBEDO_TABLE_SIZE),
                        sqrt(alpha));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_ALBEDO_LOOKUP_H
