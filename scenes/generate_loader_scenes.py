#!/usr/bin/env python3
"""generate_loader_scenes.py — writes the small glTF files that test the scene loader.

scenes/loader/   valid files, each exercising one way of storing geometry (index types,
                 non-indexed, missing normals, interleaved vertices, .glb, transforms, ...) or
                 one part of the scene model (textures, texture transforms, spheres, lights,
                 KHR_materials_specular, _unlit, _variants).
scenes/invalid/  broken files, one per kind of bad input; loading each must end with one
                 InputError line naming the file and the place.

Python 3 standard library only, and deterministic: running it again rewrites the same bytes.
The outputs are committed; tests/unit/gltf_loader_test.cpp and gltf_extensions_test.cpp state
what each must load to.
"""

import base64
import json
import math
import re
import struct
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent
LOADER_DIR = ROOT / "loader"
INVALID_DIR = ROOT / "invalid"

GENERATOR = "vkpt scenes/generate_loader_scenes.py"

# glTF constants
BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT = 5120, 5121, 5122, 5123, 5125, 5126
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
POINTS, TRIANGLES = 0, 4
NEAREST, LINEAR = 9728, 9729
REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT = 10497, 33071, 33648

# The unit quad in the z = 0 plane, counter-clockwise seen from +Z.
QUAD_POSITIONS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
QUAD_NORMALS = [(0, 0, 1)] * 4
QUAD_INDICES = [0, 1, 2, 0, 2, 3]
TRIANGLE_POSITIONS = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
# sin 45 degrees, the quaternion component of a 90-degree rotation
S45 = math.sqrt(0.5)


def floats(values):
    flat = [float(c) for v in values for c in (v if isinstance(v, (tuple, list)) else (v,))]
    return struct.pack("<%df" % len(flat), *flat)


def unsigned(values, component_type):
    code = {UNSIGNED_BYTE: "B", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I"}[component_type]
    return struct.pack("<%d%s" % (len(values), code), *values)


def data_uri(data, mime="application/octet-stream"):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode("ascii"))


def png_bytes(rows, compressed=None):
    """An 8-bit RGBA PNG of `rows` (lists of (r, g, b, a)), row 0 first, unfiltered; the IDAT
    data replaced by `compressed` if given."""
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for texel in row for c in texel) for row in rows)
    if compressed is None:
        compressed = zlib.compress(raw, 9)

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8 bits, RGBA
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", compressed) +
            chunk(b"IEND", b""))


# A 3 x 2 image whose every texel differs, so that tests see the order of rows and columns:
# row 0 (v = 0) red, green, blue; row 1 yellow, cyan and a dark grey, with four alphas.
TEXTURE_ROWS = [[(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255)],
                [(255, 255, 0, 128), (0, 255, 255, 64), (10, 20, 30, 40)]]
TEXTURE_PNG = png_bytes(TEXTURE_ROWS)
QUAD_TEXCOORDS = [(0, 0), (1, 0), (1, 1), (0, 1)]


