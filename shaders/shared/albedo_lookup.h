// albedo_lookup.h — reads the directional albedo tables of albedo_tables.h: bilinear in
// (√cos θo, √α), the axes along which the tables were computed (host/tables), and linear in √α
// for the averages, which are exactly the cosine-weighted means of what the 2D lookup returns.
#ifndef VKPT_ALBEDO_LOOKUP_H
#define VKPT_ALBEDO_LOOKUP_H

#include "albedo_tables.h"
#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
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

VKPT_FN float bilinear(AlbedoCell c, float v00, float v10, float v01, float v11) {
    return mix(mix(v00, v10, c.tx), mix(v01, v11, c.tx), c.ty);
}

// One function per table: GLSL passes arrays by value, so the table is named, not passed.
#define VKPT_ALBEDO_2D(table, c)                                                                   \
    bilinear(c, table[c.index], table[c.index + 1u],                                               \
             table[c.index + uint(VKPT_ALBEDO_TABLE_SIZE)],                                        \
             table[c.index + uint(VKPT_ALBEDO_TABLE_SIZE) + 1u])

// E of the GGX lobe with F = 1, and with Schlick's weight (1 − V·H)^5, at cos θo for α.
VKPT_FN float ggxAlbedo(float cosTheta, float alpha) {
    AlbedoCell c = albedoCell(cosTheta, sqrt(alpha));
    return VKPT_ALBEDO_2D(ggxAlbedoTable, c);
}

VKPT_FN float ggxFresnelAlbedo(float cosTheta, float alpha) {
    AlbedoCell c = albedoCell(cosTheta, sqrt(alpha));
    return VKPT_ALBEDO_2D(ggxFresnelAlbedoTable, c);
}

// E of the white Charlie sheen lobe at cos θo for the sheen α, whose rows run from roughness
// √VKPT_MIN_SHEEN_ALPHA = 0.1 to 1.
VKPT_FN float sheenAlbedo(float cosTheta, float alpha) {
    AlbedoCell c = albedoCell(cosTheta, (sqrt(alpha) - 0.1f) / 0.9f);
    return VKPT_ALBEDO_2D(sheenAlbedoTable, c);
}

// 2 ∫ E(μ) μ dμ of the two GGX lookups above, for α.
VKPT_FN float ggxAverageAlbedo(float alpha) {
    float y = albedoAxis(sqrt(alpha));
    uint j = albedoNode(y);
    return mix(ggxAverageAlbedoTable[j], ggxAverageAlbedoTable[j + 1u], y - float(j));
}

VKPT_FN float ggxFresnelAverageAlbedo(float alpha) {
    float y = albedoAxis(sqrt(alpha));
    uint j = albedoNode(y);
    return mix(ggxFresnelAverageAlbedoTable[j], ggxFresnelAverageAlbedoTable[j + 1u], y - float(j));
}

#undef VKPT_ALBEDO_2D

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_ALBEDO_LOOKUP_H
