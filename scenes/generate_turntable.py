#!/usr/bin/env python3
"""generate_turntable.py — writes scenes/turntable.gltf, the README's turntable example.

A grey floor, a red box and a white sphere; a camera on a pivot node that an animation turns
once about +Y in 4 seconds (LINEAR rotation keys every 90 degrees, so that slerp turns at a
constant rate). No light: the default studio environment lights it. Render every frame of the
turn at 24 frames per second with

    vkpt --frames 0:95 --fps 24 --spp 64 --res 320 180 -o turntable.####.png scenes/turntable.gltf

Python 3 standard library only, deterministic; the output is committed.
"""

import math
from pathlib import Path

from generate_loader_scenes import (FLOAT, QUAD_INDICES, Gltf, floats, json_text, primitive,
                                    write)

ROOT = Path(__file__).resolve().parent
TURN_SECONDS = 4.0


def cube_faces():
    """24 corners (4 per face, counter-clockwise from outside), their normals, 36 indices."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (1, -1):
            normal = [0, 0, 0]
            normal[axis] = sign
            u, v = [0, 0, 0], [0, 0, 0]
            u[(axis + 1) % 3] = 1
            v[(axis + 2) % 3] = sign
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                positions.append(tuple(0.5 * (normal[i] + a * u[i] + b * v[i]) for i in range(3)))
                normals.append(tuple(normal))
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def turntable():
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_implicit_shapes"]
    gltf.doc["extensions"] = {"KHR_implicit_shapes": {
        "shapes": [{"type": "sphere", "sphere": {"radius": 0.5}}]}}
    gltf.doc["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1],
                                                   "metallicFactor": 0}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.05, 1],
                                                 "metallicFactor": 0, "roughnessFactor": 0.4}},
        {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 0.2}},
    ]
    floor_positions = [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)]
    floor = gltf.mesh([primitive(gltf.positions(floor_positions), gltf.normals([(0, 1, 0)] * 4),
                                 gltf.indices(QUAD_INDICES), material=0)], name="floor")
    positions, normals, indices = cube_faces()
    cube = gltf.mesh([primitive(gltf.positions(positions), gltf.normals(normals),
                                gltf.indices(indices), material=1)], name="box")
    gltf.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.05}}]
    tilt = math.radians(-12) / 2
    camera = gltf.node(name="camera", camera=0, translation=[0, 1.3, 5],
                       rotation=[math.sin(tilt), 0, 0, math.cos(tilt)])
    pivot = gltf.node(name="pivot", children=[camera])
    times = [TURN_SECONDS * k / 4 for k in range(5)]
    keys = []
    for k in range(5):
        half = math.pi * k / 4  # a quarter turn per key: half-angle π/4 per key
        keys += [0, math.sin(half), 0, math.cos(half)]
    input_ = gltf.accessor(gltf.view(floats(times)), FLOAT, 5, "SCALAR", min=[0],
                           max=[TURN_SECONDS])
    output = gltf.accessor(gltf.view(floats(keys)), FLOAT, 5, "VEC4")
    gltf.doc["animations"] = [{"name": "turn",
                               "channels": [{"sampler": 0,
                                             "target": {"node": pivot, "path": "rotation"}}],
                               "samplers": [{"input": input_, "output": output,
                                             "interpolation": "LINEAR"}]}]
    nodes = [gltf.node(name="floor", mesh=floor),
             gltf.node(name="box", mesh=cube, translation=[-0.7, 0.5, 0], rotation=[0, 0.38, 0, 0.92]),
             gltf.node(name="ball", translation=[0.8, 0.5, 0.3],
                       extensions={"KHR_implicit_shapes": {"shape": 0}}, extras={"vkpt_material": 2}),
             pivot]
    gltf.scene(nodes)
    gltf.embed_buffer()
    return gltf


def main():
    write(ROOT / "turntable.gltf", json_text(turntable().doc))


if __name__ == "__main__":
    main()
