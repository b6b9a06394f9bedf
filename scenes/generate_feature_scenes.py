#!/usr/bin/env python3
"""generate_feature_scenes.py — writes the small scenes that exercise one part of vkpt's scene
model each (scenes/test/features/): analytic spheres, glTF metallic-roughness (GGX)
materials, textures with KHR_texture_transform and alpha MASK, normal textures (with generated
and stored tangents), KHR_lights_punctual lights, a scene lit only by the environment (with a
tiny equirectangular .hdr), an orthographic camera, glass: KHR_materials_transmission,
KHR_materials_ior and KHR_materials_volume (smooth and rough, solid and thin-walled, clear and
absorbing), the KHR_materials_clearcoat and KHR_materials_sheen layers, and
KHR_materials_anisotropy (brushed metal with stored and generated tangents), and
KHR_materials_iridescence (thin films on spheres).

Run from anywhere:  python3 scenes/generate_feature_scenes.py

Standard library only; deterministic output. The tests render every scene with vkpt-ref and
vkpt at one seed and compare them pixel by pixel, so the scenes are small and each feature
covers a good part of the image. scenes/README.md describes them.
"""

import math
import struct
from pathlib import Path

from generate_loader_scenes import (Gltf, data_uri, floats, json_text, png_bytes, primitive,
                                    write,
                                    write_embedded)

FEATURES_DIR = Path(__file__).resolve().parent / "test" / "features"
SPECULAR = "KHR_materials_specular"
EMISSIVE_STRENGTH = "KHR_materials_emissive_strength"
TEXTURE_TRANSFORM = "KHR_texture_transform"
PUNCTUAL = "KHR_lights_punctual"
CLEARCOAT = "KHR_materials_clearcoat"
SHEEN = "KHR_materials_sheen"
SHAPES = "KHR_implicit_shapes"
TRANSMISSION = "KHR_materials_transmission"
IOR = "KHR_materials_ior"
VOLUME = "KHR_materials_volume"
ANISOTROPY = "KHR_materials_anisotropy"
IRIDESCENCE = "KHR_materials_iridescence"
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
FLOAT = 5126


