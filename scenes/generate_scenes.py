#!/usr/bin/env python3
"""generate_scenes.py — writes vkpt's generated glTF scenes (scenes/*.gltf, scenes/test/*.gltf)
and then re-reads every file it wrote and checks it.

Run from anywhere (paths are relative to this file):  python3 scenes/generate_scenes.py

Standard library only. The output is deterministic: running the script twice writes the same
bytes. Every file is glTF 2.0 JSON with its binary data embedded as a base64 data URI; units
are metres. The conventions are DESIGN.md's ("Conventions every image depends on"): emission
leaves the front face only (counter-clockwise vertices) unless the material is doubleSided,
surfaces reflect on both sides with albedo = baseColorFactor, and emitted radiance =
emissiveFactor x KHR_materials_emissive_strength. scenes/README.md describes every scene and
the images expected from it.
"""

import base64
import json
import math
import struct
import sys
from pathlib import Path

SCENES_DIR = Path(__file__).resolve().parent
GENERATOR = "vkpt scenes/generate_scenes.py"
EMISSIVE_STRENGTH = "KHR_materials_emissive_strength"
# specularFactor 0 removes the glTF dielectric's specular layer: what remains is exactly the
# Lambertian base, the "diffuse" material kind that the analytic tests rely on.
SPECULAR = "KHR_materials_specular"
DATA_URI_PREFIX = "data:application/octet-stream;base64,"

# glTF enums used here.
FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
TRIANGLES = 4


# ---------------------------------------------------------------------------------------------
# Numbers and vectors
# ---------------------------------------------------------------------------------------------