class Gltf:
    """A glTF document with one binary buffer, built up view by view."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": GENERATOR}}

    def _list(self, key):
        return self.doc.setdefault(key, [])

    def add(self, key, item):
        self._list(key).append(item)
        return len(self.doc[key]) - 1

    def view(self, data, stride=None, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(data)}
        if stride is not None:
            view["byteStride"] = stride
        if target is not None:
            view["target"] = target
        self.data += data
        return self.add("bufferViews", view)

    def accessor(self, view, component_type, count, type_, byte_offset=0, **extra):
        accessor = {"bufferView": view, "componentType": component_type, "count": count,
                    "type": type_}
        if view is None:  # the data comes from an extension (Draco)
            del accessor["bufferView"]
        if byte_offset:
            accessor["byteOffset"] = byte_offset
        accessor.update(extra)
        return self.add("accessors", accessor)

    def positions(self, values):
        lo = [min(v[i] for v in values) for i in range(3)]
        hi = [max(v[i] for v in values) for i in range(3)]
        view = self.view(floats(values), target=ARRAY_BUFFER)
        return self.accessor(view, FLOAT, len(values), "VEC3", min=lo, max=hi)

    def normals(self, values):
        return self.accessor(self.view(floats(values), target=ARRAY_BUFFER), FLOAT, len(values),
                             "VEC3")

    def texcoords(self, values, component_type=FLOAT):
        if component_type == FLOAT:
            return self.accessor(self.view(floats(values), target=ARRAY_BUFFER), FLOAT,
                                 len(values), "VEC2")
        data = unsigned([c for v in values for c in v], component_type)
        return self.accessor(self.view(data, target=ARRAY_BUFFER), component_type, len(values),
                             "VEC2", normalized=True)

    def indices(self, values, component_type=UNSIGNED_SHORT):
        view = self.view(unsigned(values, component_type), target=ELEMENT_ARRAY_BUFFER)
        return self.accessor(view, component_type, len(values), "SCALAR")

    def mesh(self, primitives, name=None):
        mesh = {"primitives": primitives}
        if name:
            mesh["name"] = name
        return self.add("meshes", mesh)

    def node(self, **fields):
        return self.add("nodes", fields)

    def embed_buffer(self):
        """Declares the buffer with its bytes inside, as a base64 data URI."""
        data = self.finish_buffer()
        self.doc["buffers"][0]["uri"] = data_uri(data)

    def scene(self, nodes):
        self.doc["scene"] = 0
        self.doc["scenes"] = [{"nodes": nodes}]

    def finish_buffer(self, uri=None):
        """Declares the buffer and returns its bytes; uri None means the .glb BIN chunk."""
        while len(self.data) % 4:
            self.data.append(0)
        buffer = {"byteLength": len(self.data)}
        if uri is not None:
            buffer["uri"] = uri
        self.doc["buffers"] = [buffer]
        return bytes(self.data)


def primitive(position, normal=None, indices=None, material=None, mode=None, texcoord=None):
    result = {"attributes": {"POSITION": position}}
    if normal is not None:
        result["attributes"]["NORMAL"] = normal
    if texcoord is not None:
        result["attributes"]["TEXCOORD_0"] = texcoord
    if indices is not None:
        result["indices"] = indices
    if material is not None:
        result["material"] = material
    if mode is not None:
        result["mode"] = mode
    return result


def json_text(doc):
    text = json.dumps(doc, indent=1)
    # Arrays of numbers on one line, so that a person can read the files.
    return re.sub(r"\[\s+([-+\d.eE,\s]+?)\s+\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]",
                  text) + "\n"


def write(path, data):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode("utf-8") if isinstance(data, str) else data)


def write_embedded(path, gltf):
    gltf.embed_buffer()
    write(path, json_text(gltf.doc))


def write_external(path, gltf):
    data = gltf.finish_buffer(uri=path.with_suffix(".bin").name)
    write(path.with_suffix(".bin"), data)
    write(path, json_text(gltf.doc))


def glb_bytes(doc, binary):
    chunk_json = json.dumps(doc, separators=(",", ":")).encode("utf-8")
    chunk_json += b" " * (-len(chunk_json) % 4)
    chunks = struct.pack("<II", len(chunk_json), 0x4E4F534A) + chunk_json
    if binary is not None:
        binary += b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def write_glb(path, gltf):
    write(path, glb_bytes(gltf.doc, gltf.finish_buffer()))


# --------------------------------------------------------------------------------------------
# Valid scenes


def quad(index_type):
    gltf = Gltf()
    mesh = gltf.mesh([primitive(gltf.positions(QUAD_POSITIONS), gltf.normals(QUAD_NORMALS),
                                gltf.indices(QUAD_INDICES, index_type))])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


def non_indexed():
    corners = [QUAD_POSITIONS[i] for i in QUAD_INDICES]
    gltf = Gltf()
    mesh = gltf.mesh([primitive(gltf.positions(corners), gltf.normals([(0, 0, 1)] * 6))])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


def no_normals():
    # A slanted triangle: its flat normal is (1, 1, 1) / sqrt(3).
    gltf = Gltf()
    mesh = gltf.mesh([primitive(gltf.positions([(1, 0, 0), (0, 1, 0), (0, 0, 1)]))])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


INTERLEAVED_NORMALS = [(0, 0, 1), (0, 0.6, 0.8), (0.6, 0, 0.8), (0.8, 0, 0.6)]


def interleaved():
    # position, normal, one padding float per vertex: stride 28, normals at byte offset 12.
    # The padding holds a value that would show if the stride were ignored.
    vertices = b"".join(floats([p, n, 1234.5])
                        for p, n in zip(QUAD_POSITIONS, INTERLEAVED_NORMALS))
    gltf = Gltf()
    view = gltf.view(vertices, stride=28, target=ARRAY_BUFFER)
    position = gltf.accessor(view, FLOAT, 4, "VEC3", min=[0, 0, 0], max=[1, 1, 0])
    normal = gltf.accessor(view, FLOAT, 4, "VEC3", byte_offset=12)
    mesh = gltf.mesh([primitive(position, normal, gltf.indices(QUAD_INDICES, UNSIGNED_BYTE))])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


def binary():
    gltf = quad(UNSIGNED_SHORT)
    gltf.doc["nodes"][0]["translation"] = [0, 0, -2]
    return gltf


def negative_scale():
    # The same triangle plain, mirrored in x (with normals) and mirrored in z (flat normals).
    gltf = Gltf()
    position = gltf.positions(TRIANGLE_POSITIONS)
    with_normals = gltf.mesh([primitive(position, gltf.normals([(0, 0, 1)] * 3))])
    without_normals = gltf.mesh([primitive(position)])
    gltf.scene([gltf.node(name="plain", mesh=with_normals),
                gltf.node(name="mirror_x", mesh=with_normals, scale=[-1, 1, 1]),
                gltf.node(name="mirror_z", mesh=without_normals, scale=[1, 1, -1])])
    return gltf


def transforms():
    # Node 0 (T, R, S) and node 1 (the same as a matrix) must agree; node 3 is a rotated child
    # of the translated node 2.
    gltf = Gltf()
    mesh = gltf.mesh([primitive(gltf.positions([(1, 0, 0), (0, 1, 0), (0, 0, 1)]))])
    trs = gltf.node(name="trs", mesh=mesh, translation=[1, 2, 3], rotation=[0, S45, 0, S45],
                    scale=[2, 2, 2])
    matrix = gltf.node(name="matrix", mesh=mesh,
                       matrix=[0, 0, -2, 0, 0, 2, 0, 0, 2, 0, 0, 0, 1, 2, 3, 1])
    child = gltf.node(name="child", mesh=mesh, rotation=[0, 0, S45, S45])
    parent = gltf.node(name="parent", translation=[10, 0, 0], children=[child])
    gltf.scene([trs, matrix, parent])
    return gltf


def materials():
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    gltf.doc["materials"] = [
        {"name": "defaults"},
        {"name": "factors", "doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.25,
         "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 0.125, 0.75],
                                  "metallicFactor": 0.25, "roughnessFactor": 0.5}},
        {"name": "emissive", "emissiveFactor": [1, 0.5, 0.25],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
        {"name": "blend", "alphaMode": "BLEND"},
    ]
    position = gltf.positions(TRIANGLE_POSITIONS)
    mesh = gltf.mesh([primitive(position, material=m) for m in (0, 1, 2, 3, None)])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


def instancing_attributes(gltf, translations, rotations=None, scales=None,
                          rotation_type=SHORT):
    """EXT_mesh_gpu_instancing attributes: float TRANSLATION and SCALE, ROTATION as normalized
    `rotation_type` (x, y, z, w) or FLOAT."""
    attributes = {"TRANSLATION": gltf.accessor(gltf.view(floats(translations)), FLOAT,
                                               len(translations), "VEC3")}
    if rotations is not None:
        if rotation_type == FLOAT:
            attributes["ROTATION"] = gltf.accessor(gltf.view(floats(rotations)), FLOAT,
                                                   len(rotations), "VEC4")
        else:
            code, peak = {SHORT: ("h", 32767), BYTE: ("b", 127),
                          UNSIGNED_BYTE: ("B", 255)}[rotation_type]
            values = [round(c * peak) for q in rotations for c in q]
            data = struct.pack("<%d%s" % (len(values), code), *values)
            attributes["ROTATION"] = gltf.accessor(gltf.view(data), rotation_type,
                                                   len(rotations), "VEC4", normalized=True)
    if scales is not None:
        attributes["SCALE"] = gltf.accessor(gltf.view(floats(scales)), FLOAT, len(scales),
                                            "VEC3")
    return {"EXT_mesh_gpu_instancing": {"attributes": attributes}}


def instancing():
    # One triangle mesh placed six times: by two nodes, a mirrored node, and three
    # EXT_mesh_gpu_instancing instances under a translated node; an emissive quad mesh placed by
    # two nodes (emitters are flattened at every placement).
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    gltf.doc["materials"] = [{"name": "grey"},
                             {"name": "light", "emissiveFactor": [1, 1, 1]}]
    position = gltf.positions(TRIANGLE_POSITIONS)
    triangle_mesh = gltf.mesh([primitive(position, gltf.normals([(0, 0, 1)] * 3), material=0)],
                              name="triangle")
    quad_mesh = gltf.mesh([primitive(gltf.positions(QUAD_POSITIONS), gltf.normals(QUAD_NORMALS),
                                     gltf.indices(QUAD_INDICES), material=1)], name="lamp")
    extension = instancing_attributes(
        gltf, [(0, 0, 0), (2, 0, 0), (0, 3, 0)],
        [(0, 0, 0, 1), (0, 0, S45, S45), (S45, 0, 0, S45)], [(1, 1, 1), (2, 2, 2), (1, 0.5, 1)])
    nodes = [gltf.node(name="plain", mesh=triangle_mesh),
             gltf.node(name="moved", mesh=triangle_mesh, translation=[0, 0, -4],
                       rotation=[0, S45, 0, S45]),
             gltf.node(name="mirrored", mesh=triangle_mesh, scale=[-1, 1, 1]),
             gltf.node(name="instanced", mesh=triangle_mesh, translation=[10, 0, 0],
                       extensions=extension),
             gltf.node(name="lamp_a", mesh=quad_mesh, translation=[0, 5, 0]),
             gltf.node(name="lamp_b", mesh=quad_mesh, translation=[3, 5, 0])]
    gltf.scene(nodes)
    return gltf


def instancing_far():
    # A triangle mesh whose vertices lie a million units from its own origin, placed by two
    # nodes that bring it back near the world's: kept once, it is measured from its centre.
    gltf = Gltf()
    far = [(1e6 + x, y, z) for x, y, z in TRIANGLE_POSITIONS]
    mesh = gltf.mesh([primitive(gltf.positions(far))], name="far")
    gltf.scene([gltf.node(name="near_a", mesh=mesh, translation=[-1e6, 0, 0]),
                gltf.node(name="near_b", mesh=mesh, translation=[-1e6, 2, 0])])
    return gltf


def default_scene():
    gltf = Gltf()
    mesh = gltf.mesh([primitive(gltf.positions(TRIANGLE_POSITIONS))])
    hidden = gltf.node(name="in_scene_0", mesh=mesh)
    shown = gltf.node(name="in_scene_1", mesh=mesh, translation=[0, 0, 5])
    gltf.doc["scenes"] = [{"nodes": [hidden]}, {"nodes": [shown]}]
    gltf.doc["scene"] = 1
    return gltf


def cameras():
    # Cameras come in node-walk order: "rotated" (node 1), then "child" (node 4, under a parent
    # rotated 90 degrees about X), with the orthographic one (node 2) between them.
    gltf = Gltf()
    gltf.doc["cameras"] = [
        {"name": "rotated", "type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}},
        {"name": "ortho", "type": "orthographic",
         "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}},
        {"name": "child", "type": "perspective",
         "perspective": {"yfov": 1.0, "znear": 0.1, "aspectRatio": 1.5}},
    ]
    mesh = gltf.mesh([primitive(gltf.positions(TRIANGLE_POSITIONS))])
    geometry = gltf.node(name="geometry", mesh=mesh)
    rotated = gltf.node(name="rotated_camera", camera=0, translation=[1, 2, 3],
                        rotation=[0, S45, 0, S45], scale=[2, 2, 2])
    ortho = gltf.node(name="ortho_camera", camera=1)
    child = gltf.node(name="child_camera", camera=2)
    parent = gltf.node(name="camera_parent", translation=[0, 0, 10], rotation=[S45, 0, 0, S45],
                       children=[child])
    gltf.scene([geometry, rotated, ortho, parent])
    return gltf


def extensions():
    gltf = quad(UNSIGNED_SHORT)
    gltf.doc["extensionsUsed"] = ["KHR_materials_emissive_strength", "EXT_lights_image_based",
                                  "NV_materials_mdl", "EXT_lights_image_based"]
    return gltf


def textured_quad_mesh(gltf, material):
    return primitive(gltf.positions(QUAD_POSITIONS), gltf.normals(QUAD_NORMALS),
                     gltf.indices(QUAD_INDICES), material=material,
                     texcoord=gltf.texcoords(QUAD_TEXCOORDS))


def textured():
    # Material 0 reads image 0 through two textures (one image, decoded once); material 1 has
    # no texture. Primitive 0: the textured quad (float TEXCOORD_0); primitive 1: a triangle
    # at z = 1 without TEXCOORD_0; primitives 2 and 3: triangles at z = 2 and 3 with normalized
    # UNSIGNED_BYTE and UNSIGNED_SHORT TEXCOORD_0. Image 1 is no PNG at all, but no material
    # uses its texture, so it is never decoded.
    gltf = Gltf()
    gltf.doc["samplers"] = [{"magFilter": NEAREST, "minFilter": LINEAR,
                             "wrapS": CLAMP_TO_EDGE, "wrapT": MIRRORED_REPEAT}]
    gltf.doc["images"] = [{"name": "texels", "uri": data_uri(TEXTURE_PNG, "image/png")},
                          {"name": "unused", "uri": data_uri(b"not an image", "image/png")}]
    gltf.doc["textures"] = [{"sampler": 0, "source": 0}, {"source": 0}, {"source": 1}]
    gltf.doc["materials"] = [
        {"name": "textured", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}}},
        {"name": "plain"},
    ]
    lifted = [[(x, y, z) for x, y, _ in TRIANGLE_POSITIONS] for z in (1, 2, 3)]
    prims = [textured_quad_mesh(gltf, 0),
             primitive(gltf.positions(lifted[0]), material=1),
             primitive(gltf.positions(lifted[1]), material=1,
                       texcoord=gltf.texcoords([(255, 0), (0, 255), (51, 102)], UNSIGNED_BYTE)),
             primitive(gltf.positions(lifted[2]), material=1,
                       texcoord=gltf.texcoords([(65535, 13107), (0, 0), (32768, 65535)],
                                               UNSIGNED_SHORT))]
    gltf.scene([gltf.node(mesh=gltf.mesh(prims))])
    return gltf


def textured_glb():
    # The image in a buffer view of the BIN chunk, as exporters write .glb files.
    gltf = Gltf()
    image_view = gltf.view(TEXTURE_PNG)
    gltf.doc["images"] = [{"bufferView": image_view, "mimeType": "image/png"}]
    gltf.doc["textures"] = [{"source": 0}]
    gltf.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                              "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1]}]
    gltf.scene([gltf.node(mesh=gltf.mesh([textured_quad_mesh(gltf, 0)]))])
    return gltf


def texture_transform():
    # The image as an external file (texture_3x2.png). Emissive: offset (0.5, 0.25), rotation
    # pi/2, scale (2, 3). Base colour: the extension's texCoord 0 overrides the textureInfo's 1.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_texture_transform"]
    gltf.doc["images"] = [{"uri": "texture_3x2.png"}]
    gltf.doc["textures"] = [{"source": 0}]
    transform = {"offset": [0.5, 0.25], "rotation": math.pi / 2, "scale": [2, 3]}
    gltf.doc["materials"] = [{
        "pbrMetallicRoughness": {"baseColorTexture": {
            "index": 0, "texCoord": 1,
            "extensions": {"KHR_texture_transform": {"scale": [4, 4], "texCoord": 0}}}},
        "emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": transform}},
        "emissiveFactor": [1, 1, 1]}]
    gltf.scene([gltf.node(mesh=gltf.mesh([textured_quad_mesh(gltf, 0)]))])
    return gltf


def write_texture_transform(path, gltf):
    write(path.parent / "texture_3x2.png", TEXTURE_PNG)
    write_embedded(path, gltf)


def sphere_shapes():
    """KHR_implicit_shapes: shape 0 a sphere of radius 0.5, shape 1 a box."""
    return {"shapes": [{"type": "sphere", "sphere": {"radius": 0.5}},
                       {"type": "box", "box": {"size": [1, 1, 1]}}]}


def collider(shape):
    return {"KHR_physics_rigid_bodies": {"collider": {"geometry": {"shape": shape}}}}


def spheres():
    # Node "own": vkpt's reference, scale 2 at (1, 2, 3), material 1 (emissive): radius 1.
    # Node "collider": a mesh-less collider under a parent at (0, 0, -10), rotated and scaled
    # by -3 on every axis: centre (0, 0, -10), radius 1.5, the default material.
    # Not drawn: a collider on a node with a mesh, a box collider, a zero-scale sphere.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_implicit_shapes", "KHR_physics_rigid_bodies"]
    gltf.doc["extensions"] = {"KHR_implicit_shapes": sphere_shapes()}
    gltf.doc["materials"] = [{"name": "floor", "pbrMetallicRoughness": {"metallicFactor": 0}},
                             {"name": "glowing", "emissiveFactor": [1, 1, 1],
                              "pbrMetallicRoughness": {"metallicFactor": 0}}]
    floor = gltf.mesh([primitive(gltf.positions(QUAD_POSITIONS), indices=gltf.indices(QUAD_INDICES),
                                 material=0)])
    own = gltf.node(name="own", translation=[1, 2, 3], scale=[2, 2, 2],
                    extensions={"KHR_implicit_shapes": {"shape": 0}},
                    extras={"vkpt_material": 1})
    inner = gltf.node(name="collider", rotation=[0, S45, 0, S45], scale=[-3, -3, -3],
                      extensions=collider(0))
    parent = gltf.node(name="parent", translation=[0, 0, -10], children=[inner])
    with_mesh = gltf.node(name="collider_with_mesh", mesh=floor, extensions=collider(0))
    box = gltf.node(name="box_collider", extensions=collider(1))
    disabled = gltf.node(name="zero_scale", scale=[0, 0, 0],
                         extensions={"KHR_implicit_shapes": {"shape": 0}})
    gltf.scene([own, parent, with_mesh, box, disabled])
    return gltf


def sphere_only():
    # No triangles at all: a scene all the same.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_implicit_shapes"]
    gltf.doc["extensions"] = {"KHR_implicit_shapes": sphere_shapes()}
    gltf.scene([gltf.node(name="ball", extensions={"KHR_implicit_shapes": {"shape": 0}})])
    return gltf


def write_without_buffer(path, gltf):
    write(path, json_text(gltf.doc))


def lights():
    # Point at (1, 2, 3); spot on a node turned +90 degrees about X (its -Z becomes +Y);
    # directional under a parent turned +90 degrees about Y (-Z becomes -X), scaled by 5.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "bulb", "type": "point", "color": [1, 0.5, 0.25], "intensity": 10,
         "range": 5},
        {"name": "stage", "type": "spot", "intensity": 100,
         "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.5}},
        {"name": "sun", "type": "directional", "intensity": 2},
    ]}}
    quad = primitive(gltf.positions(QUAD_POSITIONS), indices=gltf.indices(QUAD_INDICES))
    mesh = gltf.mesh([quad])
    point = gltf.node(name="point", translation=[1, 2, 3],
                      extensions={"KHR_lights_punctual": {"light": 0}})
    spot = gltf.node(name="spot", translation=[0, -1, 0], rotation=[S45, 0, 0, S45],
                     extensions={"KHR_lights_punctual": {"light": 1}})
    sun = gltf.node(name="sun", scale=[5, 5, 5], extensions={"KHR_lights_punctual": {"light": 2}})
    turned = gltf.node(name="turned", rotation=[0, S45, 0, S45], children=[sun])
    gltf.scene([gltf.node(mesh=mesh), point, spot, turned])
    return gltf


def far_away():
    # A triangle, a sphere (radius 0.5, local centre (0, 0, 2)) and a point light (local
    # (0, 3, 0)) under a parent at x = 1e6: their extent, (1e6 - 0.5, -0.5, 0) to
    # (1e6 + 1, 3, 2.5), is recentred to its centre (1e6 + 0.25, 1.25, 1.25).
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_implicit_shapes", "KHR_lights_punctual"]
    gltf.doc["extensions"] = {"KHR_implicit_shapes": sphere_shapes(),
                              "KHR_lights_punctual": {"lights": [{"type": "point"}]}}
    mesh = gltf.mesh([primitive(gltf.positions(TRIANGLE_POSITIONS))])
    children = [gltf.node(name="triangle", mesh=mesh),
                gltf.node(name="ball", translation=[0, 0, 2],
                          extensions={"KHR_implicit_shapes": {"shape": 0}}),
                gltf.node(name="lamp", translation=[0, 3, 0],
                          extensions={"KHR_lights_punctual": {"light": 0}})]
    gltf.scene([gltf.node(name="far", translation=[1e6, 0, 0], children=children)])
    return gltf


def specular():
    # Material 0: metallic 0 and specularFactor 0, Lambertian only, with a specularTexture that
    # multiplies 0. Material 1: specular 0.5, colour (1, 0.5, 0.25), a specularTexture and a
    # specularColorTexture (with a KHR_texture_transform). Material 2: no extension.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_materials_specular", "KHR_texture_transform"]
    gltf.doc["images"] = [{"uri": data_uri(TEXTURE_PNG, "image/png")}]
    gltf.doc["textures"] = [{"source": 0}]
    gltf.doc["materials"] = [
        {"name": "lambert", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0,
                                                   "specularTexture": {"index": 0}}}},
        {"name": "tinted", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {"KHR_materials_specular": {
             "specularFactor": 0.5, "specularColorFactor": [1, 0.5, 0.25],
             "specularTexture": {"index": 0},
             "specularColorTexture": {"index": 0, "extensions": {
                 "KHR_texture_transform": {"offset": [0.5, 0]}}}}}},
        {"name": "core", "pbrMetallicRoughness": {"metallicFactor": 0}},
    ]
    position = gltf.positions(TRIANGLE_POSITIONS)
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position, material=m) for m in (0, 1, 2)]))])
    return gltf


def glass():
    # Material 0: KHR_materials_transmission 0.8 with a transmissionTexture, KHR_materials_ior
    # 1.33 and KHR_materials_volume (thickness 0.5, attenuationColor (0.5, 0.25, 1) after 2, and
    # a thicknessTexture: not read, one note). Material 1: none of them (the defaults).
    # Material 2: ior 0, the extension's "not a dielectric", read as the default 1.5.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_materials_ior", "KHR_materials_transmission",
                                  "KHR_materials_volume"]
    gltf.doc["images"] = [{"uri": data_uri(TEXTURE_PNG, "image/png")}]
    gltf.doc["textures"] = [{"source": 0}]
    gltf.doc["materials"] = [
        {"name": "water", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {
             "KHR_materials_transmission": {"transmissionFactor": 0.8,
                                            "transmissionTexture": {"index": 0}},
             "KHR_materials_ior": {"ior": 1.33},
             "KHR_materials_volume": {"thicknessFactor": 0.5,
                                      "attenuationColor": [0.5, 0.25, 1.0],
                                      "attenuationDistance": 2.0,
                                      "thicknessTexture": {"index": 0}}}},
        {"name": "plain", "pbrMetallicRoughness": {"metallicFactor": 0}},
        {"name": "ior zero", "pbrMetallicRoughness": {"metallicFactor": 0},
         "extensions": {"KHR_materials_ior": {"ior": 0}}},
    ]
    position = gltf.positions(TRIANGLE_POSITIONS)
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position, material=m) for m in (0, 1, 2)]))])
    return gltf


def make_sparse(gltf, accessor, indices, values):
    """Makes `accessor` sparse: its elements `indices` replaced by `values`."""
    gltf.doc["accessors"][accessor]["sparse"] = {
        "count": len(indices),
        "indices": {"bufferView": gltf.view(unsigned(indices, UNSIGNED_SHORT)),
                    "componentType": UNSIGNED_SHORT},
        "values": {"bufferView": gltf.view(floats(values))}}


def sparse():
    # The unit triangle's POSITION with vertex 1 replaced by (2, 0, 0) through a sparse
    # substitution on top of its buffer view.
    gltf = Gltf()
    position = gltf.positions(TRIANGLE_POSITIONS)
    make_sparse(gltf, position, [1], [(2, 0, 0)])
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position)]))])
    return gltf


# Skins, morph targets and animations: small enough that every posed vertex is computed by hand
# in tests/unit/gltf_animation_test.cpp.

IDENTITY_MATRIX = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
# A quad 1 wide and 2 high whose upper corners hang on a second joint at y = 1.
SKIN_POSITIONS = [(0, 0, 0), (1, 0, 0), (0, 2, 0), (1, 2, 0)]
SKIN_INDICES = [0, 1, 3, 0, 3, 2]


def add_skin_attributes(gltf, prim, joints, weights):
    data = bytes(c for j in joints for c in j)
    prim["attributes"]["JOINTS_0"] = gltf.accessor(gltf.view(data, target=ARRAY_BUFFER),
                                                   UNSIGNED_BYTE, len(joints), "VEC4")
    prim["attributes"]["WEIGHTS_0"] = gltf.accessor(
        gltf.view(floats(weights), target=ARRAY_BUFFER), FLOAT, len(weights), "VEC4")


def add_animation(gltf, name, channels):
    """channels: (node, path, interpolation, times, flat output values)."""
    samplers, targets = [], []
    for node, path, interpolation, times, values in channels:
        width = {"translation": 3, "scale": 3, "rotation": 4}.get(path, 1)
        type_ = {1: "SCALAR", 3: "VEC3", 4: "VEC4"}[width]
        input_ = gltf.accessor(gltf.view(floats(times)), FLOAT, len(times), "SCALAR",
                               min=[min(times)], max=[max(times)])
        output = gltf.accessor(gltf.view(floats(values)), FLOAT, len(values) // width, type_)
        targets.append({"sampler": len(samplers), "target": {"node": node, "path": path}})
        samplers.append({"input": input_, "output": output, "interpolation": interpolation})
    animation = {"channels": targets, "samplers": samplers}
    if name:
        animation["name"] = name
    return gltf.add("animations", animation)


def add_normal_map(gltf, prim, tangents):
    """A material with a normal texture (the 3 x 2 PNG) on `prim`, which gets TANGENT and
    TEXCOORD_0, so that the loader keeps the frames it moves."""
    gltf.doc["images"] = [{"uri": data_uri(TEXTURE_PNG, "image/png")}]
    gltf.doc["textures"] = [{"source": 0}]
    gltf.doc["materials"] = [{"name": "bumpy", "normalTexture": {"index": 0},
                              "pbrMetallicRoughness": {"metallicFactor": 0}}]
    prim["material"] = 0
    prim["attributes"]["TEXCOORD_0"] = gltf.texcoords([(0, 0)] * len(tangents))
    prim["attributes"]["TANGENT"] = gltf.accessor(
        gltf.view(floats(tangents), target=ARRAY_BUFFER), FLOAT, len(tangents), "VEC4")


def skin():
    # Joint 0 (node 1) lifts everything by z = 1; joint 1 (node 2, its child at y = 1) turns the
    # quad's top 90 degrees about Z. Vertex 1's single weight of 0.5 is renormalised to 1 (with a
    # note); vertex 3 hangs half on each joint. The skinned node's own translation (5, 0, 0)
    # must be ignored. "bend" turns joint 1 from 0 to 180 degrees over a second (slerp);
    # "lift" steps joint 0 from z = 1 to z = 3 at t = 1; a camera rides on joint 0. Every
    # TANGENT is (1, 0, 0, 1), under a normal-mapped material, so that skinning turns them too.
    gltf = Gltf()
    gltf.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}]
    prim = primitive(gltf.positions(SKIN_POSITIONS), gltf.normals([(0, 0, 1)] * 4),
                     gltf.indices(SKIN_INDICES))
    add_skin_attributes(gltf, prim, [(0, 0, 0, 0), (0, 0, 0, 0), (1, 0, 0, 0), (0, 1, 0, 0)],
                        [(1, 0, 0, 0), (0.5, 0, 0, 0), (1, 0, 0, 0), (0.5, 0.5, 0, 0)])
    add_normal_map(gltf, prim, [(1, 0, 0, 1)] * 4)
    mesh = gltf.mesh([prim])
    inverse_bind = floats(IDENTITY_MATRIX + [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1])
    matrices = gltf.accessor(gltf.view(inverse_bind), FLOAT, 2, "MAT4")
    skinned = gltf.node(name="skinned", mesh=mesh, skin=0, translation=[5, 0, 0])
    bent = gltf.node(name="bent_joint", translation=[0, 1, 0], rotation=[0, 0, S45, S45])
    camera = gltf.node(name="rider", camera=0, translation=[0, 0, 5])
    root = gltf.node(name="root_joint", translation=[0, 0, 1], children=[bent, camera])
    gltf.doc["skins"] = [{"joints": [root, bent], "inverseBindMatrices": matrices,
                          "skeleton": root}]
    add_animation(gltf, "bend", [(bent, "rotation", "LINEAR", [0, 1], [0, 0, 0, 1, 0, 0, 1, 0])])
    add_animation(gltf, "lift", [(root, "translation", "STEP", [0, 1], [0, 0, 1, 0, 0, 3])])
    gltf.scene([skinned, root])
    return gltf


def morph():
    # One triangle with two morph targets placed three times: by the mesh's weights (0.5, 0.25),
    # by node weights (1, 0) at x = 2 and by node weights (0, 0) at x = 4. Target 0 lifts
    # vertex 0 by z = 1 and tilts its normal by (1, 0, -1); target 1 lifts vertex 1 by z = 2.
    # "pulse" moves the first node's weights from (0, 0) to (1, 1) over a second. TANGENT is
    # (1, 0, 0, -1) under a normal-mapped material; target 0 adds (0, 1, 0) to vertex 0's.
    gltf = Gltf()
    prim = primitive(gltf.positions(TRIANGLE_POSITIONS), gltf.normals([(0, 0, 1)] * 3))
    add_normal_map(gltf, prim, [(1, 0, 0, -1)] * 3)
    turn_0 = gltf.normals([(0, 1, 0), (0, 0, 0), (0, 0, 0)])
    lift_0 = gltf.normals([(0, 0, 1), (0, 0, 0), (0, 0, 0)])
    tilt_0 = gltf.normals([(1, 0, -1), (0, 0, 0), (0, 0, 0)])
    # Target 1 is sparse without a buffer view, as exporters store morph targets: zeros but
    # for its element 1.
    lift_1 = gltf.accessor(None, FLOAT, 3, "VEC3")
    make_sparse(gltf, lift_1, [1], [(0, 0, 2)])
    prim["targets"] = [{"POSITION": lift_0, "NORMAL": tilt_0, "TANGENT": turn_0},
                       {"POSITION": lift_1}]
    mesh = gltf.mesh([prim])
    gltf.doc["meshes"][mesh]["weights"] = [0.5, 0.25]
    by_mesh = gltf.node(name="mesh_weights", mesh=mesh)
    by_node = gltf.node(name="node_weights", mesh=mesh, weights=[1, 0], translation=[2, 0, 0])
    at_rest = gltf.node(name="zero_weights", mesh=mesh, weights=[0, 0], translation=[4, 0, 0])
    add_animation(gltf, "pulse", [(by_mesh, "weights", "LINEAR", [0, 1], [0, 0, 1, 1])])
    gltf.scene([by_mesh, by_node, at_rest])
    return gltf


def unlit():
    # A unit quad seen by a camera 2 above it along +Z (yfov 0.2: the quad fills the view).
    # Material 0: KHR_materials_unlit, orange (1, 0.25, 0) with a specular extension and a normal
    # texture that an unlit surface does not read. Material 1: unlit with the test image as base
    # colour texture and alphaMode MASK. Material 2: unlit, blue, double-sided.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_materials_specular", "KHR_materials_unlit"]
    gltf.doc["extensionsRequired"] = ["KHR_materials_unlit"]
    gltf.doc["images"] = [{"uri": data_uri(TEXTURE_PNG, "image/png")}]
    gltf.doc["textures"] = [{"source": 0}]
    gltf.doc["materials"] = [
        {"name": "orange", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.25, 0, 1]},
         "normalTexture": {"index": 0},
         "extensions": {"KHR_materials_unlit": {},
                        "KHR_materials_specular": {"specularFactor": 0.5}}},
        {"name": "cut out", "alphaMode": "MASK",
         "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1],
                                  "baseColorTexture": {"index": 0}},
         "extensions": {"KHR_materials_unlit": {}}},
        {"name": "blue", "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1]},
         "extensions": {"KHR_materials_unlit": {}}},
    ]
    gltf.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.2, "znear": 0.1}}]
    position = gltf.positions(QUAD_POSITIONS)
    normal = gltf.normals(QUAD_NORMALS)
    texcoord = gltf.texcoords(QUAD_TEXCOORDS)
    index = gltf.indices(QUAD_INDICES)
    quads = [primitive(position, normal, index, material=m, texcoord=texcoord) for m in (1, 2)]
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position, normal, index, material=0)])),
                gltf.node(mesh=gltf.mesh(quads), translation=[0, 0, -5]),
                gltf.node(camera=0, translation=[0.5, 0.5, 2])])
    return gltf


def variants():
    # Three variants; mesh 0's primitive maps variant 0 ("red") to material 1 and variants 1
    # and 2 to material 2, and has material 0 of its own; mesh 1's primitive has no mapping.
    gltf = Gltf()
    gltf.doc["extensionsUsed"] = ["KHR_materials_variants"]
    gltf.doc["extensions"] = {"KHR_materials_variants": {
        "variants": [{"name": "red"}, {"name": "green"}, {"name": "2"}]}}
    gltf.doc["materials"] = [
        {"name": "default", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
        {"name": "green", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1]}},
    ]
    position = gltf.positions(TRIANGLE_POSITIONS)
    mapped = primitive(position, material=0)
    mapped["extensions"] = {"KHR_materials_variants": {"mappings": [
        {"material": 1, "variants": [0]}, {"material": 2, "variants": [1, 2]}]}}
    gltf.scene([gltf.node(mesh=gltf.mesh([mapped])),
                gltf.node(mesh=gltf.mesh([primitive(position, material=0)]))])
    return gltf


VALID_SCENES = [
    # (file, builder, writer, what it exercises)
    ("indices_u8.gltf", lambda: quad(UNSIGNED_BYTE), write_embedded,
     "unit quad, UNSIGNED_BYTE indices"),
    ("indices_u16.gltf", lambda: quad(UNSIGNED_SHORT), write_external,
     "unit quad, UNSIGNED_SHORT indices, external indices_u16.bin"),
    ("indices_u32.gltf", lambda: quad(UNSIGNED_INT), write_embedded,
     "unit quad, UNSIGNED_INT indices"),
    ("non_indexed.gltf", non_indexed, write_embedded, "unit quad without indices"),
    ("no_normals.gltf", no_normals, write_embedded,
     "slanted triangle without NORMAL: flat normal (1, 1, 1) / sqrt(3)"),
    ("interleaved.gltf", interleaved, write_embedded,
     "unit quad, POSITION and NORMAL interleaved with padding (byteStride 28)"),
    ("binary.glb", binary, write_glb, "unit quad in a .glb, translated to z = -2"),
    ("negative_scale.gltf", negative_scale, write_embedded,
     "a triangle plain, mirrored in x and mirrored in z (winding flip)"),
    ("transforms.gltf", transforms, write_embedded,
     "T/R/S node and the same as a matrix; a rotated child of a translated parent"),
    ("materials.gltf", materials, write_embedded,
     "material factors, emissive strength, alpha modes, a primitive without material"),
    ("default_scene.gltf", default_scene, write_embedded, "two scenes, `scene` selects the second"),
    ("cameras.gltf", cameras, write_embedded,
     "perspective cameras on rotated and child nodes, an orthographic camera between them"),
    ("extensions.gltf", extensions, write_embedded,
     "extensionsUsed with supported, unsupported and repeated entries"),
    ("textured.gltf", textured, write_embedded,
     "a base colour and metallic-roughness texture of one 3 x 2 PNG (data URI); float, "
     "UNSIGNED_BYTE and UNSIGNED_SHORT TEXCOORD_0 and none; an unused undecodable image"),
    ("textured.glb", textured_glb, write_glb, "the textured quad with its PNG in a buffer view"),
    ("texture_transform.gltf", texture_transform, write_texture_transform,
     "KHR_texture_transform on two textures of the external texture_3x2.png"),
    ("spheres.gltf", spheres, write_embedded,
     "KHR_implicit_shapes spheres: vkpt's own reference and a physics collider; shapes not drawn"),
    ("sphere_only.gltf", sphere_only, write_without_buffer, "one sphere and no triangles"),
    ("lights.gltf", lights, write_embedded, "KHR_lights_punctual point, spot, directional lights"),
    ("far_away.gltf", far_away, write_embedded,
     "a triangle, a sphere and a point light 1e6 from the origin: recentred together"),
    ("specular.gltf", specular, write_embedded, "KHR_materials_specular factors and textures"),
    ("glass.gltf", glass, write_embedded,
     "KHR_materials_transmission, KHR_materials_ior and KHR_materials_volume"),
    ("skin.gltf", skin, write_embedded,
     "a quad skinned to two joints, one bent 90 degrees; two animations and a camera on a joint"),
    ("morph.gltf", morph, write_embedded,
     "a triangle with two morph targets (one sparse) under mesh weights, node weights and a "
     "weights animation"),
    ("sparse.gltf", sparse, write_embedded, "a triangle whose sparse POSITION moves vertex 1"),
    ("unlit.gltf", unlit, write_embedded,
     "KHR_materials_unlit: a plain, a textured alpha-masked and a double-sided material"),
    ("variants.gltf", variants, write_embedded,
     "KHR_materials_variants: three variants, a mapped primitive and an unmapped one"),
    ("instancing.gltf", instancing, write_embedded,
     "a triangle mesh placed by two nodes, a mirrored node and three EXT_mesh_gpu_instancing "
     "instances; an emissive quad mesh placed twice"),
    ("instancing_far.gltf", instancing_far, write_embedded,
     "a triangle mesh 1e6 from its own origin, placed near the world's origin by two nodes"),
]


def write_readme(directory, title, rows):
    lines = ["# " + title, "",
             "Generated by `scenes/generate_loader_scenes.py`; do not edit by hand.", "",
             "| File | What it holds |", "|---|---|"]
    lines += ["| `%s` | %s |" % (name, text) for name, text in rows]
    write(directory / "README.md", "\n".join(lines) + "\n")


def write_valid_scenes():
    for name, build, writer, _ in VALID_SCENES:
        writer(LOADER_DIR / name, build())
    write_readme(LOADER_DIR, "Loader test scenes (valid)",
                 [(name, text) for name, _, _, text in VALID_SCENES] +
                 [("texture_3x2.png", "the image of `texture_transform.gltf`")])


# --------------------------------------------------------------------------------------------
# Invalid scenes: each starts from one good triangle and breaks one thing.


DEFAULT = object()


def triangle(normal=DEFAULT, indices=DEFAULT, **fields):
    """Accessor and buffer view 0 are POSITION, 1 NORMAL, 2 indices (unless left out)."""
    gltf = Gltf()
    position = gltf.positions(TRIANGLE_POSITIONS)
    if normal is DEFAULT:
        normal = gltf.normals([(0, 0, 1)] * 3)
    if indices is DEFAULT:
        indices = gltf.indices([0, 1, 2])
    mesh = gltf.mesh([primitive(position, normal, indices, **fields)])
    gltf.scene([gltf.node(mesh=mesh)])
    return gltf


def glb_of(gltf):
    return glb_bytes(gltf.doc, gltf.finish_buffer())


def embedded_text(gltf):
    gltf.embed_buffer()
    return json_text(gltf.doc)


def garbage():
    # Deterministic noise that starts like nothing in particular.
    state, out = 12345, bytearray()
    for _ in range(256):
        state = (state * 1103515245 + 12345) % (1 << 31)
        out.append(state >> 23)
    return bytes(out)


def missing_buffer():
    gltf = triangle()
    gltf.finish_buffer(uri="missing_buffer.bin")
    return json_text(gltf.doc)


def short_buffer():
    """The .bin is 12 bytes shorter than the buffer's byteLength."""
    gltf = triangle()
    data = gltf.finish_buffer(uri="short_buffer.bin")
    write(INVALID_DIR / "short_buffer.bin", data[:-12])
    return json_text(gltf.doc)


