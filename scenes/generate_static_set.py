#!/usr/bin/env python3
"""generate_static_set.py — writes a benchmark scene: a large static set and a small thing moving
in it, for measuring what an animation's frame costs beyond its samples (docs/benchmarks.md,
"Animation frames").

A rippled terrain of 2 × N × N triangles (N = 512 by default: 524,288 triangles) that never
moves, and a red box that an animation turns once about +Y in 4 s and lifts by half its size,
seen by a fixed camera. No light: the default studio environment lights it. Usage:

    python3 scenes/generate_static_set.py OUT.gltf [N]

writes OUT.gltf and OUT.bin (about 12 MiB at N = 512), not committed: generate it where it is
needed. With no argument it writes the small one the tests render, scenes/test/moving-box.gltf
(N = 6, its buffer embedded). Python 3 standard library only, deterministic.
"""

import math
import sys
from pathlib import Path

from generate_loader_scenes import (FLOAT, UNSIGNED_INT, Gltf, floats, primitive,
                                    write_embedded, write_external)
from generate_turntable import cube_faces

TURN_SECONDS = 4.0


def terrain(gltf, n):
    """An (n + 1)² grid over [-10, 10]² with gentle ripples, so that its BVH is not a flat one."""
    positions, normals, indices = [], [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = -10 + 20 * i / n, -10 + 20 * j / n
            y = 0.15 * math.sin(1.3 * x) * math.cos(0.9 * z)
            dx = 0.15 * 1.3 * math.cos(1.3 * x) * math.cos(0.9 * z)
            dz = -0.15 * 0.9 * math.sin(1.3 * x) * math.sin(0.9 * z)
            length = math.sqrt(dx * dx + 1 + dz * dz)
            positions.append((x, y, z))
            normals.append((-dx / length, 1 / length, -dz / length))
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            indices += [a, c, b, b, c, d]
    return gltf.mesh([primitive(gltf.positions(positions), gltf.normals(normals),
                                gltf.indices(indices, UNSIGNED_INT), material=0)], name="terrain")


def static_set(n):
    gltf = Gltf()
    gltf.doc["materials"] = [
        {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.45, 1],
                                                    "metallicFactor": 0}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.05, 1],
                                                 "metallicFactor": 0, "roughnessFactor": 0.4}},
    ]
    ground = terrain(gltf, n)
    positions, normals, indices = cube_faces()
    cube = gltf.mesh([primitive(gltf.positions(positions), gltf.normals(normals),
                                gltf.indices(indices), material=1)], name="box")
    gltf.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.05}}]
    tilt = math.radians(-20) / 2
    camera = gltf.node(name="camera", camera=0, translation=[0, 2.0, 5],
                       rotation=[math.sin(tilt), 0, 0, math.cos(tilt)])
    box = gltf.node(name="box", mesh=cube, translation=[0, 0.6, 0])
    times = [TURN_SECONDS * k / 4 for k in range(5)]
    rotations, translations = [], []
    for k in range(5):
        half = math.pi * k / 4
        rotations += [0, math.sin(half), 0, math.cos(half)]
        translations += [0, 0.6 + 0.25 * math.sin(math.pi * k / 2), 0]
    input_ = gltf.accessor(gltf.view(floats(times)), FLOAT, 5, "SCALAR", min=[0],
                           max=[TURN_SECONDS])
    turn = gltf.accessor(gltf.view(floats(rotations)), FLOAT, 5, "VEC4")
    lift = gltf.accessor(gltf.view(floats(translations)), FLOAT, 5, "VEC3")
    gltf.doc["animations"] = [{
        "name": "turn and lift",
        "channels": [{"sampler": 0, "target": {"node": box, "path": "rotation"}},
                     {"sampler": 1, "target": {"node": box, "path": "translation"}}],
        "samplers": [{"input": input_, "output": turn, "interpolation": "LINEAR"},
                     {"input": input_, "output": lift, "interpolation": "LINEAR"}]}]
    gltf.scene([gltf.node(name="terrain", mesh=ground), box, camera])
    return gltf


def main():
    if len(sys.argv) == 1:
        write_embedded(Path(__file__).resolve().parent / "test" / "moving-box.gltf", static_set(6))
        return
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: generate_static_set.py [OUT.gltf [N]]")
    n = int(sys.argv[2]) if len(sys.argv) == 3 else 512
    write_external(Path(sys.argv[1]), static_set(n))


if __name__ == "__main__":
    main()