class FeatureScene(Gltf):
    """A Gltf with the helpers these scenes need: quads and boxes, materials of both kinds,
    textures, spheres, punctual lights and a camera."""

    def __init__(self):
        super().__init__()
        self.roots = []
        self.extensions = set()

    def use(self, extension):
        self.extensions.add(extension)

    def material(self, name, base, metallic=0.0, roughness=1.0, diffuse=False, emission=None,
                 strength=None, double_sided=False, **extra):
        """diffuse=True: specularFactor 0, the Lambertian kind; else glTF's GGX model."""
        pbr = {"baseColorFactor": list(base) + ([1.0] if len(base) == 3 else []),
               "metallicFactor": metallic, "roughnessFactor": roughness}
        pbr.update(extra.pop("pbr", {}))
        m = {"name": name, "pbrMetallicRoughness": pbr}
        extensions = {}
        if diffuse:
            extensions[SPECULAR] = {"specularFactor": 0.0}
            self.use(SPECULAR)
        if emission is not None:
            m["emissiveFactor"] = list(emission)
        if strength is not None:
            extensions[EMISSIVE_STRENGTH] = {"emissiveStrength": strength}
            self.use(EMISSIVE_STRENGTH)
        if extensions:
            m["extensions"] = extensions
        if double_sided:
            m["doubleSided"] = True
        m.update(extra)
        return self.add("materials", m)

    def glass(self, name, base=(1.0, 1.0, 1.0), roughness=0.0, ior=1.5, thickness=None,
              attenuation_color=None, attenuation_distance=None, transmission=1.0):
        """A KHR_materials_transmission material (metallic 0) with KHR_materials_ior and, when
        thickness is given, KHR_materials_volume (thickness 0: thin-walled)."""
        extensions = {TRANSMISSION: {"transmissionFactor": transmission}, IOR: {"ior": ior}}
        self.use(TRANSMISSION)
        self.use(IOR)
        if thickness is not None:
            volume = {"thicknessFactor": thickness}
            if attenuation_color is not None:
                volume["attenuationColor"] = list(attenuation_color)
            if attenuation_distance is not None:
                volume["attenuationDistance"] = attenuation_distance
            extensions[VOLUME] = volume
            self.use(VOLUME)
        return self.material(name, base, metallic=0.0, roughness=roughness,
                             extensions=extensions)

    def quad(self, name, corner, edge_u, edge_v, material, uv_scale=1.0, tangent=None,
             **node):
        """A rectangle corner + s·edge_u + t·edge_v, front face (counter-clockwise) along
        edge_u × edge_v, with texture coordinates (s, t)·uv_scale and, if given, the TANGENT
        `tangent` (x, y, z, w) at every corner; `node` adds fields to its node."""
        p = [corner,
             [corner[i] + edge_u[i] for i in range(3)],
             [corner[i] + edge_u[i] + edge_v[i] for i in range(3)],
             [corner[i] + edge_v[i] for i in range(3)]]
        n = cross(edge_u, edge_v)
        length = math.sqrt(sum(c * c for c in n))
        n = [c / length for c in n]
        uv = [(0.0, 0.0), (uv_scale, 0.0), (uv_scale, uv_scale), (0.0, uv_scale)]
        prim = primitive(self.positions(p), self.normals([n] * 4),
                         self.indices([0, 1, 2, 0, 2, 3], UNSIGNED_SHORT), material,
                         texcoord=self.texcoords(uv))
        if tangent is not None:
            prim["attributes"]["TANGENT"] = self.accessor(
                self.view(floats([tangent] * 4), target=ARRAY_BUFFER), FLOAT, 4, "VEC4")
        self.roots.append(self.node(name=name, mesh=self.mesh([prim], name), **node))

    def box(self, name, lo, hi, material):
        """An axis-aligned box with outward faces."""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        dx, dy, dz = x1 - x0, y1 - y0, z1 - z0
        self.quad(name + " -x", [x0, y0, z0], [0, 0, dz], [0, dy, 0], material)
        self.quad(name + " +x", [x1, y0, z0], [0, dy, 0], [0, 0, dz], material)
        self.quad(name + " -y", [x0, y0, z0], [dx, 0, 0], [0, 0, dz], material)
        self.quad(name + " +y", [x0, y1, z0], [0, 0, dz], [dx, 0, 0], material)
        self.quad(name + " -z", [x0, y0, z0], [0, dy, 0], [dx, 0, 0], material)
        self.quad(name + " +z", [x0, y0, z1], [dx, 0, 0], [0, dy, 0], material)

    def texture(self, rows, sampler=None):
        image = self.add("images", {"uri": data_uri(png_bytes(rows), "image/png")})
        texture = {"source": image}
        if sampler is not None:
            texture["sampler"] = self.add("samplers", sampler)
        return self.add("textures", texture)

    def sphere(self, name, centre, radius, material):
        shapes = self.doc.setdefault("extensions", {}).setdefault(SHAPES, {"shapes": []})
        shapes["shapes"].append({"type": "sphere", "sphere": {"radius": radius}})
        self.use(SHAPES)
        self.roots.append(self.node(name=name, translation=list(centre),
                                    extensions={SHAPES: {"shape": len(shapes["shapes"]) - 1}},
                                    extras={"vkpt_material": material}))

    def light(self, name, light, translation=None, rotation=None):
        lights = self.doc.setdefault("extensions", {}).setdefault(PUNCTUAL, {"lights": []})
        lights["lights"].append(dict(light, name=name))
        self.use(PUNCTUAL)
        node = {"name": name, "extensions": {PUNCTUAL: {"light": len(lights["lights"]) - 1}}}
        if translation is not None:
            node["translation"] = list(translation)
        if rotation is not None:
            node["rotation"] = list(rotation)
        self.roots.append(self.node(**node))

    def camera(self, eye, yfov_degrees=45.0):
        """A camera at eye looking along −Z (the glTF camera's own direction)."""
        camera = self.add("cameras", {"type": "perspective", "name": "camera",
                                      "perspective": {"yfov": math.radians(yfov_degrees),
                                                      "znear": 0.01}})
        self.roots.append(self.node(name="camera", camera=camera, translation=list(eye)))

    def orthographic_camera(self, eye, pitch_degrees, xmag, ymag):
        """An orthographic camera at eye looking along −Z turned about X by pitch_degrees."""
        camera = self.add("cameras", {"type": "orthographic", "name": "orthographic camera",
                                      "orthographic": {"xmag": xmag, "ymag": ymag,
                                                       "znear": 0.0, "zfar": 100.0}})
        self.roots.append(self.node(name="camera", camera=camera, translation=list(eye),
                                    rotation=quat_about_x(pitch_degrees)))

    def save(self, name):
        if self.extensions:
            self.doc["extensionsUsed"] = sorted(self.extensions)
        self.scene(self.roots)
        if not self.doc.get("bufferViews"):
            # Spheres alone need no binary data, and an empty data URI is not valid base64.
            self.doc.pop("buffers", None)
            write(FEATURES_DIR / name, json_text(self.doc))
            return
        write_embedded(FEATURES_DIR / name, self)


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quat_about_x(degrees):
    h = math.radians(degrees) / 2.0
    return [math.sin(h), 0.0, 0.0, math.cos(h)]