def short_bin_chunk():
    gltf = triangle()
    data = gltf.finish_buffer()
    gltf.doc["buffers"][0]["byteLength"] = len(data) + 64
    return glb_bytes(gltf.doc, data)


def buffer_view_out_of_range():
    gltf = triangle()
    gltf.doc["bufferViews"][0]["byteLength"] += 4
    gltf.doc["bufferViews"][0]["byteOffset"] = 100
    return embedded_text(gltf)


def accessor_out_of_range():
    gltf = triangle(normal=None, indices=None)
    gltf.doc["accessors"][0]["count"] = 4
    return embedded_text(gltf)


def stride_too_small():
    gltf = triangle()
    gltf.doc["bufferViews"][0]["byteStride"] = 8
    return embedded_text(gltf)


def index_out_of_range():
    # The bad index is in mesh 1, primitive 1, so that the message must name the right place.
    gltf = triangle()
    position = gltf.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
    good = primitive(position, indices=gltf.indices([2, 1, 0]))
    bad = primitive(position, indices=gltf.indices([0, 1, 3]))
    mesh = gltf.mesh([good, bad])
    gltf.doc["scenes"][0]["nodes"].append(gltf.node(mesh=mesh))
    return embedded_text(gltf)


def nan_position():
    gltf = Gltf()
    nan = struct.unpack("<f", struct.pack("<I", 0x7FC00000))[0]
    view = gltf.view(floats([(0, 0, 0), (1, 0, 0), (0, nan, 0)]), target=ARRAY_BUFFER)
    position = gltf.accessor(view, FLOAT, 3, "VEC3")
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position)]))])
    return embedded_text(gltf)


