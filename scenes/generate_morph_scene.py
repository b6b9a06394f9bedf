#!/usr/bin/env python3
"""generate_morph_scene.py — writes scenes/test/morph-grow.gltf: a still floor and a quad that an
animation of its morph weight raises far above where it rests, for the rest extent's test
(tests/unit/frame_reuse_test.cpp: the origin and the default framing hold every shape a morph
animation gives).

The quad lies flat at y = 0 over [-0.5, 0.5]² with a weight of 0 at rest; its one morph target
lifts its two far corners by y = 1. "grow" moves the weight from 0 to 3 at 0.5 s and back to 1 at
1 s (LINEAR), so that the corners reach y = 3 at 0.5 s, outside the extent of the rest pose. The
floor, a larger quad at y = -1 that never moves, is the still geometry. Python 3 standard library
only, deterministic.

    python3 scenes/generate_morph_scene.py
"""

from pathlib import Path

from generate_loader_scenes import Gltf, add_animation, primitive, write_embedded


def quad(half, y):
    positions = [(-half, y, -half), (half, y, -half), (-half, y, half), (half, y, half)]
    return positions, [0, 2, 1, 1, 2, 3]


def morph_grow():
    gltf = Gltf()
    positions, indices = quad(0.5, 0.0)
    prim = primitive(gltf.positions(positions), gltf.normals([(0, 1, 0)] * 4),
                     gltf.indices(indices))
    # The far corners (z = -0.5) rise; a target's POSITION holds displacements, with min and max.
    prim["targets"] = [{"POSITION": gltf.positions([(0, 1, 0), (0, 1, 0), (0, 0, 0), (0, 0, 0)])}]
    grow = gltf.mesh([prim], name="growing quad")
    positions, indices = quad(2.0, -1.0)
    floor = gltf.mesh([primitive(gltf.positions(positions), gltf.normals([(0, 1, 0)] * 4),
                                 gltf.indices(indices))], name="floor")
    grown = gltf.node(name="grown", mesh=grow)
    add_animation(gltf, "grow", [(grown, "weights", "LINEAR", [0, 0.5, 1], [0, 3, 1])])
    gltf.scene([gltf.node(name="floor", mesh=floor), grown])
    return gltf


def main():
    write_embedded(Path(__file__).resolve().parent / "test" / "morph-grow.gltf", morph_grow())


if __name__ == "__main__":
    main()