def room(scene, floor_material, back_material):
    """A floor (y = 0) and a back wall (z = −1) seen by a camera at (0, 0.6, 2.2)."""
    scene.quad("floor", [-1.5, 0.0, 1.5], [3.0, 0.0, 0.0], [0.0, 0.0, -3.0], floor_material,
               uv_scale=3.0)
    scene.quad("back wall", [-1.5, 0.0, -1.0], [3.0, 0.0, 0.0], [0.0, 2.0, 0.0], back_material)
    scene.camera([0.0, 0.6, 2.2], 50.0)


def spheres():
    """A diffuse, a rough-metal and a glossy dielectric sphere next to an emitting sphere."""
    s = FeatureScene()
    white = s.material("white", (0.75, 0.75, 0.75), diffuse=True)
    room(s, white, white)
    s.sphere("diffuse sphere", (-0.75, 0.35, 0.0), 0.35, s.material("red", (0.7, 0.1, 0.1),
                                                                      diffuse=True))
    s.sphere("metal sphere", (0.0, 0.35, 0.1), 0.35,
             s.material("gold", (1.0, 0.78, 0.34), metallic=1.0, roughness=0.3))
    s.sphere("glossy sphere", (0.75, 0.35, 0.0), 0.35,
             s.material("blue plastic", (0.1, 0.2, 0.7), roughness=0.15))
    s.sphere("light sphere", (0.0, 1.4, 0.3), 0.2,
             s.material("sphere light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 0.9, 0.8),
                        strength=12.0))
    s.save("spheres.gltf")