def points_mode():
    return embedded_text(triangle(mode=POINTS))


def position_not_float():
    gltf = Gltf()
    view = gltf.view(unsigned([0, 0, 0, 1, 0, 0, 0, 1, 0], UNSIGNED_SHORT), target=ARRAY_BUFFER)
    position = gltf.accessor(view, UNSIGNED_SHORT, 3, "VEC3")
    gltf.scene([gltf.node(mesh=gltf.mesh([primitive(position)]))])
    return embedded_text(gltf)


def indices_not_integer():
    gltf = triangle(normal=None, indices=None)
    view = gltf.view(floats([0, 1, 2]), target=ELEMENT_ARRAY_BUFFER)
    gltf.doc["meshes"][0]["primitives"][0]["indices"] = gltf.accessor(view, FLOAT, 3, "SCALAR")
    return embedded_text(gltf)


def no_position():
    gltf = triangle()
    attributes = gltf.doc["meshes"][0]["primitives"][0]["attributes"]
    del attributes["POSITION"]
    return embedded_text(gltf)


def sparse_index_out_of_range():
    gltf = triangle(normal=None, indices=None)
    make_sparse(gltf, 0, [5], [(2, 0, 0)])
    return embedded_text(gltf)


def no_triangles():
    gltf = triangle()
    gltf.doc["nodes"].append({"name": "empty"})
    gltf.doc["scenes"][0]["nodes"] = [1]
    return embedded_text(gltf)


