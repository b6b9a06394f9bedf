#!/usr/bin/env python3
"""generate_lobe_scenes.py — writes the test scenes of the lobes that only some scenes compile
(scenes/test/lobes/): KHR_materials_diffuse_transmission (a leaf lit from behind) and
KHR_materials_dispersion (a prism before a narrow light). They live outside
scenes/test/features so that the feature sweeps, which compile every scene's own pipelines, do
not grow; tests/image/lobe_render_test.cpp renders them.

Run from anywhere:  python3 scenes/generate_lobe_scenes.py

Standard library only; deterministic output. scenes/README.md describes the scenes.
"""

import math
from pathlib import Path

from generate_feature_scenes import FeatureScene, room
from generate_loader_scenes import primitive, write_embedded

LOBES_DIR = Path(__file__).resolve().parent / "test" / "lobes"
DIFFUSE_TRANSMISSION = "KHR_materials_diffuse_transmission"
DISPERSION = "KHR_materials_dispersion"
UNSIGNED_SHORT = 5123


def save(scene, name):
    """FeatureScene.save, into scenes/test/lobes."""
    if scene.extensions:
        scene.doc["extensionsUsed"] = sorted(scene.extensions)
    scene.scene(scene.roots)
    write_embedded(LOBES_DIR / name, scene)


def leaf():
    """A thin leaf (a quad, KHR_materials_diffuse_transmission 0.6 with a vein pattern in the
    factor texture's A, a yellow-green transmitted colour) seen from the front, lit only by a
    light panel behind it that faces the camera and that the leaf hides: what the camera sees of
    the leaf is the light it transmits, plus what the floor and wall send back."""
    s = FeatureScene()
    s.use(DIFFUSE_TRANSMISSION)
    grey = s.material("grey", (0.6, 0.6, 0.6), diffuse=True)
    room(s, grey, grey)
    # A: the factor (veins transmit less); RGB unused by the factor texture.
    veins = s.texture([[(255, 255, 255, 255 if (x + y) % 3 else 96) for x in range(4)]
                       for y in range(4)],
                      {"magFilter": 9728, "wrapS": 10497, "wrapT": 10497})
    leaf_material = s.material(
        "leaf", (0.15, 0.4, 0.08), roughness=0.6, double_sided=True, extensions={
            DIFFUSE_TRANSMISSION: {"diffuseTransmissionFactor": 0.6,
                                   "diffuseTransmissionTexture": {"index": veins},
                                   "diffuseTransmissionColorFactor": [0.7, 0.95, 0.3]}})
    s.quad("leaf", [-0.5, 0.1, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], leaf_material)
    s.quad("light behind", [-0.3, 0.3, -0.5], [0.6, 0.0, 0.0], [0.0, 0.6, 0.0],
           s.material("light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=8.0))
    save(s, "leaf.gltf")


def prism(scene, name, material, x0, x1, apex_y, base_y, half_depth):
    """A triangular prism along X: apex edge at y = apex_y, z = 0; base edges at y = base_y,
    z = ±half_depth; flat faces turned so that their front (counter-clockwise) side faces out."""
    a = (0.0, apex_y, 0.0)
    b = (0.0, base_y, half_depth)
    c = (0.0, base_y, -half_depth)

    def at(x, p):
        return [x, p[1], p[2]]

    faces = [
        [at(x0, a), at(x0, c), at(x0, b)],             # cap at x0
        [at(x1, a), at(x1, b), at(x1, c)],             # cap at x1
        [at(x0, a), at(x0, b), at(x1, b), at(x1, a)],  # front slope
        [at(x0, c), at(x0, a), at(x1, a), at(x1, c)],  # back slope
        [at(x0, b), at(x0, c), at(x1, c), at(x1, b)],  # base
    ]
    centre = [(x0 + x1) / 2.0, (apex_y + 2.0 * base_y) / 3.0, 0.0]
    positions, normals, indices = [], [], []
    for face in faces:
        u = [face[1][i] - face[0][i] for i in range(3)]
        v = [face[2][i] - face[0][i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        if sum(n[i] * (face[0][i] - centre[i]) for i in range(3)) < 0.0:
            face = face[::-1]
        u = [face[1][i] - face[0][i] for i in range(3)]
        v = [face[2][i] - face[0][i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        length = math.sqrt(sum(x * x for x in n))
        n = [x / length for x in n]
        first = len(positions)
        positions += face
        normals += [n] * len(face)
        for k in range(1, len(face) - 1):
            indices += [first, first + k, first + k + 1]
    prim = primitive(scene.positions(positions), scene.normals(normals),
                     scene.indices(indices, UNSIGNED_SHORT), material)
    scene.roots.append(scene.node(name=name, mesh=scene.mesh([prim], name)))


def dispersive_prism():
    """A smooth glass prism, apex down (ior 1.5, KHR_materials_dispersion 4: Abbe number 5,
    four times a dense flint's spread, so that the spectrum spans several pixels of a test's
    small image), and a narrow bright strip on the back wall above it: the camera sees the strip
    directly, and again through the prism, which bends its rays up by an angle that depends on
    the wavelength, so that there the strip spreads into a spectrum."""
    s = FeatureScene()
    s.use(DISPERSION)
    grey = s.material("grey", (0.3, 0.3, 0.3), diffuse=True)
    room(s, grey, grey)
    glass = s.glass("flint", thickness=0.5)
    s.doc["materials"][glass]["extensions"][DISPERSION] = {"dispersion": 4.0}
    prism(s, "prism", glass, -0.6, 0.6, 0.35, 0.85, 0.25)
    s.quad("strip", [-1.2, 1.15, -0.95], [2.4, 0.0, 0.0], [0.0, 0.08, 0.0],
           s.material("strip light", (0.0, 0.0, 0.0), diffuse=True, emission=(1.0, 1.0, 1.0),
                      strength=40.0))
    save(s, "prism.gltf")


def main():
    leaf()
    dispersive_prism()


if __name__ == "__main__":
    main()