def f32(x):
    """x rounded to the nearest float32, as the renderer will see it."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32_json(x):
    """The shortest decimal that reads back as the float32 nearest x.

    Accessor min/max must equal the stored float32 data; writing e.g. 0.5528 rather than the
    float32's exact 0.552799999713897705078125 keeps the file readable and still round-trips.
    """
    target = f32(x)
    for digits in range(1, 18):
        candidate = float(f"{target:.{digits}g}")
        if f32(candidate) == target:
            return candidate
    return target


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    return scale(a, 1.0 / length(a))


def centroid(points):
    n = len(points)
    return tuple(sum(p[i] for p in points) / n for i in range(3))


def face_normal(p0, p1, p2):
    """Unnormalised; points to the front side, from which p0, p1, p2 run counter-clockwise."""
    return cross(sub(p1, p0), sub(p2, p0))


def polygon_normal(corners):
    """Newell's normal of a (possibly slightly non-planar) polygon, unit length."""
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(corners):
        q = corners[(i + 1) % len(corners)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return normalize(tuple(n))


# ---------------------------------------------------------------------------------------------
# Rotations and node transforms (4x4 matrices as row-major nested lists)
# ---------------------------------------------------------------------------------------------

def quat_axis_angle(axis, degrees):
    """glTF quaternion [x, y, z, w] for a rotation by `degrees` about `axis`."""
    half = math.radians(degrees) / 2.0
    s = math.sin(half)
    a = normalize(axis)
    return [a[0] * s, a[1] * s, a[2] * s, math.cos(half)]


def quat_from_basis(right, up, back):
    """Quaternion of the rotation whose matrix has columns right, up, back (orthonormal)."""
    m = [[right[i], up[i], back[i]] for i in range(3)]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0.0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2])
        q = [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    elif m[1][1] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2])
        q = [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1])
        q = [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def look_at_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Node rotation that makes a glTF camera (looking down its local -Z, +Y up) at `eye` look
    at `target`."""
    back = normalize(sub(eye, target))
    right = normalize(cross(up, back))
    true_up = cross(back, right)
    return quat_from_basis(right, true_up, back)


def matrix_identity():
    return [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]


def matrix_multiply(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def matrix_from_trs(translation, rotation, scale_xyz):
    """M = T * R * S, the order glTF prescribes."""
    x, y, z, w = rotation
    r = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    m = matrix_identity()
    for row in range(3):
        for col in range(3):
            m[row][col] = r[row][col] * scale_xyz[col]
        m[row][3] = translation[row]
    return m


def matrix_from_gltf(column_major):
    return [[column_major[c * 4 + r] for c in range(4)] for r in range(4)]


def matrix_to_gltf(m):
    return [m[r][c] for c in range(4) for r in range(4)]


def transform_point(m, p):
    return tuple(m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3] for r in range(3))


def transform_direction(m, d):
    return tuple(m[r][0] * d[0] + m[r][1] * d[1] + m[r][2] * d[2] for r in range(3))


def node_local_matrix(node):
    if "matrix" in node:
        return matrix_from_gltf(node["matrix"])
    return matrix_from_trs(node.get("translation", [0.0, 0.0, 0.0]),
                           node.get("rotation", [0.0, 0.0, 0.0, 1.0]),
                           node.get("scale", [1.0, 1.0, 1.0]))


# ---------------------------------------------------------------------------------------------
# Geometry: a triangle mesh with one position and one normal per vertex
# ---------------------------------------------------------------------------------------------

class MeshBuilder:
    """Positions, normals and triangle indices. Every triangle runs counter-clockwise seen from
    its front side, and its vertex normals point to that side."""

    def __init__(self):
        self.positions = []
        self.normals = []
        self.indices = []

    def add_vertex(self, position, normal):
        self.positions.append(tuple(position))
        self.normals.append(tuple(normal))
        return len(self.positions) - 1

    def add_triangle(self, p0, p1, p2):
        """A triangle with its own three vertices and its flat normal."""
        n = normalize(face_normal(p0, p1, p2))
        self.indices += [self.add_vertex(p, n) for p in (p0, p1, p2)]

    def add_polygon(self, corners):
        """A convex polygon, fanned from its first corner; corners share one (Newell) normal."""
        n = polygon_normal(corners)
        first = [self.add_vertex(p, n) for p in corners]
        for i in range(1, len(first) - 1):
            self.indices += [first[0], first[i], first[i + 1]]

    def add_centre_fan(self, corners):
        """A convex polygon fanned around its centroid. Unlike a diagonal split, this is
        mirror-symmetric whenever the polygon is, which the symmetric box needs."""
        n = polygon_normal(corners)
        centre = self.add_vertex(centroid(corners), n)
        ring = [self.add_vertex(p, n) for p in corners]
        for i in range(len(ring)):
            self.indices += [centre, ring[i], ring[(i + 1) % len(ring)]]


def facing(corners, toward):
    """The corners, reversed if needed so that the polygon's front side faces `toward`."""
    if dot(polygon_normal(corners), toward) < 0.0:
        return list(reversed(corners))
    return list(corners)


def rectangle(centre, half_u, half_v):
    """Four corners centre ± half_u ± half_v, counter-clockwise seen from half_u x half_v."""
    c = centre
    return [sub(sub(c, half_u), half_v), sub(add(c, half_u), half_v),
            add(add(c, half_u), half_v), add(sub(c, half_u), half_v)]


def unit_cube():
    """The cube -0.5..0.5 with all six faces outward, 24 vertices, 12 triangles."""
    mesh = MeshBuilder()
    for axis in range(3):
        for sign in (-1.0, 1.0):
            normal = [0.0, 0.0, 0.0]
            normal[axis] = sign
            u = [0.0, 0.0, 0.0]
            v = [0.0, 0.0, 0.0]
            u[(axis + 1) % 3] = 0.5
            v[(axis + 2) % 3] = 0.5
            corners = rectangle(scale(tuple(normal), 0.5), tuple(u), tuple(v))
            mesh.add_polygon(facing(corners, tuple(normal)))
    return mesh


def icosphere(subdivisions):
    """Unit icosphere: the icosahedron with each triangle split into four, `subdivisions` times,
    and new vertices pushed onto the sphere. Returns (vertices, outward CCW triangles)."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    vertices = [normalize(v) for v in [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
        (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
        (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                vertices.append(normalize(scale(add(vertices[a], vertices[b]), 0.5)))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        refined = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    return vertices, faces


def sphere_mesh(subdivisions, inward):
    """Icosphere of radius 1 with smooth normals; front faces inward or outward."""
    vertices, faces = icosphere(subdivisions)
    mesh = MeshBuilder()
    for v in vertices:
        mesh.add_vertex(v, scale(v, -1.0) if inward else v)
    for a, b, c in faces:
        mesh.indices += [a, c, b] if inward else [a, b, c]
    return mesh


# ---------------------------------------------------------------------------------------------
# glTF document
# ---------------------------------------------------------------------------------------------

def emission(radiance):
    """(emissiveFactor, strength or None) for a grey radiance. emissiveFactor must stay <= 1,
    so anything brighter goes through KHR_materials_emissive_strength."""
    if radiance <= 1.0:
        return [radiance] * 3, None
    return [1.0, 1.0, 1.0], radiance


class GltfDocument:
    def __init__(self, extras=None):
        self.binary = bytearray()
        self.buffer_views = []
        self.accessors = []
        self.materials = []
        self.meshes = []
        self.cameras = []
        self.nodes = []
        self.extensions_used = set()
        self.extras = extras

    # -- binary data ---------------------------------------------------------------------------

    def _add_view(self, data, target):
        while len(self.binary) % 4:  # every accessor's component size divides 4
            self.binary.append(0)
        self.buffer_views.append({"buffer": 0, "byteOffset": len(self.binary),
                                  "byteLength": len(data), "target": target})
        self.binary += data
        return len(self.buffer_views) - 1

    def _add_vec3_accessor(self, values, with_bounds):
        stored = [tuple(f32(c) for c in v) for v in values]
        data = b"".join(struct.pack("<3f", *v) for v in stored)
        accessor = {"bufferView": self._add_view(data, ARRAY_BUFFER), "componentType": FLOAT,
                    "count": len(stored), "type": "VEC3"}
        if with_bounds:
            accessor["min"] = [f32_json(min(v[i] for v in stored)) for i in range(3)]
            accessor["max"] = [f32_json(max(v[i] for v in stored)) for i in range(3)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def _add_index_accessor(self, indices, vertex_count):
        # UNSIGNED_SHORT where it fits (65535 is reserved as a restart value, so stay below).
        if vertex_count < 65535:
            component, fmt = UNSIGNED_SHORT, "<%dH"
        else:
            component, fmt = UNSIGNED_INT, "<%dI"
        data = struct.pack(fmt % len(indices), *indices)
        self.accessors.append({"bufferView": self._add_view(data, ELEMENT_ARRAY_BUFFER),
                               "componentType": component, "count": len(indices),
                               "type": "SCALAR"})
        return len(self.accessors) - 1

    # -- scene objects -------------------------------------------------------------------------

    def add_material(self, name, albedo, emissive_factor=None, emissive_strength=None,
                     double_sided=False):
        material = {"name": name,
                    "pbrMetallicRoughness": {"baseColorFactor": list(albedo) + [1.0],
                                             "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if emissive_factor is not None:
            material["emissiveFactor"] = list(emissive_factor)
        material["extensions"] = {SPECULAR: {"specularFactor": 0.0}}
        self.extensions_used.add(SPECULAR)
        if emissive_strength is not None:
            material["extensions"][EMISSIVE_STRENGTH] = {"emissiveStrength": emissive_strength}
            self.extensions_used.add(EMISSIVE_STRENGTH)
        if double_sided:
            material["doubleSided"] = True
        self.materials.append(material)
        return len(self.materials) - 1

    def add_emitter(self, name, radiance, albedo=(0.0, 0.0, 0.0), double_sided=False):
        factor, strength = emission(radiance)
        return self.add_material(name, albedo, factor, strength, double_sided)

    def add_mesh(self, name, mesh, material):
        primitive = {
            "attributes": {"POSITION": self._add_vec3_accessor(mesh.positions, True),
                           "NORMAL": self._add_vec3_accessor(mesh.normals, False)},
            "indices": self._add_index_accessor(mesh.indices, len(mesh.positions)),
            "material": material,
            "mode": TRIANGLES,
        }
        self.meshes.append({"name": name, "primitives": [primitive]})
        return len(self.meshes) - 1

    def add_camera(self, name, yfov, znear=0.001):
        # No aspectRatio: the renderer takes the aspect from the image. No zfar: infinite.
        self.cameras.append({"name": name, "type": "perspective",
                             "perspective": {"yfov": yfov, "znear": znear}})
        return len(self.cameras) - 1

    def add_node(self, name, mesh=None, camera=None, children=None, translation=None,
                 rotation=None, scale_xyz=None, matrix=None, extras=None):
        node = {"name": name}
        for key, value in (("mesh", mesh), ("camera", camera), ("children", children),
                           ("translation", translation), ("rotation", rotation),
                           ("scale", scale_xyz), ("matrix", matrix), ("extras", extras)):
            if value is not None:
                node[key] = value
        self.nodes.append(node)
        return len(self.nodes) - 1

    def add_mesh_node(self, name, mesh, material, **node_fields):
        return self.add_node(name, mesh=self.add_mesh(name, mesh, material), **node_fields)

    def to_json(self, scene_name, root_nodes):
        asset = {"version": "2.0", "generator": GENERATOR}
        if self.extras:
            asset["extras"] = self.extras
        document = {"asset": asset}
        if self.extensions_used:
            document["extensionsUsed"] = sorted(self.extensions_used)
        document["scene"] = 0
        document["scenes"] = [{"name": scene_name, "nodes": list(root_nodes)}]
        document["nodes"] = self.nodes
        if self.cameras:
            document["cameras"] = self.cameras
        document["meshes"] = self.meshes
        document["materials"] = self.materials
        document["accessors"] = self.accessors
        document["bufferViews"] = self.buffer_views
        while len(self.binary) % 4:
            self.binary.append(0)
        document["buffers"] = [{
            "byteLength": len(self.binary),
            "uri": DATA_URI_PREFIX + base64.b64encode(bytes(self.binary)).decode("ascii")}]
        return document


def format_json(value, depth=0):
    """Indented JSON that keeps arrays of plain values (vectors, matrices, index lists) on one
    line, so that a scene reads like a table rather than one number per line."""
    pad, inner = "  " * depth, "  " * (depth + 1)
    if isinstance(value, dict):
        items = [f"{inner}{json.dumps(k)}: {format_json(v, depth + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}" if items else "{}"
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        items = [inner + format_json(v, depth + 1) for v in value]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(value, ensure_ascii=True, separators=(", ", ": "))


def write_document(relative_path, document):
    path = SCENES_DIR / relative_path
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(format_json(document) + "\n", encoding="ascii")
    return path


# ---------------------------------------------------------------------------------------------
# 1. The Cornell box
# ---------------------------------------------------------------------------------------------

# Published measured geometry of the Cornell box, in millimetres, as listed by the Cornell
# University Program of Computer Graphics: https://www.graphics.cornell.edu/online/box/data.html
# Each entry is one quad in the published vertex order; the light is lowered from the ceiling
# height 548.8 to 548.7 so that the two surfaces do not coincide.
CORNELL_SOURCE = "https://www.graphics.cornell.edu/online/box/data.html"
CORNELL_LIGHT_Y_MM = 548.7
CORNELL_QUADS_MM = {
    "Floor": [[(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]],
    "Light": [[(343.0, CORNELL_LIGHT_Y_MM, 227.0), (343.0, CORNELL_LIGHT_Y_MM, 332.0),
               (213.0, CORNELL_LIGHT_Y_MM, 332.0), (213.0, CORNELL_LIGHT_Y_MM, 227.0)]],
    "Ceiling": [[(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2),
                 (0.0, 548.8, 0.0)]],
    "Back wall": [[(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2),
                   (556.0, 548.8, 559.2)]],
    "Right wall": [[(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0),
                    (0.0, 548.8, 559.2)]],
    "Left wall": [[(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2),
                   (556.0, 548.8, 0.0)]],
    "Short block": [
        [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0),
         (290.0, 165.0, 114.0)],
        [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0),
         (240.0, 0.0, 272.0)],
        [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0),
         (290.0, 0.0, 114.0)],
        [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0),
         (130.0, 0.0, 65.0)],
        [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0),
         (82.0, 0.0, 225.0)],
    ],
    "Tall block": [
        [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0),
         (472.0, 330.0, 406.0)],
        [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0),
         (472.0, 0.0, 406.0)],
        [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0),
         (314.0, 0.0, 456.0)],
        [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0),
         (265.0, 0.0, 296.0)],
        [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0),
         (423.0, 0.0, 247.0)],
    ],
}
CORNELL_MATERIAL_OF = {"Floor": "White", "Light": "Light", "Ceiling": "White",
                       "Back wall": "White", "Right wall": "Green", "Left wall": "Red",
                       "Short block": "White", "Tall block": "White"}
CORNELL_BOX_CENTRE_MM = (278.0, 274.4, 279.6)
# Camera: position (278, 273, -800) mm looking along +z, focal length 35 mm, 25 mm film.
CORNELL_CAMERA_MM = (278.0, 273.0, -800.0)
CORNELL_YFOV = 2.0 * math.atan(12.5 / 35.0)


def cornell_inward_direction(name, quad):
    """Where a quad's front face must point: walls into the box, the light down, block faces
    out of their block (into the room)."""
    if name == "Light":
        return (0.0, -1.0, 0.0)
    if name.endswith("block"):
        block = [p for q in CORNELL_QUADS_MM[name] for p in q]
        return sub(centroid(quad), centroid(block))
    return sub(CORNELL_BOX_CENTRE_MM, centroid(quad))


def mm_to_m(p):
    # Division is correctly rounded, so 278 / 1000 is exactly the double nearest 0.278.
    return tuple(c / 1000.0 for c in p)


def cornell_box():
    doc = GltfDocument(extras={"source": CORNELL_SOURCE,
                               "note": "Published millimetre coordinates x 0.001; light at "
                                       "y = 548.7 mm, 0.1 mm below the ceiling."})
    materials = {
        "White": doc.add_material("White", (0.725, 0.71, 0.68)),
        "Red": doc.add_material("Red", (0.63, 0.065, 0.05)),
        "Green": doc.add_material("Green", (0.14, 0.45, 0.091)),
        "Light": doc.add_material("Light", (0.78, 0.78, 0.78), (1.0, 0.7059, 0.2353), 17.0),
    }
    roots = []
    for name, quads in CORNELL_QUADS_MM.items():
        mesh = MeshBuilder()
        for quad in quads:
            oriented = facing(quad, cornell_inward_direction(name, quad))
            mesh.add_polygon([mm_to_m(p) for p in oriented])
        roots.append(doc.add_mesh_node(name, mesh, materials[CORNELL_MATERIAL_OF[name]]))
    # The camera looks down its local -Z; turning it 180 degrees about +Y makes it look along
    # world +Z, and then world +x is image-left, so the red wall (x = 0.556) is on the left.
    camera = doc.add_camera("Cornell camera", CORNELL_YFOV)
    roots.append(doc.add_node("Camera", camera=camera, translation=list(mm_to_m(CORNELL_CAMERA_MM)),
                              rotation=[0.0, 1.0, 0.0, 0.0]))
    return doc.to_json("Cornell box", roots)


# ---------------------------------------------------------------------------------------------
# 2. White furnace
# ---------------------------------------------------------------------------------------------

FURNACE_SUBDIVISIONS = 3
FURNACE_ALBEDO = 0.5
FURNACE_EMISSION = 0.5


def furnace(double_sided):
    doc = GltfDocument()
    grey = (FURNACE_ALBEDO,) * 3
    if double_sided:
        material = doc.add_material("Furnace grey, double-sided", grey, [FURNACE_EMISSION] * 3,
                                    double_sided=True)
        name = "Furnace sphere (outward, double-sided)"
    else:
        material = doc.add_material("Furnace grey", grey, [FURNACE_EMISSION] * 3)
        name = "Furnace sphere (inward)"
    roots = [doc.add_mesh_node(name, sphere_mesh(FURNACE_SUBDIVISIONS, not double_sided),
                               material)]
    camera = doc.add_camera("Centre camera", math.radians(60.0))
    roots.append(doc.add_node("Camera", camera=camera))
    return doc.to_json("White furnace", roots)


# ---------------------------------------------------------------------------------------------
# 3. Quad light over a floor
# ---------------------------------------------------------------------------------------------

QLF_ALBEDO = 0.8
QLF_RADIANCE = 4.0
QLF_LIGHT_HALF = 0.25
QLF_LIGHT_HEIGHT = 1.0


def point_to_rectangle_form_factor(a, b, h):
    """Form factor from a differential area to a parallel a x b rectangle at height h whose
    corner lies straight above it (the classic closed form, e.g. Howell's catalogue C-11)."""
    ra = math.sqrt(a * a + h * h)
    rb = math.sqrt(b * b + h * h)
    return (a / ra * math.atan(b / ra) + b / rb * math.atan(a / rb)) / (2.0 * math.pi)


def quad_light_floor_centre_radiance():
    """Floor radiance straight below the light: albedo x radiance x form factor. It is exact at
    every depth >= 1: the floor cannot see itself and the light (albedo 0) reflects nothing."""
    quarter = point_to_rectangle_form_factor(QLF_LIGHT_HALF, QLF_LIGHT_HALF, QLF_LIGHT_HEIGHT)
    return QLF_ALBEDO * QLF_RADIANCE * 4.0 * quarter


def floor_and_light(doc, floor_half, light_half, light_height, radiance):
    floor = MeshBuilder()
    floor.add_polygon(rectangle((0.0, 0.0, 0.0), (0.0, 0.0, floor_half), (floor_half, 0.0, 0.0)))
    light = MeshBuilder()
    light.add_polygon(rectangle((0.0, light_height, 0.0), (light_half, 0.0, 0.0),
                                (0.0, 0.0, light_half)))
    return [doc.add_mesh_node("Floor", floor, doc.add_material("White", (QLF_ALBEDO,) * 3)),
            doc.add_mesh_node("Light", light, doc.add_emitter("Light", radiance))]


def quad_light_floor():
    doc = GltfDocument()
    roots = floor_and_light(doc, 1.0, QLF_LIGHT_HALF, QLF_LIGHT_HEIGHT, QLF_RADIANCE)
    eye = (0.0, 1.2, 2.5)
    camera = doc.add_camera("Camera", math.radians(45.0))
    roots.append(doc.add_node("Camera", camera=camera, translation=list(eye),
                              rotation=look_at_rotation(eye, (0.0, 0.0, 0.0))))
    return doc.to_json("Quad light over a floor", roots)


# ---------------------------------------------------------------------------------------------
# 3b. Many lights
# ---------------------------------------------------------------------------------------------

ML_FLOOR_HALF = 16.0      # the floor: x, z in [-16, 16]
ML_GRID = 48              # lamps per side: 48 x 48 = 2304 lamps, 4608 emitting triangles
ML_LAMP_HALF = 0.06       # each lamp a 0.12 m square
ML_LAMP_HEIGHT = 0.4      # above the floor, facing down
ML_RADIANCES = (5.0, 20.0, 60.0)  # dim, medium and bright lamps, one material each
ML_BLOCK_COUNT = 24       # grey blocks between the lamps, casting shadows


def ml_hash(i):
    """A number in [0, 1) from i (an integer hash, the same on every Python)."""
    x = (i * 2654435761 + 12345) & 0xffffffff
    x ^= x >> 16
    x = (x * 0x45d9f3b) & 0xffffffff
    x ^= x >> 16
    return x / 4294967296.0


def many_lights():
    """Thousands of small lamps hung low over a large floor: at any point only the few lamps
    nearby matter, the case a light BVH is for (docs/integrator.md, "Choosing an emitter")."""
    doc = GltfDocument()
    floor = MeshBuilder()
    floor.add_polygon(rectangle((0.0, 0.0, 0.0), (0.0, 0.0, ML_FLOOR_HALF),
                                (ML_FLOOR_HALF, 0.0, 0.0)))
    roots = [doc.add_mesh_node("Floor", floor, doc.add_material("Floor", (0.5, 0.5, 0.5)))]
    lamps = [MeshBuilder() for _ in ML_RADIANCES]
    step = 2.0 * ML_FLOOR_HALF / ML_GRID
    for i in range(ML_GRID):
        for j in range(ML_GRID):
            k = i * ML_GRID + j
            x = -ML_FLOOR_HALF + step * (i + 0.2 + 0.6 * ml_hash(3 * k))
            z = -ML_FLOOR_HALF + step * (j + 0.2 + 0.6 * ml_hash(3 * k + 1))
            kind = min(int(ml_hash(3 * k + 2) * 10.0), 9)  # 5 dim, 4 medium, 1 bright in 10
            mesh = lamps[0 if kind < 5 else 1 if kind < 9 else 2]
            mesh.add_polygon(rectangle((x, ML_LAMP_HEIGHT, z), (ML_LAMP_HALF, 0.0, 0.0),
                                       (0.0, 0.0, ML_LAMP_HALF)))
    for n, (mesh, value) in enumerate(zip(lamps, ML_RADIANCES)):
        roots.append(doc.add_mesh_node(f"Lamps {n}", mesh,
                                       doc.add_emitter(f"Lamp {n}", value)))
    blocks = MeshBuilder()
    for b in range(ML_BLOCK_COUNT):
        x = -ML_FLOOR_HALF * 0.8 + 1.6 * ML_FLOOR_HALF * ml_hash(7001 + 2 * b)
        z = -ML_FLOOR_HALF * 0.8 + 1.6 * ML_FLOOR_HALF * ml_hash(7002 + 2 * b)
        lo, hi = (x - 0.15, 0.0, z - 0.15), (x + 0.15, 0.3, z + 0.15)
        for axis in range(3):
            for side, value in ((-1.0, lo[axis]), (1.0, hi[axis])):
                if axis == 1 and side < 0.0:
                    continue  # the bottom lies on the floor
                centre = [(lo[c] + hi[c]) / 2.0 for c in range(3)]
                centre[axis] = value
                half_u = [0.0, 0.0, 0.0]
                half_v = [0.0, 0.0, 0.0]
                half_u[(axis + 1) % 3] = (hi[(axis + 1) % 3] - lo[(axis + 1) % 3]) / 2.0
                half_v[(axis + 2) % 3] = (hi[(axis + 2) % 3] - lo[(axis + 2) % 3]) / 2.0
                normal = [0.0, 0.0, 0.0]
                normal[axis] = side
                blocks.add_polygon(facing(rectangle(centre, half_u, half_v), normal))
    roots.append(doc.add_mesh_node("Blocks", blocks, doc.add_material("Blocks", (0.6, 0.6, 0.6))))
    eye = (0.0, 5.0, 12.0)
    camera = doc.add_camera("Camera", math.radians(50.0))
    roots.append(doc.add_node("Camera", camera=camera, translation=list(eye),
                              rotation=look_at_rotation(eye, (0.0, 0.0, 2.0))))
    return doc.to_json("Many lights", roots)


# ---------------------------------------------------------------------------------------------
# 4. Mirror-symmetric box
# ---------------------------------------------------------------------------------------------

def symmetric_box():
    """Every symmetric quad is fanned around its centre and every off-centre quad has a mirror
    twin built by negating x (with reversed order, as a mirror flips orientation), so the
    triangle set is exactly its own mirror image in x, float for float."""
    doc = GltfDocument()
    walls = MeshBuilder()
    inside = (0.0, 0.5, 0.0)
    centred = [
        [(-0.5, 0.0, -0.5), (-0.5, 0.0, 0.5), (0.5, 0.0, 0.5), (0.5, 0.0, -0.5)],  # floor
        [(-0.5, 1.0, -0.5), (-0.5, 1.0, 0.5), (0.5, 1.0, 0.5), (0.5, 1.0, -0.5)],  # ceiling
        [(-0.5, 0.0, -0.5), (0.5, 0.0, -0.5), (0.5, 1.0, -0.5), (-0.5, 1.0, -0.5)],  # back
    ]
    for quad in centred:
        walls.add_centre_fan(facing(quad, sub(inside, centroid(quad))))
    left = facing([(-0.5, 0.0, -0.5), (-0.5, 0.0, 0.5), (-0.5, 1.0, 0.5), (-0.5, 1.0, -0.5)],
                  (1.0, 0.0, 0.0))
    add_mirrored_pair(walls, left)

    block = MeshBuilder()
    lo, hi = (-0.15, 0.0, -0.2), (0.15, 0.3, 0.1)
    mid = centroid([lo, hi])
    for face in symmetric_box_block_faces(lo, hi):
        oriented = facing(face, sub(centroid(face), mid))
        if abs(centroid(face)[0]) == 0.0:
            block.add_centre_fan(oriented)
        else:
            add_mirrored_pair(block, oriented)

    light = MeshBuilder()
    light.add_centre_fan(facing(rectangle((0.0, 0.999, 0.0), (0.15, 0.0, 0.0), (0.0, 0.0, 0.15)),
                                (0.0, -1.0, 0.0)))

    white = doc.add_material("White", (0.7, 0.7, 0.7))
    roots = [doc.add_mesh_node("Walls", walls, white),
             doc.add_mesh_node("Block", block, white),
             doc.add_mesh_node("Light", light, doc.add_emitter("Light", 8.0))]
    camera = doc.add_camera("Camera", math.radians(45.0))
    eye = (0.0, 0.5, 1.6)
    roots.append(doc.add_node("Camera", camera=camera, translation=list(eye),
                              rotation=look_at_rotation(eye, (0.0, 0.5, 0.0))))
    return doc.to_json("Mirror-symmetric box", roots)


def symmetric_box_block_faces(lo, hi):
    """The block's top, front and back (each symmetric about x = 0) and its -x side; the +x
    side is added as the mirror twin of the -x side."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return [
        [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],  # top
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # front (+z)
        [(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)],  # back (-z)
        [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],  # -x side
    ]


def mirror_x(p):
    return (-p[0], p[1], p[2])


def add_mirrored_pair(mesh, polygon):
    """The polygon and its mirror image in x. The twin keeps the first corner and reverses the
    rest: mirroring flips the orientation, and keeping the fan's apex mirrors its diagonals."""
    mesh.add_polygon(polygon)
    mesh.add_polygon([mirror_x(polygon[0])] + [mirror_x(p) for p in reversed(polygon[1:])])


# ---------------------------------------------------------------------------------------------
# 5. Which side emits
# ---------------------------------------------------------------------------------------------

# Camera at distance 2.5 with tan(yfov / 2) = 0.4 sees exactly -1..1 in y at z = 0, so in a
# square image a world point (x, y, 0) lands at u = (x + 1) / 2, v = (1 - y) / 2 (v from the
# top), and the quad edges (multiples of 1/8 m) fall on multiples of 1/16 of the image.
SIDES_CAMERA_DISTANCE = 2.5
SIDES_YFOV = 2.0 * math.atan(0.4)
SIDES_QUADS = [
    # name, x range, y range, front toward the camera?, doubleSided
    ("Front toward camera", (-0.875, -0.125), (0.125, 0.875), True, False),
    ("Back toward camera", (0.125, 0.875), (0.125, 0.875), False, False),
    ("Back toward camera, double-sided", (-0.375, 0.375), (-0.875, -0.125), False, True),
]


def emission_sides():
    doc = GltfDocument()
    roots = []
    for name, (x0, x1), (y0, y1), front_to_camera, double_sided in SIDES_QUADS:
        quad = [(x0, y0, 0.0), (x1, y0, 0.0), (x1, y1, 0.0), (x0, y1, 0.0)]  # CCW from +z
        mesh = MeshBuilder()
        mesh.add_polygon(quad if front_to_camera else list(reversed(quad)))
        material = doc.add_emitter(name, 1.0, double_sided=double_sided)
        roots.append(doc.add_mesh_node(name, mesh, material))
    camera = doc.add_camera("Camera", SIDES_YFOV)
    roots.append(doc.add_node("Camera", camera=camera,
                              translation=[0.0, 0.0, SIDES_CAMERA_DISTANCE]))
    return doc.to_json("Emission sides", roots)


# ---------------------------------------------------------------------------------------------
# 6. Small cases: one triangle, no lights, no camera
# ---------------------------------------------------------------------------------------------

def single_triangle():
    doc = GltfDocument()
    mesh = MeshBuilder()
    mesh.add_triangle((-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.0, 0.5, 0.0))
    roots = [doc.add_mesh_node("Triangle", mesh, doc.add_emitter("White emitter", 1.0))]
    camera = doc.add_camera("Camera", SIDES_YFOV)
    roots.append(doc.add_node("Camera", camera=camera,
                              translation=[0.0, 0.0, SIDES_CAMERA_DISTANCE]))
    return doc.to_json("Single triangle", roots)


def no_lights():
    doc = GltfDocument()
    mesh = MeshBuilder()
    mesh.add_polygon(rectangle((0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.0, 0.5, 0.0)))
    roots = [doc.add_mesh_node("Quad", mesh, doc.add_material("White", (0.8, 0.8, 0.8)))]
    camera = doc.add_camera("Camera", SIDES_YFOV)
    roots.append(doc.add_node("Camera", camera=camera,
                              translation=[0.0, 0.0, SIDES_CAMERA_DISTANCE]))
    return doc.to_json("No lights", roots)


# ---------------------------------------------------------------------------------------------
# 6b. Single-sided surfaces seen from behind (glTF doubleSided false: back-face culled)
# ---------------------------------------------------------------------------------------------

# A closed room, x and z in -1..1, y in 0..2, every wall single-sided and facing in, lit by a
# ceiling quad facing down; the camera stands outside, on +z, and looks through the near wall
# (whose back faces it) at the inside, as a glTF viewer shows it.
ROOM_HALF = 1.0
ROOM_HEIGHT = 2.0
ROOM_CAMERA = (0.0, 1.0, 3.2)
ROOM_LIGHT_HALF = 0.3
ROOM_LIGHT_RADIANCE = 8.0
ROOM_WALLS = [
    # name, centre, half_u, half_v, colour
    ("Floor", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.8, 0.8, 0.8)),
    ("Ceiling", (0.0, 2.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.8, 0.8, 0.8)),
    ("Back wall", (0.0, 1.0, -1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.8, 0.8, 0.8)),
    ("Near wall", (0.0, 1.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.8, 0.8, 0.8)),
    ("Left wall", (-1.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (0.63, 0.065, 0.05)),
    ("Right wall", (1.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (0.14, 0.45, 0.091)),
]
ROOM_BLOCK = ((0.0, 0.35, -0.3), 0.7)  # centre, edge: a white cube on the floor, faces out


def single_sided_room():
    doc = GltfDocument()
    roots = []
    inside = (0.0, ROOM_HEIGHT / 2.0, 0.0)
    for name, centre, half_u, half_v, colour in ROOM_WALLS:
        mesh = MeshBuilder()
        mesh.add_polygon(facing(rectangle(centre, half_u, half_v), sub(inside, centre)))
        roots.append(doc.add_mesh_node(name, mesh, doc.add_material(name, colour)))
    light = MeshBuilder()
    light.add_polygon(facing(rectangle((0.0, ROOM_HEIGHT - 0.01, 0.0), (ROOM_LIGHT_HALF, 0.0, 0.0),
                                       (0.0, 0.0, ROOM_LIGHT_HALF)), (0.0, -1.0, 0.0)))
    roots.append(doc.add_mesh_node("Light", light, doc.add_emitter("Light", ROOM_LIGHT_RADIANCE)))
    centre, edge = ROOM_BLOCK
    roots.append(doc.add_mesh_node("Block", unit_cube(), doc.add_material("Block", (0.8,) * 3),
                                   translation=list(centre), scale_xyz=[edge] * 3))
    camera = doc.add_camera("Camera", SIDES_YFOV)
    roots.append(doc.add_node("Camera", camera=camera, translation=list(ROOM_CAMERA)))
    return doc.to_json("Single-sided room", roots)


# A closed box, -1..1 on each axis, every face single-sided and facing out (a crate, authored
# to be seen from outside), with the camera inside and an emitter inside facing up, away from
# the camera. The camera sees through every face: the image is black, as in a glTF viewer.
INSIDE_OUT_CAMERA = (0.0, -0.5, 0.5)
INSIDE_OUT_LIGHT_Y = 0.9


def inside_out_box():
    doc = GltfDocument()
    box = unit_cube()
    roots = [doc.add_mesh_node("Crate", box, doc.add_material("Crate", (0.8,) * 3),
                               scale_xyz=[2.0] * 3)]
    light = MeshBuilder()
    light.add_polygon(facing(rectangle((0.0, INSIDE_OUT_LIGHT_Y, 0.0), (0.3, 0.0, 0.0),
                                       (0.0, 0.0, 0.3)), (0.0, 1.0, 0.0)))
    roots.append(doc.add_mesh_node("Light", light, doc.add_emitter("Light", 5.0)))
    camera = doc.add_camera("Camera", SIDES_YFOV)
    roots.append(doc.add_node("Camera", camera=camera, translation=list(INSIDE_OUT_CAMERA)))
    return doc.to_json("Inside-out box", roots)


def no_camera():
    doc = GltfDocument()
    roots = floor_and_light(doc, 1.0, QLF_LIGHT_HALF, QLF_LIGHT_HEIGHT, QLF_RADIANCE)
    return doc.to_json("No camera", roots)


# ---------------------------------------------------------------------------------------------
# 7. Deep BVH
# ---------------------------------------------------------------------------------------------

# 4096 emissive slivers in DEEP_LAYERS planes z = -d_k facing a camera at the origin, with
# d_k = DEEP_NEAREST_FAR * DEEP_RATIO^-k shrinking geometrically towards the camera (40 binary
# orders of magnitude from the first layer to the last). Layer k is the scaled copy of one
# pattern: every sliver spans the same screen height, so each layer covers the whole view in
# its bounding box and boxes shrink by DEEP_RATIO in every direction from layer to layer. The
# slivers of all layers interleave into one zig-zag strip across the screen (each grown 10%
# about its centroid so neighbours overlap), so they cover every pixel together.
#
# Why this is deep: a layer's box has DEEP_RATIO^2 times the area of the next, and the layer
# counts fall by DEEP_COUNT_DECAY per layer, so at every level the SAH's cheapest split peels
# off the farthest layer alone: one tree level per layer, plus the split within a layer.
# Why every ray walks deep: the camera sits where the layers converge, so each ray crosses
# every nested box near t = 0 and must descend the whole spine before it can trust a hit.
# Float range: the nearest layer is DEEP_NEAREST_FAR * 2^-40 = 2^-36 m away; the largest
# product in the ray/triangle test (about d^3 x sliver width) stays above 2^-120, clear of
# float32 denormals, which GPUs may flush.
DEEP_SLIVERS = 4096
DEEP_LAYERS = 34
DEEP_NEAREST_FAR = 16.0
DEEP_RATIO = 2.0 ** (40.0 / (DEEP_LAYERS - 1))
DEEP_COUNT_DECAY = 1.19
DEEP_SCREEN_HALF_X = 2.0   # slivers span screen x = x/-z in [-2, 2] ...
DEEP_SCREEN_HALF_Y = 0.7   # ... and y/-z in [-0.7, 0.7]
DEEP_GROW = 1.1
DEEP_YFOV = math.radians(60.0)  # tan 30 deg = 0.577 < 0.7; covers aspect ratios up to 3.4
DEEP_SLIVER_RADIANCE = 1.0
DEEP_BACKDROP_RADIANCE = 0.5
DEEP_MIN_BVH_DEPTH = 30


def deep_layer_counts():
    weights = [DEEP_COUNT_DECAY ** -k for k in range(DEEP_LAYERS)]
    total = sum(weights)
    counts = [max(1, round(DEEP_SLIVERS * w / total)) for w in weights]
    counts[0] += DEEP_SLIVERS - sum(counts)
    return counts


def deep_slivers():
    """The sliver triangles, front faces toward the camera at the origin (+z)."""
    layers = []
    for layer, count in enumerate(deep_layer_counts()):
        layers += [layer] * count
    # Spread each layer over the screen: strip position i takes the layer of rank
    # frac(i * golden ratio), a deterministic low-discrepancy shuffle.
    golden = (math.sqrt(5.0) - 1.0) / 2.0
    ranks = sorted(range(DEEP_SLIVERS), key=lambda i: ((i * golden) % 1.0, i))
    step = 2.0 * DEEP_SCREEN_HALF_X / (DEEP_SLIVERS + 1)
    hy = DEEP_SCREEN_HALF_Y
    triangles = []
    for position, rank in enumerate(ranks):
        x0 = -DEEP_SCREEN_HALF_X + position * step
        if position % 2 == 0:   # pointing up
            screen = [(x0, -hy), (x0 + 2 * step, -hy), (x0 + step, hy)]
        else:                   # pointing down
            screen = [(x0, hy), (x0 + step, -hy), (x0 + 2 * step, hy)]
        cx = sum(p[0] for p in screen) / 3.0
        cy = sum(p[1] for p in screen) / 3.0
        screen = [(cx + (sx - cx) * DEEP_GROW, cy + (sy - cy) * DEEP_GROW) for sx, sy in screen]
        d = DEEP_NEAREST_FAR * DEEP_RATIO ** -layers[rank]
        triangles.append([(sx * d, sy * d, -d) for sx, sy in screen])
    return triangles


def deep_bvh():
    doc = GltfDocument()
    slivers = MeshBuilder()
    for triangle in deep_slivers():
        slivers.add_triangle(*triangle)
    backdrop = MeshBuilder()
    far = 2.0 * DEEP_NEAREST_FAR
    backdrop.add_polygon(rectangle((0.0, 0.0, -far), (3.0 * far, 0.0, 0.0), (0.0, far, 0.0)))
    # Albedo 0 everywhere: nothing scatters, so the image is the same at every --max-depth.
    roots = [doc.add_mesh_node("Slivers", slivers, doc.add_emitter("Sliver emitter",
                                                                   DEEP_SLIVER_RADIANCE)),
             doc.add_mesh_node("Backdrop", backdrop, doc.add_emitter("Backdrop emitter",
                                                                     DEEP_BACKDROP_RADIANCE))]
    nearest = DEEP_NEAREST_FAR * DEEP_RATIO ** -(DEEP_LAYERS - 1)
    camera = doc.add_camera("Camera at the convergence point", DEEP_YFOV, znear=f32(nearest / 4))
    roots.append(doc.add_node("Camera", camera=camera))
    return doc.to_json("Deep BVH", roots)


# ---------------------------------------------------------------------------------------------
# 8. Node hierarchy
# ---------------------------------------------------------------------------------------------

ROOT_HALF = math.sqrt(0.5)
HIERARCHY_PARENT_TRS = ([1.0, 0.5, -2.0], [0.0, ROOT_HALF, 0.0, ROOT_HALF], [2.0, 1.0, 0.5])
# Child: translate (1, 2, 0) * rotate 90 degrees about +X * scale (0.5, 1, 0.5), as a matrix.
HIERARCHY_CHILD_MATRIX = matrix_multiply(
    matrix_from_trs([1.0, 2.0, 0.0], quat_axis_angle((1.0, 0.0, 0.0), 90.0), [1.0, 1.0, 1.0]),
    matrix_from_trs([0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0], [0.5, 1.0, 0.5]))
# Hand-derived world bounds (exact arithmetic); the script checks its own transforms against
# these, and a loader should match them within float rounding.
HIERARCHY_EXPECTED = {
    "Parent cube": ((0.75, 0.0, -3.0), (1.25, 1.0, -1.0)),
    "Child cube": ((0.75, 2.25, -4.5), (1.25, 2.75, -3.5)),
    "Light": ((0.5, 3.5, -3.0), (1.5, 3.5, -2.0)),
}
HIERARCHY_CAMERA_POSITION = (1.0, 1.5, 3.0)
HIERARCHY_CAMERA_FORWARD = (0.0, 0.0, -1.0)


def clean_matrix(m):
    """Snap float noise (cos 90 deg = 6e-17) to the exact values it stands for."""
    return [[round(v, 12) + 0.0 for v in row] for row in m]


def hierarchy():
    doc = GltfDocument()
    cube = doc.add_mesh("Unit cube", unit_cube(), doc.add_material("White", (0.8, 0.8, 0.8)))
    bounds = {name: {"min": list(lo), "max": list(hi)}
              for name, (lo, hi) in HIERARCHY_EXPECTED.items()}
    translation, rotation, scale_xyz = HIERARCHY_PARENT_TRS
    parent = doc.add_node("Parent cube", mesh=cube, translation=translation, rotation=rotation,
                          scale_xyz=scale_xyz,
                          extras={"expectedWorldBounds": bounds["Parent cube"]})
    child = doc.add_node("Child cube", mesh=cube,
                         matrix=matrix_to_gltf(clean_matrix(HIERARCHY_CHILD_MATRIX)),
                         extras={"expectedWorldBounds": bounds["Child cube"]})
    doc.nodes[parent]["children"] = [child]
    light_mesh = MeshBuilder()
    light_mesh.add_polygon(facing(rectangle((0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.0, 0.0, 0.5)),
                                  (0.0, -1.0, 0.0)))
    light = doc.add_mesh_node("Light", light_mesh, doc.add_emitter("Light", 10.0),
                              translation=[1.0, 3.5, -2.5],
                              extras={"expectedWorldBounds": bounds["Light"]})
    # The rig turns +90 degrees about +Y and the camera -90 degrees, so the camera's world
    # orientation is the identity, while its local offset (-3, 0, 0) is turned to (0, 0, 3).
    rig = doc.add_node("Camera rig", translation=[1.0, 1.5, 0.0],
                       rotation=[0.0, ROOT_HALF, 0.0, ROOT_HALF])
    camera = doc.add_camera("Nested camera", math.radians(50.0))
    camera_node = doc.add_node("Camera", camera=camera, translation=[-3.0, 0.0, 0.0],
                               rotation=[0.0, -ROOT_HALF, 0.0, ROOT_HALF],
                               extras={"expectedWorldPosition": list(HIERARCHY_CAMERA_POSITION),
                                       "expectedWorldForward": list(HIERARCHY_CAMERA_FORWARD)})
    doc.nodes[rig]["children"] = [camera_node]
    return doc.to_json("Node hierarchy", [parent, light, rig])


# ---------------------------------------------------------------------------------------------
# Checks: re-read each written file and verify it independently of the builder above
# ---------------------------------------------------------------------------------------------

COMPONENT_FORMATS = {FLOAT: "f", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I"}
COMPONENT_COUNTS = {"SCALAR": 1, "VEC3": 3}


class LoadedScene:
    """What a loader would see: per mesh node, its world-space triangles and material."""

    def __init__(self, path):
        self.path = path
        self.doc = json.loads(path.read_text(encoding="ascii"))
        self.buffer = self._decode_buffer()
        self.instances = []   # (node name, world matrix, mesh index)
        self.camera_nodes = []  # (node, world matrix)
        self._walk_nodes()

    def fail(self, message):
        raise AssertionError(f"{self.path.relative_to(SCENES_DIR)}: {message}")

    def expect(self, condition, message):
        if not condition:
            self.fail(message)

    def _decode_buffer(self):
        buffers = self.doc["buffers"]
        self.expect(len(buffers) == 1, "expected one buffer")
        uri = buffers[0]["uri"]
        self.expect(uri.startswith(DATA_URI_PREFIX), "buffer is not an embedded data URI")
        data = base64.b64decode(uri[len(DATA_URI_PREFIX):], validate=True)
        self.expect(len(data) == buffers[0]["byteLength"], "buffer byteLength mismatch")
        return data

    def read_accessor(self, index):
        accessor = self.doc["accessors"][index]
        view = self.doc["bufferViews"][accessor["bufferView"]]
        fmt = COMPONENT_FORMATS[accessor["componentType"]]
        components = COMPONENT_COUNTS[accessor["type"]]
        size = struct.calcsize("<" + fmt)
        start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
        length = accessor["count"] * components * size
        self.expect("byteStride" not in view, f"accessor {index}: unexpected byteStride")
        self.expect(start % size == 0, f"accessor {index}: misaligned")
        self.expect(view.get("byteOffset", 0) + view["byteLength"] <= len(self.buffer),
                    f"bufferView {accessor['bufferView']} runs past the buffer")
        self.expect(accessor.get("byteOffset", 0) + length <= view["byteLength"],
                    f"accessor {index} runs past its bufferView")
        values = struct.unpack_from(f"<{accessor['count'] * components}{fmt}", self.buffer, start)
        if components == 1:
            return list(values)
        return [tuple(values[i:i + 3]) for i in range(0, len(values), 3)]

    def _walk_nodes(self):
        doc = self.doc
        seen = set()
        stack = [(n, matrix_identity()) for n in doc["scenes"][doc.get("scene", 0)]["nodes"]]
        while stack:
            index, parent = stack.pop()
            self.expect(index not in seen, f"node {index} reached twice")
            seen.add(index)
            node = doc["nodes"][index]
            self.expect(bool(node.get("name")), f"node {index} has no name")
            self.expect(not ("matrix" in node and any(k in node for k in
                                                      ("translation", "rotation", "scale"))),
                        f"node {index} has both matrix and TRS")
            world = matrix_multiply(parent, node_local_matrix(node))
            if "mesh" in node:
                self.instances.append((node["name"], world, node["mesh"]))
            if "camera" in node:
                self.camera_nodes.append((node, world))
            stack += [(c, world) for c in node.get("children", [])]
        self.expect(len(seen) == len(doc["nodes"]), "some nodes are not in the scene")

    def primitive_data(self, primitive):
        """Checked positions, normals and index triples of one primitive (local space)."""
        self.expect(primitive.get("mode", TRIANGLES) == TRIANGLES, "mode is not TRIANGLES")
        position_index = primitive["attributes"]["POSITION"]
        positions = self.read_accessor(position_index)
        normals = self.read_accessor(primitive["attributes"]["NORMAL"])
        indices = self.read_accessor(primitive["indices"])
        accessor = self.doc["accessors"][position_index]
        self.expect(len(normals) == len(positions), "NORMAL count != POSITION count")
        self.expect(self.doc["accessors"][primitive["indices"]]["componentType"]
                    in (UNSIGNED_SHORT, UNSIGNED_INT), "index type")
        for i in range(3):
            self.expect(f32(accessor["min"][i]) == min(p[i] for p in positions),
                        f"POSITION accessor {position_index}: min[{i}] is wrong")
            self.expect(f32(accessor["max"][i]) == max(p[i] for p in positions),
                        f"POSITION accessor {position_index}: max[{i}] is wrong")
        for n in normals:
            self.expect(abs(length(n) - 1.0) < 1e-6, f"normal {n} is not unit length")
        self.expect(len(indices) % 3 == 0, "index count is not a multiple of 3")
        self.expect(max(indices) < len(positions), "index out of range")
        triples = [tuple(indices[i:i + 3]) for i in range(0, len(indices), 3)]
        for a, b, c in triples:
            n = face_normal(positions[a], positions[b], positions[c])
            self.expect(length(n) > 0.0, f"degenerate triangle {(a, b, c)}")
            for v in (a, b, c):
                self.expect(dot(n, normals[v]) > 0.0,
                            f"vertex normal {v} points to the back of triangle {(a, b, c)}")
        return positions, normals, triples

    def world_triangles(self, name=None):
        """[(triangle corners in world space, material index)] of all (or one named) node."""
        result = []
        for node_name, world, mesh_index in self.instances:
            if name is not None and node_name != name:
                continue
            for primitive in self.doc["meshes"][mesh_index]["primitives"]:
                positions, _, triples = self.primitive_data(primitive)
                for t in triples:
                    corners = [transform_point(world, positions[i]) for i in t]
                    result.append((corners, primitive["material"]))
        return result

    def material(self, name):
        for m in self.doc["materials"]:
            if m["name"] == name:
                return m
        self.fail(f"no material {name!r}")

    def camera(self):
        """(position, forward, up, yfov) of the first camera node, in world space."""
        self.expect(len(self.camera_nodes) >= 1, "no camera")
        node, world = self.camera_nodes[0]
        yfov = self.doc["cameras"][node["camera"]]["perspective"]["yfov"]
        return (transform_point(world, (0.0, 0.0, 0.0)),
                normalize(transform_direction(world, (0.0, 0.0, -1.0))),
                normalize(transform_direction(world, (0.0, 1.0, 0.0))), yfov)


def check_common(scene):
    doc = scene.doc
    scene.expect(doc["asset"]["version"] == "2.0", "asset.version")
    for kind in ("meshes", "materials", "cameras"):
        for i, item in enumerate(doc.get(kind, [])):
            scene.expect(bool(item.get("name")), f"{kind}[{i}] has no name")
    uses_strength = False
    for m in doc["materials"]:
        pbr = m["pbrMetallicRoughness"]
        scene.expect(pbr.get("metallicFactor") == 0.0, f"material {m['name']}: metallic")
        scene.expect(m.get("extensions", {}).get(SPECULAR, {}).get("specularFactor") == 0.0,
                     f"material {m['name']}: not diffuse-only (specularFactor 0)")
        scene.expect(all(0.0 <= c <= 1.0 for c in pbr["baseColorFactor"]), "baseColorFactor")
        scene.expect(all(0.0 <= c <= 1.0 for c in m.get("emissiveFactor", [0.0] * 3)),
                     f"material {m['name']}: emissiveFactor above 1")
        uses_strength |= EMISSIVE_STRENGTH in m.get("extensions", {})
    scene.expect(uses_strength == (EMISSIVE_STRENGTH in doc.get("extensionsUsed", [])),
                 "extensionsUsed does not match the materials")
    for cam in doc.get("cameras", []):
        scene.expect(cam["type"] == "perspective" and cam["perspective"]["znear"] > 0.0,
                     "camera")
    for corners, _ in scene.world_triangles():  # checks every accessor on the way
        pass


def radiance(material):
    strength = material.get("extensions", {}).get(EMISSIVE_STRENGTH, {}).get(
        "emissiveStrength", 1.0)
    return [c * strength for c in material.get("emissiveFactor", [0.0, 0.0, 0.0])]


def triangle_normal(corners):
    return normalize(face_normal(*corners))


def check_cornell(scene):
    box_centre = mm_to_m(CORNELL_BOX_CENTRE_MM)
    total = 0
    for name in CORNELL_QUADS_MM:
        triangles = scene.world_triangles(name)
        total += len(triangles)
        scene.expect(len(triangles) == 2 * len(CORNELL_QUADS_MM[name]), f"{name}: triangles")
        block_centre = centroid([p for corners, _ in triangles for p in corners])
        for corners, material in triangles:
            n = triangle_normal(corners)
            if name == "Light":
                scene.expect(n[1] < -0.999999, "light does not face down")
                scene.expect(all(abs(p[1] - 0.5487) < 1e-6 for p in corners), "light height")
            elif name.endswith("block"):
                # Compare with the face's own outward direction: from the block's middle
                # (at half its height) to the triangle's centroid, horizontally for the sides.
                c = centroid(corners)
                out = sub(c, block_centre) if n[1] < 0.5 else (0.0, 1.0, 0.0)
                scene.expect(dot(n, out) > 0.0, f"{name}: a face points into the block")
            else:
                scene.expect(dot(n, sub(box_centre, centroid(corners))) > 0.0,
                             f"{name}: faces out of the box")
            material_name = scene.doc["materials"][material]["name"]
            scene.expect(material_name == CORNELL_MATERIAL_OF[name], f"{name}: material")
    scene.expect(total == 32, "Cornell box should have 32 triangles")
    light = scene.material("Light")
    scene.expect(all(abs(a - b) < 0.01 for a, b in zip(radiance(light), (17.0, 12.0, 4.0))),
                 "light radiance")
    position, forward, up, yfov = scene.camera()
    scene.expect(all(abs(a - b) < 1e-9 for a, b in zip(position, (0.278, 0.273, -0.8))),
                 "camera position")
    scene.expect(abs(forward[2] - 1.0) < 1e-12 and abs(up[1] - 1.0) < 1e-12, "camera axes")
    scene.expect(abs(yfov - 0.6860478808) < 1e-9, "camera yfov")
    right = cross(forward, up)
    scene.expect(right[0] < 0.0, "world +x (the red wall) should be image-left")


def check_closed_sphere(scene, inward):
    triangles = scene.world_triangles()
    edges = {}
    for corners, _ in triangles:
        n = face_normal(*corners)
        outward = dot(n, centroid(corners)) > 0.0
        scene.expect(outward != inward, "a face points the wrong way")
        keys = [tuple(map(f32, p)) for p in corners]
        for i in range(3):
            edge = (keys[i], keys[(i + 1) % 3])
            scene.expect(edge not in edges, "an edge is used twice in the same direction")
            edges[edge] = True
        for p in corners:
            scene.expect(abs(length(p) - 1.0) < 1e-6, "vertex off the unit sphere")
    scene.expect(all((b, a) in edges for a, b in edges), "the sphere is not closed")
    scene.expect(len(triangles) == 20 * 4 ** FURNACE_SUBDIVISIONS, "triangle count")
    material = scene.doc["materials"][0]
    scene.expect(material["pbrMetallicRoughness"]["baseColorFactor"][:3] == [0.5] * 3, "albedo")
    scene.expect(radiance(material) == [0.5] * 3, "emission")
    scene.expect(material.get("doubleSided", False) == (not inward), "doubleSided")
    position, _, _, yfov = scene.camera()
    scene.expect(length(position) == 0.0 and abs(yfov - math.pi / 3) < 1e-12, "camera")


def faces(scene, name, direction):
    triangles = scene.world_triangles(name)
    scene.expect(len(triangles) > 0, f"no node {name!r}")
    return all(dot(triangle_normal(c), direction) > 0.999999 for c, _ in triangles)


def check_many_lights(scene):
    scene.expect(faces(scene, "Floor", (0.0, 1.0, 0.0)), "floor does not face up")
    lamps = 0
    for n, value in enumerate(ML_RADIANCES):
        name = f"Lamps {n}"
        scene.expect(faces(scene, name, (0.0, -1.0, 0.0)), f"{name} do not face down")
        scene.expect(radiance(scene.material(f"Lamp {n}")) == [value] * 3, f"{name} radiance")
        for corners, _ in scene.world_triangles(name):
            scene.expect(all(abs(p[1] - ML_LAMP_HEIGHT) < 1e-6 and
                             abs(p[0]) < ML_FLOOR_HALF and abs(p[2]) < ML_FLOOR_HALF
                             for p in corners), f"{name}: a lamp off its plane or the floor")
            lamps += 1
    scene.expect(lamps == 2 * ML_GRID * ML_GRID, f"{lamps} lamp triangles")


def check_quad_light_floor(scene):
    scene.expect(faces(scene, "Floor", (0.0, 1.0, 0.0)), "floor does not face up")
    scene.expect(faces(scene, "Light", (0.0, -1.0, 0.0)), "light does not face down")
    scene.expect(radiance(scene.material("Light")) == [4.0] * 3, "light radiance")
    position, forward, _, _ = scene.camera()
    to_origin = normalize(scale(position, -1.0))
    scene.expect(dot(forward, to_origin) > 1.0 - 1e-12, "camera does not look at the origin")
    scene.expect(all(abs(a - b) < 1e-12 for a, b in zip(position, (0.0, 1.2, 2.5))), "eye")
    # The README's centre value, from the closed form and from integrating over the light as
    # stored in the file: F = sum of cos * cos' / (pi r^2) dA from the origin (normal +y).
    corners = [p for c, _ in scene.world_triangles("Light") for p in c]
    x0, x1 = min(p[0] for p in corners), max(p[0] for p in corners)
    z0, z1 = min(p[2] for p in corners), max(p[2] for p in corners)
    h, n = corners[0][1], 200
    cell = (x1 - x0) * (z1 - z0) / (n * n)
    integral = 0.0
    for i in range(n):
        for j in range(n):
            x = x0 + (x1 - x0) * (i + 0.5) / n
            z = z0 + (z1 - z0) * (j + 0.5) / n
            integral += h * h / (math.pi * (x * x + h * h + z * z) ** 2) * cell
    centre = quad_light_floor_centre_radiance()
    scene.expect(abs(QLF_ALBEDO * QLF_RADIANCE * integral - centre) < 1e-5, "form factor")
    scene.expect(abs(centre - 0.2351284) < 1e-7, "centre radiance differs from the README")


def check_symmetric_box(scene):
    def key(corners):
        # A triangle as its cyclic vertex order, starting from its smallest vertex.
        pts = [tuple(map(f32, p)) for p in corners]
        i = pts.index(min(pts))
        return tuple(pts[i:] + pts[:i])

    triangles = scene.world_triangles()
    keys = {key(c) for c, _ in triangles}
    for corners, _ in triangles:
        mirrored = [mirror_x(p) for p in reversed(corners)]
        scene.expect(key(mirrored) in keys, f"triangle {corners} has no mirror twin")
    scene.expect(faces(scene, "Light", (0.0, -1.0, 0.0)), "light does not face down")
    for corners, _ in scene.world_triangles("Walls"):
        scene.expect(dot(triangle_normal(corners), sub((0.0, 0.5, 0.0), centroid(corners)))
                     > 0.0, "a wall faces out of the box")
    position, forward, _, _ = scene.camera()
    scene.expect(position == (0.0, 0.5, 1.6) and forward == (0.0, 0.0, -1.0), "camera")


# Written out independently of SIDES_QUADS, as README.md states them: node name ->
# (front face toward the camera, doubleSided, pixel rectangle x0, x1, y0, y1 in a 64 x 64 image).
SIDES_EXPECTED = {
    "Front toward camera": (True, False, (4, 28, 4, 28)),
    "Back toward camera": (False, False, (36, 60, 4, 28)),
    "Back toward camera, double-sided": (False, True, (20, 44, 36, 60)),
}


def check_emission_sides(scene):
    position, forward, up, yfov = scene.camera()
    tan_half = math.tan(yfov / 2.0)
    scene.expect(forward == (0.0, 0.0, -1.0) and up == (0.0, 1.0, 0.0), "camera axes")
    for name, (front_to_camera, double_sided, pixels) in SIDES_EXPECTED.items():
        triangles = scene.world_triangles(name)
        scene.expect(len(triangles) == 2, f"{name}: not one quad")
        for corners, material in triangles:
            toward = dot(triangle_normal(corners), sub(position, centroid(corners))) > 0.0
            scene.expect(toward == front_to_camera, f"{name}: wrong side toward the camera")
            m = scene.doc["materials"][material]
            scene.expect(m.get("doubleSided", False) == double_sided, f"{name}: doubleSided")
            scene.expect(radiance(m) == [1.0] * 3, f"{name}: radiance")
        # Project the corners into a 64 x 64 image (pixel (0, 0) at the top-left).
        projected = []
        for corners, _ in triangles:
            for p in corners:
                d = position[2] - p[2]
                projected.append(((p[0] - position[0]) / (d * tan_half) * 32.0 + 32.0,
                                  32.0 - (p[1] - position[1]) / (d * tan_half) * 32.0))
        box = (min(q[0] for q in projected), max(q[0] for q in projected),
               min(q[1] for q in projected), max(q[1] for q in projected))
        scene.expect(all(abs(a - b) < 1e-4 for a, b in zip(box, pixels)),
                     f"{name}: covers pixels {box}, expected {pixels}")


def check_single_triangle(scene):
    triangles = scene.world_triangles()
    scene.expect(len(triangles) == 1, "one triangle")
    position, _, _, _ = scene.camera()
    corners, _ = triangles[0]
    scene.expect(dot(triangle_normal(corners), sub(position, corners[0])) > 0.0,
                 "the triangle's back faces the camera")


def check_no_lights(scene):
    scene.expect(all(radiance(m) == [0.0] * 3 for m in scene.doc["materials"]), "an emitter")
    scene.camera()


def faces_away_from(scene, name, point):
    """Whether every triangle of node `name` has its back toward `point`."""
    return all(dot(triangle_normal(c), sub(point, centroid(c))) < 0.0
               for c, _ in scene.world_triangles(name))


def check_single_sided_room(scene):
    position, forward, _, _ = scene.camera()
    scene.expect(forward == (0.0, 0.0, -1.0), "camera axes")
    inside = (0.0, ROOM_HEIGHT / 2.0, 0.0)
    for name, _, _, _, _ in ROOM_WALLS:
        scene.expect(not faces_away_from(scene, name, inside), f"{name}: does not face in")
    scene.expect(faces_away_from(scene, "Near wall", position), "near wall faces the camera")
    scene.expect(not any(m.get("doubleSided", False) for m in scene.doc["materials"]),
                 "a double-sided material")
    for corners, _ in scene.world_triangles("Light"):
        scene.expect(triangle_normal(corners)[1] < -0.999999, "light does not face down")


def check_inside_out_box(scene):
    position, _, _, _ = scene.camera()
    scene.expect(faces_away_from(scene, "Crate", position), "a crate face faces the camera")
    scene.expect(faces_away_from(scene, "Light", position), "the light faces the camera")
    scene.expect(not any(m.get("doubleSided", False) for m in scene.doc["materials"]),
                 "a double-sided material")


def check_no_camera(scene):
    scene.expect("cameras" not in scene.doc and not scene.camera_nodes, "has a camera")
    scene.expect(any(radiance(m) != [0.0] * 3 for m in scene.doc["materials"]), "no emitter")


def check_deep_bvh(scene):
    slivers = [c for c, _ in scene.world_triangles("Slivers")]
    scene.expect(len(slivers) == DEEP_SLIVERS, "sliver count")
    for corners in slivers:
        scene.expect(triangle_normal(corners)[2] > 0.999999, "a sliver faces away")
    check_deep_coverage(scene, slivers)
    everything = [c for c, _ in scene.world_triangles()]
    depth = sah_tree_depth([triangle_box(c) for c in everything])
    scene.expect(depth >= DEEP_MIN_BVH_DEPTH, f"SAH tree depth only {depth}")
    return depth


def check_deep_coverage(scene, slivers):
    """Every sample direction of a 3.4:1 view hits some sliver (2D test in screen space)."""
    buckets = {}
    width = 1.0 / 256.0
    projected = []
    for corners in slivers:
        screen = [(p[0] / -p[2], p[1] / -p[2]) for p in corners]
        projected.append(screen)
        xs = [s[0] for s in screen]
        for b in range(math.floor(min(xs) / width), math.floor(max(xs) / width) + 1):
            buckets.setdefault(b, []).append(len(projected) - 1)

    def inside(point, tri):
        signs = []
        for i in range(3):
            a, b = tri[i], tri[(i + 1) % 3]
            signs.append((b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0]))
        return all(s >= 0.0 for s in signs) or all(s <= 0.0 for s in signs)

    tan_half = math.tan(DEEP_YFOV / 2)
    half_x = 3.4 * tan_half
    for i in range(341):
        for j in range(101):
            point = (-half_x + 2 * half_x * (i + 0.5) / 341, -tan_half + 2 * tan_half * j / 100)
            candidates = buckets.get(math.floor(point[0] / width), [])
            scene.expect(any(inside(point, projected[k]) for k in candidates),
                         f"screen point {point} is not covered by any sliver")


def triangle_box(corners):
    return tuple(min(p[i] for p in corners) for i in range(3)) + \
        tuple(max(p[i] for p in corners) for i in range(3))


def box_area(b):
    dx, dy, dz = b[3] - b[0], b[4] - b[1], b[5] - b[2]
    return 2.0 * (dx * dy + dy * dz + dz * dx)


def box_union(a, b):
    return tuple(min(a[i], b[i]) for i in range(3)) + tuple(max(a[i], b[i]) for i in range(3, 6))


EMPTY_BOX = (math.inf,) * 3 + (-math.inf,) * 3


def sah_tree_depth(boxes, bin_count=16, max_leaf_size=4, traversal_cost=1.0, hit_cost=1.0):
    """Depth (root = 0) of a binned-SAH tree over `boxes`, a model of host/bvh's builder with
    its default options: centroid bins on each axis, split cost traversal + Σ area·count /
    node area, a leaf when that is not cheaper and the node holds at most max_leaf_size."""
    centres = [tuple((b[i] + b[i + 3]) / 2 for i in range(3)) for b in boxes]
    deepest = 0
    stack = [(list(range(len(boxes))), 0)]
    while stack:
        items, depth = stack.pop()
        deepest = max(deepest, depth)
        node = EMPTY_BOX
        for i in items:
            node = box_union(node, boxes[i])
        best = None
        for axis in range(3):
            lo = min(centres[i][axis] for i in items)
            hi = max(centres[i][axis] for i in items)
            if hi <= lo:
                continue

            def bin_of(i, lo=lo, hi=hi, axis=axis):
                return min(bin_count - 1, int((centres[i][axis] - lo) * bin_count / (hi - lo)))

            counts = [0] * bin_count
            bounds = [EMPTY_BOX] * bin_count
            for i in items:
                b = bin_of(i)
                counts[b] += 1
                bounds[b] = box_union(bounds[b], boxes[i])
            for split in range(1, bin_count):
                left, right = EMPTY_BOX, EMPTY_BOX
                for b in range(split):
                    left = box_union(left, bounds[b])
                for b in range(split, bin_count):
                    right = box_union(right, bounds[b])
                n_left, n_right = sum(counts[:split]), sum(counts[split:])
                if n_left == 0 or n_right == 0:
                    continue
                cost = traversal_cost + hit_cost * (box_area(left) * n_left +
                                                    box_area(right) * n_right) / box_area(node)
                if best is None or cost < best[0]:
                    best = (cost, bin_of, split)
        if best is None:
            if len(items) > max_leaf_size:
                half = len(items) // 2
                stack += [(items[:half], depth + 1), (items[half:], depth + 1)]
            continue
        cost, bin_of, split = best
        if len(items) <= max_leaf_size and cost >= hit_cost * len(items):
            continue
        stack.append(([i for i in items if bin_of(i) < split], depth + 1))
        stack.append(([i for i in items if bin_of(i) >= split], depth + 1))
    return deepest


def check_hierarchy(scene):
    for name, (lo, hi) in HIERARCHY_EXPECTED.items():
        corners = [p for c, _ in scene.world_triangles(name) for p in c]
        got_lo = tuple(min(p[i] for p in corners) for i in range(3))
        got_hi = tuple(max(p[i] for p in corners) for i in range(3))
        scene.expect(all(abs(a - b) < 1e-6 for a, b in zip(got_lo + got_hi, lo + hi)),
                     f"{name}: world bounds {got_lo}..{got_hi}, expected {lo}..{hi}")
        node = next(n for n in scene.doc["nodes"] if n["name"] == name)
        scene.expect(node["extras"]["expectedWorldBounds"] == {"min": list(lo), "max": list(hi)},
                     f"{name}: extras")
    scene.expect(scene.doc["nodes"][0]["mesh"] == scene.doc["nodes"][1]["mesh"], "instancing")
    for corners, _ in scene.world_triangles("Light"):
        scene.expect(triangle_normal(corners)[1] < -0.999999, "light does not face down")
    position, forward, up, _ = scene.camera()
    scene.expect(all(abs(a - b) < 1e-12 for a, b in zip(position, HIERARCHY_CAMERA_POSITION)),
                 f"camera position {position}")
    scene.expect(all(abs(a - b) < 1e-12 for a, b in zip(forward, HIERARCHY_CAMERA_FORWARD)),
                 f"camera forward {forward}")
    scene.expect(abs(up[1] - 1.0) < 1e-12, "camera up")


# ---------------------------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------------------------

SCENES = [
    ("cornell-box.gltf", cornell_box, check_cornell),
    ("furnace.gltf", lambda: furnace(double_sided=False),
     lambda s: check_closed_sphere(s, inward=True)),
    ("test/furnace-double-sided.gltf", lambda: furnace(double_sided=True),
     lambda s: check_closed_sphere(s, inward=False)),
    ("test/quad-light-floor.gltf", quad_light_floor, check_quad_light_floor),
    ("test/many-lights.gltf", many_lights, check_many_lights),
    ("test/symmetric-box.gltf", symmetric_box, check_symmetric_box),
    ("test/emission-sides.gltf", emission_sides, check_emission_sides),
    ("test/single-triangle.gltf", single_triangle, check_single_triangle),
    ("test/no-lights.gltf", no_lights, check_no_lights),
    ("test/no-camera.gltf", no_camera, check_no_camera),
    ("test/single-sided-room.gltf", single_sided_room, check_single_sided_room),
    ("test/inside-out-box.gltf", inside_out_box, check_inside_out_box),
    ("test/deep-bvh.gltf", deep_bvh, check_deep_bvh),
    ("test/hierarchy.gltf", hierarchy, check_hierarchy),
]


def main():
    for relative, build, check in SCENES:
        path = write_document(relative, build())
        scene = LoadedScene(path)
        check_common(scene)
        detail = check(scene)
        triangles = len(scene.world_triangles())
        extra = f", SAH depth {detail}" if detail is not None else ""
        print(f"wrote scenes/{relative}: {triangles} triangles, {len(scene.instances)} mesh "
              f"nodes, {len(scene.camera_nodes)} cameras{extra}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