def required_extension():
    gltf = triangle()
    unknown = ["KHR_texture_basisu", "EXT_lights_image_based"]
    gltf.doc["extensionsUsed"] = unknown
    gltf.doc["extensionsRequired"] = unknown
    return embedded_text(gltf)


def node_cycle():
    gltf = triangle()
    gltf.doc["nodes"][0]["children"] = [1]
    gltf.doc["nodes"].append({"name": "loops_back", "children": [0]})
    return embedded_text(gltf)


def missing_node():
    gltf = triangle()
    gltf.doc["nodes"].append({"name": "empty"})
    gltf.doc["scenes"][0]["nodes"] = [0, 1, 7]
    return embedded_text(gltf)


def missing_material():
    gltf = triangle(material=3)
    gltf.doc["materials"] = [{"name": "first"}, {"name": "second"}]
    return embedded_text(gltf)


def partial_triangle():
    gltf = triangle()
    gltf.doc["meshes"][0]["primitives"][0]["indices"] = gltf.indices([0, 1, 2, 0])
    return embedded_text(gltf)


def normal_count_mismatch():
    gltf = triangle()
    gltf.doc["accessors"][1]["count"] = 2  # NORMAL
    return embedded_text(gltf)


def missing_accessor():
    gltf = triangle()
    gltf.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7
    return embedded_text(gltf)