def ggx():
    """Metals and dielectrics across roughness under a quad light, so that glossy reflections
    of the light and of the walls cover much of the image."""
    s = FeatureScene()
    grey = s.material("grey", (0.6, 0.6, 0.6), diffuse=True)
    room(s, s.material("polished floor", (0.5, 0.5, 0.55), roughness=0.2), grey)
    for i, (roughness, metallic) in enumerate([(0.05, 1.0), (0.35, 1.0), (0.7, 1.0),
                                               (0.35, 0.0)]):
        x = -1.2 + 0.6 * i
        s.box(f"block {i}", [x, 0.0, -0.5], [x + 0.45, 0.5 + 0.15 * i, -0.05],
              s.material(f"rough {roughness} metal {metallic}", (0.9, 0.6, 0.4),
                         metallic=metallic, roughness=roughness))
    s.quad("light", [-0.5, 1.6, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("ggx.gltf")


def layer_material(scene, name, base, extension, layer, metallic=0.0, roughness=0.5, **extra):
    """A GGX material with one layer extension (clearcoat or sheen) and its parameters."""
    scene.use(extension)
    return scene.material(name, base, metallic=metallic, roughness=roughness,
                          extensions={extension: layer}, **extra)


def clearcoat():
    """Clearcoat (KHR_materials_clearcoat) over a rough red dielectric, a rough metal and a
    diffuse-looking base, glossy and rough, one with clearcoat and clearcoat roughness
    textures, two with normal textures (the coat's own, and the base's under a flat coat),
    under a quad light: the coat's sharp highlight over each base."""
    s = FeatureScene()
    grey = s.material("grey", (0.6, 0.6, 0.6), diffuse=True)
    room(s, grey, grey)
    # R: clearcoat strength, G: clearcoat roughness, in stripes.
    stripes = s.texture([[(255, 20, 0, 255), (90, 200, 0, 255)]] * 2,
                        {"magFilter": 9728, "wrapS": 10497, "wrapT": 10497})
    layers = [
        ("coated red paint", (0.7, 0.08, 0.05), 0.0, 0.6, {"clearcoatFactor": 1.0,
                                                          "clearcoatRoughnessFactor": 0.03}),
        ("coated rough metal", (0.9, 0.7, 0.4), 1.0, 0.7, {"clearcoatFactor": 0.8,
                                                           "clearcoatRoughnessFactor": 0.2}),
        ("hazy coat", (0.2, 0.4, 0.7), 0.0, 0.9, {"clearcoatFactor": 1.0,
                                                  "clearcoatRoughnessFactor": 0.5}),
        ("textured coat", (0.3, 0.6, 0.3), 0.0, 0.8, {
            "clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 1.0,
            "clearcoatTexture": {"index": stripes},
            "clearcoatRoughnessTexture": {"index": stripes}}),
    ]
    for i, (name, base, metallic, roughness, layer) in enumerate(layers):
        x = -1.2 + 0.6 * i
        s.box(f"block {i}", [x, 0.0, -0.5], [x + 0.45, 0.45, -0.05],
              layer_material(s, name, base, CLEARCOAT, layer, metallic, roughness))
    # Normal maps and the coat (tangents generated): bumps in the coat over a flat base (car
    # paint's orange peel), and bumps in the base under a flat coat, which the extension says
    # keeps the unmapped normal.
    size = 16
    bumps = s.texture([[bumps_texel(x, y, size) for x in range(size)] for y in range(size)])
    s.quad("bumpy coat", [-0.9, 0.55, -0.95], [0.8, 0.0, 0.0], [0.0, 0.6, 0.0],
           layer_material(s, "bumpy coat", (0.6, 0.1, 0.1), CLEARCOAT, {
               "clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.05,
               "clearcoatNormalTexture": {"index": bumps, "scale": 0.7}}, 0.0, 0.5))
    bumpy_base = layer_material(s, "flat coat over bumps", (0.1, 0.3, 0.6), CLEARCOAT, {
        "clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.05}, 0.0, 0.5,
        normalTexture={"index": bumps})
    s.quad("flat coat over bumps", [0.1, 0.55, -0.95], [0.8, 0.0, 0.0], [0.0, 0.6, 0.0],
           bumpy_base)
    s.sphere("coated sphere", (0.0, 0.9, 0.2), 0.25,
             layer_material(s, "coated white", (0.8, 0.8, 0.8), CLEARCOAT,
                            {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.1}))
    s.quad("light", [-0.5, 1.6, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("clearcoat.gltf")


def sheen():
    """Sheen (KHR_materials_sheen) over dark fabric-like bases, smooth to rough, one with sheen
    colour (sRGB) and sheen roughness (alpha) textures, lit from behind and above so that the
    grazing rims show."""
    s = FeatureScene()
    grey = s.material("grey", (0.5, 0.5, 0.5), diffuse=True)
    room(s, grey, grey)
    weave = s.texture([[(255, 200, 120, 40), (120, 160, 255, 230)],
                       [(120, 160, 255, 230), (255, 200, 120, 40)]],
                      {"magFilter": 9728, "wrapS": 10497, "wrapT": 10497})
    layers = [
        ("velvet", (0.05, 0.02, 0.1), {"sheenColorFactor": [0.9, 0.4, 0.8],
                                       "sheenRoughnessFactor": 0.3}),
        ("dusty", (0.2, 0.2, 0.2), {"sheenColorFactor": [1.0, 1.0, 1.0],
                                    "sheenRoughnessFactor": 1.0}),
        ("satin", (0.1, 0.05, 0.02), {"sheenColorFactor": [1.0, 0.8, 0.5],
                                      "sheenRoughnessFactor": 0.15}),
    ]
    for i, (name, base, layer) in enumerate(layers):
        s.sphere(f"{name} sphere", (-0.8 + 0.8 * i, 0.32, -0.1), 0.32,
                 layer_material(s, name, base, SHEEN, layer, 0.0, 0.8))
    s.box("woven block", [-0.4, 0.0, 0.35], [0.4, 0.12, 0.75],
          layer_material(s, "woven", (0.1, 0.1, 0.1), SHEEN, {
              "sheenColorFactor": [1.0, 1.0, 1.0], "sheenRoughnessFactor": 1.0,
              "sheenColorTexture": {"index": weave},
              "sheenRoughnessTexture": {"index": weave}}, 0.0, 0.9))
    s.quad("light", [-0.8, 1.3, -0.9], [1.6, 0.0, 0.0], [0.0, 0.0, 0.5],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=8.0))
    s.save("sheen.gltf")


def anisotropy():
    """Brushed metal (KHR_materials_anisotropy) before a light panel on the back wall, whose
    stretched reflections cover much of the image: a floor stretched along its stored TANGENT (+X), and a
    block (generated tangents) whose direction comes from a texture (along u or along v, per
    texel) turned by anisotropyRotation."""
    s = FeatureScene()
    s.use(ANISOTROPY)
    grey = s.material("grey", (0.6, 0.6, 0.6), diffuse=True)
    brushed = s.material("brushed floor", (0.9, 0.8, 0.7), metallic=1.0, roughness=0.3,
                         extensions={ANISOTROPY: {"anisotropyStrength": 0.8}})
    s.quad("floor", [-1.5, 0.0, 1.5], [3.0, 0.0, 0.0], [0.0, 0.0, -3.0], brushed, uv_scale=3.0,
           tangent=[1.0, 0.0, 0.0, 1.0])
    s.quad("back wall", [-1.5, 0.0, -1.0], [3.0, 0.0, 0.0], [0.0, 2.0, 0.0], grey)
    # Low enough that the light panel's reflection in the floor is in view.
    s.camera([0.0, 0.35, 2.2], 50.0)
    # RG: the direction as (d + 1)/2, B: the strength. (255, 128) is +u, (128, 255) is +v.
    directions = s.texture([[(255, 128, 255, 255), (128, 255, 200, 255)],
                            [(128, 255, 200, 255), (255, 128, 255, 255)]],
                           {"magFilter": 9728, "wrapS": 10497, "wrapT": 10497})
    s.box("block", [-0.5, 0.0, -0.6], [0.5, 0.5, -0.2],
          s.material("textured anisotropy", (0.3, 0.5, 0.8), roughness=0.4, extensions={
              ANISOTROPY: {"anisotropyStrength": 1.0, "anisotropyRotation": 0.5,
                           "anisotropyTexture": {"index": directions}}}))
    s.quad("light", [-1.0, 0.8, -0.95], [2.0, 0.0, 0.0], [0.0, 0.4, 0.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("anisotropy.gltf")


def iridescence():
    """Thin films (KHR_materials_iridescence) on a dark dielectric sphere (a soap-bubble film,
    thickness from a texture) and on a metal sphere, before the room's light panel."""
    s = FeatureScene()
    s.use(IRIDESCENCE)
    grey = s.material("grey", (0.6, 0.6, 0.6), diffuse=True)
    room(s, grey, grey)
    # G: the thickness between the minimum and maximum; R: the factor.
    bands = s.texture([[(255, 0, 0, 255), (255, 128, 0, 255), (255, 255, 0, 255)]],
                      {"magFilter": 9729, "wrapS": 10497, "wrapT": 10497})
    s.sphere("bubble", (-0.45, 0.35, 0.0), 0.35, s.material(
        "film on black", (0.02, 0.02, 0.02), roughness=0.1, extensions={IRIDESCENCE: {
            "iridescenceFactor": 1.0, "iridescenceIor": 1.33,
            "iridescenceThicknessMinimum": 200.0, "iridescenceThicknessMaximum": 700.0,
            "iridescenceThicknessTexture": {"index": bands}}}))
    s.sphere("oily metal", (0.45, 0.35, 0.0), 0.35, s.material(
        "film on metal", (0.8, 0.8, 0.8), metallic=1.0, roughness=0.25, extensions={
            IRIDESCENCE: {"iridescenceFactor": 0.8, "iridescenceIor": 1.5,
                          "iridescenceThicknessMaximum": 450.0}}))
    s.quad("light", [-1.0, 0.8, -0.95], [2.0, 0.0, 0.0], [0.0, 0.4, 0.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("iridescence.gltf")


def checker(size, a, b):
    return [[a if (x + y) % 2 == 0 else b for x in range(size)] for y in range(size)]


def textured():
    """Base colour (sRGB, repeated and transformed), metallic-roughness and emissive textures,
    and an alpha-masked screen between the light and the floor."""
    s = FeatureScene()
    s.use(TEXTURE_TRANSFORM)
    colours = s.texture(checker(4, (230, 200, 40, 255), (30, 60, 160, 255)))
    floor = s.material("checker floor", (1.0, 1.0, 1.0), diffuse=True, pbr={
        "baseColorTexture": {"index": colours, "extensions": {TEXTURE_TRANSFORM: {
            "offset": [0.25, 0.0], "rotation": 0.3, "scale": [1.5, 1.5]}}}})
    # Green channel roughness, blue channel metallic: stripes of polished metal and rough paint.
    stripes = s.texture([[(0, 30, 255, 255), (0, 230, 0, 255)]] * 2,
                        {"magFilter": 9728, "wrapS": 10497, "wrapT": 33071})
    wall = s.material("striped wall", (0.8, 0.8, 0.8), metallic=1.0, roughness=1.0,
                      pbr={"metallicRoughnessTexture": {"index": stripes}})
    room(s, floor, wall)
    glow = s.texture(checker(2, (255, 255, 255, 255), (255, 80, 20, 255)))
    s.quad("light", [-0.6, 1.5, -0.6], [1.2, 0.0, 0.0], [0.0, 0.0, 1.2],
           s.material("textured light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=5.0, emissiveTexture={"index": glow}))
    holes = [[(255, 255, 255, 255 if (x // 2 + y // 2) % 2 else 0) for x in range(8)]
             for y in range(8)]
    screen = s.material("masked screen", (0.9, 0.9, 0.9), diffuse=True, double_sided=True,
                        alphaMode="MASK", alphaCutoff=0.5,
                        pbr={"baseColorTexture": {"index": s.texture(holes)}})
    s.quad("masked screen", [-0.7, 0.9, 0.7], [1.4, 0.0, 0.0], [0.0, 0.0, -1.4], screen)
    s.save("textured.gltf")


def bumps_texel(x, y, size):
    """A tangent-space normal map of a grid of round bumps: the normal of the height field
    h = sin(2πx/size·2)·sin(2πy/size·2), stored as (n + 1)/2 in RGB."""
    k = 2.0 * math.pi * 2.0 / size
    u, v = (x + 0.5), (y + 0.5)
    dx = 0.6 * math.cos(k * u) * math.sin(k * v)
    dy = 0.6 * math.sin(k * u) * math.cos(k * v)
    # +Y of a glTF normal texture points up the image (towards smaller v, smaller y).
    n = [-dx, dy, 1.0]
    length = math.sqrt(sum(c * c for c in n))
    return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n) + (255,)


def normal_map():
    """Normal textures: a bumpy white floor (Lambertian, tangents generated), a bumpy glossy
    back wall (GGX, scale 2), and a bumpy metal panel whose tangents come from the file (a
    TANGENT attribute) on a mirrored node, under a quad light."""
    s = FeatureScene()
    size = 16
    bumps = s.texture([[bumps_texel(x, y, size) for x in range(size)] for y in range(size)])
    floor = s.material("bumpy floor", (0.8, 0.8, 0.8), diffuse=True,
                       normalTexture={"index": bumps})
    wall = s.material("bumpy glossy wall", (0.3, 0.5, 0.8), roughness=0.3,
                      normalTexture={"index": bumps, "scale": 2.0})
    room(s, floor, wall)
    panel = s.material("bumpy metal panel", (0.9, 0.7, 0.4), metallic=1.0, roughness=0.4,
                       normalTexture={"index": bumps})
    # Mirrored in x by its node: the loader must flip the stored handedness.
    s.quad("panel", [0.2, 0.05, -0.6], [0.9, 0.0, 0.0], [0.0, 0.8, 0.0], panel,
           tangent=(1.0, 0.0, 0.0, 1.0), scale=[-1.0, 1.0, 1.0])
    s.quad("light", [-0.5, 1.6, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("normal_map.gltf")


def orthographic():
    """The room with blocks, seen by an orthographic camera from above at 35° below the
    horizontal: parallel edges stay parallel in the image."""
    s = FeatureScene()
    white = s.material("white", (0.8, 0.8, 0.8), diffuse=True)
    s.quad("floor", [-1.5, 0.0, 1.5], [3.0, 0.0, 0.0], [0.0, 0.0, -3.0], white)
    s.quad("back wall", [-1.5, 0.0, -1.0], [3.0, 0.0, 0.0], [0.0, 2.0, 0.0], white)
    s.box("block", [-0.9, 0.0, -0.4], [-0.3, 0.6, 0.2], white)
    s.box("glossy block", [0.3, 0.0, -0.5], [0.8, 0.4, 0.0],
          s.material("glossy", (0.2, 0.7, 0.3), roughness=0.3))
    s.quad("light", [-0.5, 1.6, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.orthographic_camera([0.0, 1.6, 1.7], -35.0, 1.4, 1.2)
    s.save("orthographic.gltf")


def punctual():
    """A point, a spot and a directional light (KHR_lights_punctual) on a floor and blocks."""
    s = FeatureScene()
    white = s.material("white", (0.8, 0.8, 0.8), diffuse=True)
    room(s, white, white)
    s.box("block", [-0.9, 0.0, -0.4], [-0.4, 0.6, 0.1], white)
    s.box("glossy block", [0.3, 0.0, -0.5], [0.8, 0.4, 0.0],
          s.material("glossy", (0.2, 0.7, 0.3), roughness=0.3))
    s.light("point", {"type": "point", "color": [1.0, 0.8, 0.6], "intensity": 2.0,
                      "range": 4.0}, translation=[-0.3, 1.2, 0.6])
    s.light("spot", {"type": "spot", "color": [0.5, 0.7, 1.0], "intensity": 6.0,
                     "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.45}},
            translation=[0.6, 1.6, 0.2], rotation=quat_about_x(-90.0))
    s.light("sun", {"type": "directional", "color": [1.0, 1.0, 0.9], "intensity": 0.8},
            rotation=quat_about_x(-60.0))
    s.save("punctual.gltf")


def environment_room():
    """No emitters: a floor and spheres lit by the environment alone (--env-color, --env)."""
    s = FeatureScene()
    white = s.material("white", (0.7, 0.7, 0.7), diffuse=True)
    s.quad("floor", [-1.5, 0.0, 1.5], [3.0, 0.0, 0.0], [0.0, 0.0, -3.0], white)
    s.sphere("diffuse sphere", (-0.45, 0.4, 0.0), 0.4, white)
    s.sphere("metal sphere", (0.45, 0.4, 0.0), 0.4,
             s.material("chrome", (0.95, 0.95, 0.95), metallic=1.0, roughness=0.2))
    s.camera([0.0, 0.6, 2.2], 50.0)
    s.save("environment.gltf")


def metal_rough_spheres():
    """As Khronos' MetalRoughSpheres: spheres from dielectric to metal (rows) and smooth to rough
    (columns), with no emitter and no camera, so that vkpt frames the bounds and lights the
    scene with its default studio (scenes/test/, not features/: it has no light of its own)."""
    s = FeatureScene()
    for row, metallic in enumerate([0.0, 1.0]):
        for column, roughness in enumerate([0.05, 0.35, 0.7, 1.0]):
            s.sphere(f"sphere metallic {metallic} roughness {roughness}",
                     (-1.2 + 0.8 * column, 0.4 - 0.8 * row, 0.0), 0.35,
                     s.material(f"metallic {metallic} roughness {roughness}", (0.9, 0.6, 0.3),
                                metallic=metallic, roughness=roughness))
    s.save("../metal-rough-spheres.gltf")


def glass_room():
    """Glass in a room under a quad light: a smooth solid ball (ior 1.5), a rough one, a tinted
    thin-walled pane, and an absorbing block (a volume of ior 1.33)."""
    s = FeatureScene()
    white = s.material("white", (0.75, 0.75, 0.75), diffuse=True)
    room(s, s.material("floor", (0.6, 0.55, 0.5), diffuse=True), white)
    s.sphere("smooth glass ball", (-0.7, 0.3, 0.1), 0.3,
             s.glass("smooth glass", thickness=0.6))
    s.sphere("rough glass ball", (0.05, 0.3, -0.1), 0.3,
             s.glass("rough glass", roughness=0.3, thickness=0.6))
    # Lifted off the floor: a face coplanar with the floor would leave the nearer of two
    # equal hits to traversal order.
    s.box("absorbing block", [0.45, 0.02, -0.3], [0.95, 0.47, 0.2],
          s.glass("absorbing water", ior=1.33, thickness=0.5, attenuation_color=(0.3, 0.6, 0.9),
                  attenuation_distance=0.3))
    s.quad("thin pane", [-0.9, 0.0, 0.6], [0.8, 0.0, 0.0], [0.0, 0.7, 0.0],
           s.glass("thin tinted pane", base=(0.7, 0.9, 0.8), roughness=0.2, thickness=0.0))
    s.quad("light", [-0.5, 1.6, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=6.0))
    s.save("glass.gltf")


def glass_ball():
    """A smooth, lossless glass ball (ior 1.5) alone: in a uniform environment every pixel
    sees exactly the environment's radiance (tests/image/glass_render_test.cpp)."""
    s = FeatureScene()
    s.sphere("glass ball", (0.0, 0.0, 0.0), 1.0, s.glass("clear glass", thickness=2.0))
    s.camera([0.0, 0.0, 3.0], 45.0)
    s.save("glass-ball.gltf")


def absorbing_slab():
    """A clear slab (ior 1: no refraction, no reflection) of thickness 0.5 across the whole
    view whose medium keeps (0.8, 0.5, 0.2) of the light over 0.25: Beer–Lambert in a uniform
    environment, e^(−σ·0.5/cos θ) (tests/image/glass_render_test.cpp)."""
    s = FeatureScene()
    s.box("slab", [-1.0, -1.0, -0.5], [1.0, 1.0, 0.0],
          s.glass("absorbing slab", ior=1.0, thickness=0.5, attenuation_color=(0.8, 0.5, 0.2),
                  attenuation_distance=0.25))
    s.camera([0.0, 0.0, 1.0], 30.0)
    s.save("absorbing-slab.gltf")


def radiance_hdr(width, height, texel):
    """A Radiance .hdr (flat, not run-length encoded) of texel(x, y) → (r, g, b)."""
    def rgbe(r, g, b):
        m = max(r, g, b)
        if m < 1e-32:
            return bytes(4)
        mantissa, exponent = math.frexp(m)
        scale = mantissa * 256.0 / m
        return bytes([int(r * scale), int(g * scale), int(b * scale), exponent + 128])

    header = (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" +
              f"-Y {height} +X {width}\n".encode("ascii"))
    body = b"".join(rgbe(*texel(x, y)) for y in range(height) for x in range(width))
    return header + body


def sky_texel(x, y, width=32, height=16):
    """A blue sky brightening to the horizon, a dark ground, and a small warm sun."""
    v = (y + 0.5) / height
    if 13 <= x <= 14 and 4 <= y <= 5:
        return (40.0, 36.0, 30.0)
    if v < 0.5:
        return (0.3 + 0.5 * v, 0.5 + 0.6 * v, 1.0)
    return (0.15, 0.13, 0.1)


def main():
    spheres()
    ggx()
    textured()
    punctual()
    environment_room()
    metal_rough_spheres()
    normal_map()
    orthographic()
    glass_room()
    glass_ball()
    absorbing_slab()
    clearcoat()
    sheen()
    anisotropy()
    iridescence()
    write(FEATURES_DIR / "sky.hdr", radiance_hdr(32, 16, sky_texel))


if __name__ == "__main__":
    main()