def glass_material_scene(extensions):
    gltf = triangle(material=0)
    gltf.doc["extensionsUsed"] = sorted(extensions)
    gltf.doc["materials"] = [{"pbrMetallicRoughness": {"metallicFactor": 0},
                              "extensions": extensions}]
    return embedded_text(gltf)


def variant_out_of_range():
    gltf = triangle(material=0)
    gltf.doc["extensionsUsed"] = ["KHR_materials_variants"]
    gltf.doc["extensions"] = {"KHR_materials_variants": {"variants": [{"name": "only"}]}}
    gltf.doc["materials"] = [{}, {}]
    gltf.doc["meshes"][0]["primitives"][0]["extensions"] = {"KHR_materials_variants": {
        "mappings": [{"material": 1, "variants": [0, 3]}]}}
    return embedded_text(gltf)


def light_scene(light):
    gltf = triangle()
    gltf.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
    gltf.doc["scenes"][0]["nodes"].append(
        gltf.node(name="lamp", extensions={"KHR_lights_punctual": {"light": 0}}))
    return embedded_text(gltf)


def sphere_non_uniform_scale():
    gltf = triangle()
    gltf.doc["extensionsUsed"] = ["KHR_implicit_shapes"]
    gltf.doc["extensions"] = {"KHR_implicit_shapes": sphere_shapes()}
    gltf.doc["scenes"][0]["nodes"].append(
        gltf.node(name="egg", scale=[1, 2, 1], extensions={"KHR_implicit_shapes": {"shape": 0}}))
    return embedded_text(gltf)


def uses(gltf, *extensions, required=True):
    gltf.doc["extensionsUsed"] = list(extensions)
    if required:
        gltf.doc["extensionsRequired"] = list(extensions)


def draco_corrupt():
    """A Draco primitive whose compressed view holds bytes that are not a Draco stream."""
    gltf = Gltf()
    compressed = gltf.view(b"DRACO" + bytes(range(1, 28)))
    position = gltf.accessor(None, FLOAT, 3, "VEC3", min=[0, 0, 0], max=[1, 1, 0])
    indices = gltf.accessor(None, UNSIGNED_SHORT, 3, "SCALAR")
    draco = {"bufferView": compressed, "attributes": {"POSITION": 0}}
    prim = primitive(position, indices=indices)
    prim["extensions"] = {"KHR_draco_mesh_compression": draco}
    gltf.scene([gltf.node(mesh=gltf.mesh([prim]))])
    uses(gltf, "KHR_draco_mesh_compression")
    return embedded_text(gltf)


def meshopt_scene(compressed, count, stride, mode="ATTRIBUTES", filter_=None):
    """The triangle with POSITION in buffer view 0 of a fallback buffer (buffer 1), compressed
    as `compressed` in buffer 0; index data stays uncompressed."""
    gltf = triangle(normal=None)
    position_view = gltf.doc["bufferViews"][0]
    source = gltf.view(compressed)
    meshopt = {"buffer": 0, "byteOffset": gltf.doc["bufferViews"][source].get("byteOffset", 0),
               "byteLength": len(compressed), "byteStride": stride, "count": count, "mode": mode}
    if filter_ is not None:
        meshopt["filter"] = filter_
    gltf.embed_buffer()
    gltf.doc["buffers"].append({"byteLength": 64,
                                "extensions": {"EXT_meshopt_compression": {"fallback": True}}})
    position_view.update({"buffer": 1, "byteOffset": 0, "byteStride": stride,
                          "extensions": {"EXT_meshopt_compression": meshopt}})
    uses(gltf, "EXT_meshopt_compression")
    return json_text(gltf.doc)


def meshopt_uncompressed_fallback_view():
    gltf = triangle(normal=None)
    gltf.embed_buffer()
    gltf.doc["buffers"].append({"byteLength": 36,
                                "extensions": {"EXT_meshopt_compression": {"fallback": True}}})
    gltf.doc["bufferViews"][0].update({"buffer": 1, "byteOffset": 0})
    uses(gltf, "EXT_meshopt_compression")
    return json_text(gltf.doc)


def quantized_normal_not_normalized():
    gltf = triangle(normal=None)
    view = gltf.view(struct.pack("<12b", 0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0),
                     stride=4, target=ARRAY_BUFFER)
    normal = gltf.accessor(view, BYTE, 3, "VEC3")
    gltf.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = normal
    uses(gltf, "KHR_mesh_quantization")
    return embedded_text(gltf)


def textured_triangle(image, texture=None, texture_info=None):
    """The triangle with TEXCOORD_0 and material 0 reading texture 0 of image 0."""
    gltf = triangle(material=0)
    attributes = gltf.doc["meshes"][0]["primitives"][0]["attributes"]
    attributes["TEXCOORD_0"] = gltf.texcoords([(0, 0), (1, 0), (0, 1)])
    gltf.doc["images"] = [image]
    gltf.doc["textures"] = [texture if texture is not None else {"source": 0}]
    info = {"index": 0}
    info.update(texture_info or {})
    gltf.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": info}}]
    return embedded_text(gltf)


def instanced_triangle(extension):
    gltf = triangle()
    gltf.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    gltf.doc["nodes"][0]["extensions"] = extension
    return gltf


def instancing_count_mismatch():
    gltf = triangle()
    extension = instancing_attributes(gltf, [(0, 0, 0), (1, 0, 0), (2, 0, 0)],
                                      scales=[(1, 1, 1), (1, 1, 1)])
    gltf.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    gltf.doc["nodes"][0]["extensions"] = extension
    return embedded_text(gltf)


def instancing_without_attributes():
    return embedded_text(instanced_triangle({"EXT_mesh_gpu_instancing": {"attributes": {}}}))


def instancing_zero_rotation():
    gltf = triangle()
    extension = instancing_attributes(gltf, [(0, 0, 0), (1, 0, 0)], [(0, 0, 0, 1), (0, 0, 0, 0)],
                                      rotation_type=FLOAT)
    gltf.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    gltf.doc["nodes"][0]["extensions"] = extension
    return embedded_text(gltf)


def instancing_rotation_unsigned():
    gltf = triangle()
    extension = instancing_attributes(gltf, [(0, 0, 0)], [(0, 0, 0, 1)],
                                      rotation_type=UNSIGNED_BYTE)
    gltf.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    gltf.doc["nodes"][0]["extensions"] = extension
    return embedded_text(gltf)


def skinned_triangle(joints=((0, 0, 0, 0),) * 3, weights=((1, 0, 0, 0),) * 3, joint_nodes=(1, 2),
                     matrices=2, attributes=True):
    """triangle() skinned by skin 0, whose joints are the empty nodes 1 and 2 (unless told)."""
    gltf = triangle()
    if attributes:
        add_skin_attributes(gltf, gltf.doc["meshes"][0]["primitives"][0], joints, weights)
    gltf.doc["nodes"][0]["skin"] = 0
    gltf.doc["nodes"] += [{"name": "joint_a"}, {"name": "joint_b"}]
    gltf.doc["scenes"][0]["nodes"] = [0, 1, 2]
    inverse_bind = gltf.accessor(gltf.view(floats(IDENTITY_MATRIX * matrices)), FLOAT, matrices,
                                 "MAT4")
    gltf.doc["skins"] = [{"joints": list(joint_nodes), "inverseBindMatrices": inverse_bind}]
    return gltf


def skin_missing():
    gltf = skinned_triangle()
    gltf.doc["nodes"][0]["skin"] = 4
    return embedded_text(gltf)


def morph_weight_count():
    gltf = triangle()
    lift = gltf.normals([(0, 0, 1)] * 3)
    gltf.doc["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": lift}, {"POSITION": lift}]
    gltf.doc["meshes"][0]["weights"] = [0.5, 0.5, 0.5]
    return embedded_text(gltf)


def animated_triangle(path="translation", interpolation="LINEAR", times=(0, 1),
                      values=(0, 0, 0, 1, 0, 0), node=0):
    """triangle() with one animation of one channel, and a second, empty node."""
    gltf = triangle()
    gltf.doc["nodes"].append({"name": "empty"})
    add_animation(gltf, None, [(node, path, interpolation, list(times), list(values))])
    return gltf


def animation_matrix_node():
    gltf = animated_triangle()
    gltf.doc["nodes"][0]["matrix"] = IDENTITY_MATRIX
    return embedded_text(gltf)


def write_invalid_scenes():
    good_glb = glb_of(triangle())
    files = [
        # (file, bytes or text, what is broken)
        ("empty.glb", b"", "zero bytes"),
        ("not_gltf.gltf", "This is not a glTF file.\n", "plain text"),
        ("garbage.glb", garbage(), "noise without the glTF magic"),
        ("no_asset.gltf", json_text({"scenes": [{"nodes": []}]}), "JSON without `asset`"),
        ("truncated.glb", good_glb[: len(good_glb) // 2], "a .glb cut in half"),
        ("missing_buffer.gltf", missing_buffer(), "its .bin does not exist"),
        ("short_buffer.gltf", short_buffer(), "its .bin is shorter than byteLength"),
        ("short_bin_chunk.glb", short_bin_chunk(), "BIN chunk shorter than byteLength"),
        ("buffer_view_out_of_range.gltf", buffer_view_out_of_range(),
         "a buffer view past the end of its buffer"),
        ("accessor_out_of_range.gltf", accessor_out_of_range(),
         "an accessor past the end of its buffer view"),
        ("stride_too_small.gltf", stride_too_small(), "byteStride smaller than an element"),
        ("index_out_of_range.gltf", index_out_of_range(),
         "index 3 of 3 vertices, in mesh 1, primitive 1"),
        ("nan_position.gltf", nan_position(), "a NaN vertex position"),
        ("points_mode.gltf", points_mode(), "a POINTS primitive"),
        ("position_not_float.gltf", position_not_float(), "UNSIGNED_SHORT positions"),
        ("indices_not_integer.gltf", indices_not_integer(), "FLOAT indices"),
        ("no_position.gltf", no_position(), "a primitive without POSITION"),
        ("sparse_index_out_of_range.gltf", sparse_index_out_of_range(),
         "a sparse POSITION accessor that replaces element 5 of 3"),
        ("no_triangles.gltf", no_triangles(), "a scene whose only node has no mesh"),
        ("required_extension.gltf", required_extension(),
         "requires two extensions vkpt does not implement"),
        ("node_cycle.gltf", node_cycle(), "node 0 is its own grandchild"),
        ("instancing_count_mismatch.gltf", instancing_count_mismatch(),
         "EXT_mesh_gpu_instancing with 3 translations and 2 scales"),
        ("instancing_without_attributes.gltf", instancing_without_attributes(),
         "EXT_mesh_gpu_instancing with an empty attributes object"),
        ("instancing_zero_rotation.gltf", instancing_zero_rotation(),
         "EXT_mesh_gpu_instancing instance 1 rotated by the zero quaternion"),
        ("instancing_rotation_unsigned.gltf", instancing_rotation_unsigned(),
         "EXT_mesh_gpu_instancing ROTATION of normalized UNSIGNED_BYTE"),
        ("missing_node.gltf", missing_node(), "the scene lists node 7 of 2"),
        ("skin_joint_out_of_range.gltf",
         embedded_text(skinned_triangle(joints=((0, 0, 0, 0), (3, 0, 0, 0), (0, 0, 0, 0)))),
         "a vertex weighted on joint 3 of a 2-joint skin"),
        ("skin_joint_not_a_node.gltf", embedded_text(skinned_triangle(joint_nodes=(1, 9))),
         "a skin whose second joint is node 9 of 3"),
        ("skin_bind_matrix_count.gltf",
         embedded_text(skinned_triangle(joint_nodes=(1, 2, 0), matrices=2)),
         "2 inverse bind matrices for 3 joints"),
        ("skin_without_joints.gltf", embedded_text(skinned_triangle(attributes=False)),
         "a skinned node whose primitive has no JOINTS_0 and WEIGHTS_0"),
        ("skin_zero_weights.gltf", embedded_text(skinned_triangle(
            weights=((1, 0, 0, 0), (1, 0, 0, 0), (0, 0, 0, 0)))),
         "a skinned vertex whose weights are all zero"),
        ("skin_missing.gltf", skin_missing(), "a node with skin 4 of 1"),
        ("morph_weight_count.gltf", morph_weight_count(), "3 mesh weights for 2 morph targets"),
        ("animation_times_decrease.gltf",
         embedded_text(animated_triangle(times=(0, 1, 0.5), values=(0,) * 9)),
         "an animation sampler whose input times go back"),
        ("animation_output_count.gltf", embedded_text(animated_triangle(values=(0,) * 9)),
         "3 translations for 2 keyframes"),
        ("animation_interpolation.gltf", embedded_text(animated_triangle(interpolation="SMOOTH")),
         "a sampler with interpolation SMOOTH"),
        ("animation_matrix_node.gltf", animation_matrix_node(),
         "a translation channel on a node with a matrix"),
        ("animation_missing_node.gltf", embedded_text(animated_triangle(node=5)),
         "a channel targeting node 5 of 2"),
        ("animation_weights_without_targets.gltf",
         embedded_text(animated_triangle(path="weights", values=(0, 1))),
         "a weights channel on a mesh without morph targets"),
        ("missing_material.gltf", missing_material(), "material 3 of 2"),
        ("partial_triangle.gltf", partial_triangle(), "4 indices"),
        ("normal_count_mismatch.gltf", normal_count_mismatch(), "2 normals for 3 positions"),
        ("missing_accessor.gltf", missing_accessor(), "POSITION is accessor 7 of 3"),
        ("transmission_out_of_range.gltf", glass_material_scene(
            {"KHR_materials_transmission": {"transmissionFactor": 1.5}}),
         "a transmissionFactor of 1.5"),
        ("ior_below_one.gltf", glass_material_scene({"KHR_materials_ior": {"ior": 0.5}}),
         "an ior of 0.5"),
        ("dispersion_negative.gltf", glass_material_scene(
            {"KHR_materials_volume": {"thicknessFactor": 1},
             "KHR_materials_dispersion": {"dispersion": -1}}),
         "a KHR_materials_dispersion of -1"),
        ("diffuse_transmission_out_of_range.gltf", glass_material_scene(
            {"KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 1.5}}),
         "a diffuseTransmissionFactor of 1.5"),
        ("attenuation_distance_zero.gltf", glass_material_scene(
            {"KHR_materials_volume": {"thicknessFactor": 1, "attenuationDistance": 0}}),
         "an attenuationDistance of 0"),
        ("variant_out_of_range.gltf", variant_out_of_range(),
         "a KHR_materials_variants mapping of variant 3 of 1"),
        ("light_type.gltf", light_scene({"type": "area"}), "a light of type 'area'"),
        ("light_negative_intensity.gltf", light_scene({"type": "point", "intensity": -2}),
         "a point light of intensity -2"),
        ("light_spot_cone.gltf",
         light_scene({"type": "spot", "spot": {"innerConeAngle": 0.75, "outerConeAngle": 0.5}}),
         "a spot light whose inner cone is wider than its outer cone"),
        ("sphere_non_uniform_scale.gltf", sphere_non_uniform_scale(),
         "a sphere under the scale (1, 2, 1)"),
        ("texture_without_source.gltf",
         textured_triangle({"uri": data_uri(TEXTURE_PNG, "image/png")},
                           texture={"extensions": {"KHR_texture_basisu": {"source": 0}}}),
         "a texture with only a KHR_texture_basisu source"),
        ("image_undecodable.gltf",
         textured_triangle({"uri": data_uri(png_bytes(TEXTURE_ROWS, b"not zlib"), "image/png")}),
         "a PNG whose pixel data is not a zlib stream"),
        ("image_not_png.gltf",
         textured_triangle({"uri": data_uri(b"GIF89a" + bytes(32), "image/png")}),
         "a GIF where a PNG or JPEG must be"),
        ("missing_image.gltf", textured_triangle({"uri": "missing_image.png"}),
         "its image file does not exist"),
        ("draco_corrupt.gltf", draco_corrupt(), "a Draco primitive whose data is not Draco"),
        # The header byte of a meshopt vertex stream (0xA0, version 0) and 7 bytes, far fewer
        # than 3 vertices of 12 bytes need.
        ("meshopt_truncated.gltf", meshopt_scene(b"\xa0" + bytes(7), 3, 12),
         "a meshopt ATTRIBUTES stream cut short"),
        ("meshopt_filter_stride.gltf", meshopt_scene(b"\xa0" + bytes(63), 3, 12,
                                                     filter_="OCTAHEDRAL"),
         "an OCTAHEDRAL filter on 12-byte vertices (it needs 4 or 8)"),
        ("meshopt_fallback_read.gltf", meshopt_uncompressed_fallback_view(),
         "an uncompressed buffer view on a meshopt fallback buffer"),
        ("quantized_normal_not_normalized.gltf", quantized_normal_not_normalized(),
         "KHR_mesh_quantization NORMAL of BYTE without normalized"),
        ("webp_undecodable.gltf",
         textured_triangle({"uri": data_uri(b"RIFF\x1c\x00\x00\x00WEBPVP8L" + bytes(16),
                                            "image/webp")},
                           texture={"extensions": {"EXT_texture_webp": {"source": 0}}}),
         "an EXT_texture_webp image whose data is not WebP"),
        ("texcoord_1.gltf", textured_triangle({"uri": data_uri(TEXTURE_PNG, "image/png")},
                                              texture_info={"texCoord": 1}),
         "a base colour texture on TEXCOORD_1"),
    ]
    for name, data, _ in files:
        write(INVALID_DIR / name, data)
    write_readme(INVALID_DIR, "Broken glTF files (invalid on purpose)",
                 [(name, text) for name, _, text in files] +
                 [("short_buffer.bin", "the short buffer of `short_buffer.gltf`")])


def main():
    write_valid_scenes()
    write_invalid_scenes()


if __name__ == "__main__":
    main()
