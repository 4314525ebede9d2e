#!/usr/bin/env python3
"""Generate small glTF 2.0 test files for the glTF reader.

Pure standard library (json, struct, base64, math, os, zlib). Run from anywhere:

    python3 tests/data/gltf/make_generated.py

Writes, next to this script:
    generated/interpolation.gltf   STEP / LINEAR / CUBICSPLINE translation + a rotation
                                   animation, a perspective camera and a
                                   KHR_lights_punctual directional light
    generated/metal_rough.gltf     3x3 grid of UV spheres, metallic x roughness,
                                   a point light and a camera
    generated/smooth_sphere.gltf   one smooth UV sphere (NORMAL) over a floor quad without
                                   normals (flat), a camera turned down, a coloured
                                   KHR_lights_punctual directional light (tests/suite/gltf_povray)
    generated/two_primitives.glb   binary GLB: TRIANGLE_STRIP + TRIANGLE_FAN primitives,
                                   duplicate node names, a mirrored (negative scale) node
    generated/alpha_modes.gltf     BLEND (factor alpha; texture alpha), MASK (a checker of
                                   alpha 0/1 texels, one cell of the quad each) before a
                                   floor and a wall, a directional light casting their
                                   shadows (tests/suite/gltf_povray)
    generated/alpha_blend.gltf     three quads: BLEND at alpha 1, BLEND and MASK (cutoff
                                   0.3) at factor 0.8 x texture (1 | 0.2) x COLOR_0 0.5
    generated/emissive.gltf        an emissiveTexture read on TEXCOORD_1 (mirrored from
                                   TEXCOORD_0) with emissive_strength 2, and a lit quad
                                   with an emissiveFactor alone
    bad/*.gltf                     hostile files, each with exactly one intended fault

Output is deterministic: running the script twice gives identical bytes.
"""

import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
GEN_DIR = os.path.join(HERE, "generated")
BAD_DIR = os.path.join(HERE, "bad")

# glTF constants
BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT = 5120, 5121, 5122, 5123, 5125, 5126
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = range(7)

_FMT = {BYTE: "b", UNSIGNED_BYTE: "B", SHORT: "h", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I", FLOAT: "f"}
_NCOMP = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def f32(x):
    """Round a Python float to the nearest float32 (so min/max match the stored data)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


class Builder:
    """Accumulates one binary buffer plus bufferViews/accessors, keeping 4-byte alignment."""

    def __init__(self):
        self.data = bytearray()
        self.buffer_views = []
        self.accessors = []

    def _align(self):
        while len(self.data) % 4:
            self.data.append(0)

    def view(self, payload, target=None, stride=None):
        self._align()
        bv = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if stride is not None:
            bv["byteStride"] = stride
        if target is not None:
            bv["target"] = target
        self.data += payload
        self._align()
        self.buffer_views.append(bv)
        return len(self.buffer_views) - 1

    def accessor(self, values, ctype, atype, target=None, minmax=False, count=None):
        """values: flat list of numbers (len = count * components)."""
        n = _NCOMP[atype]
        assert len(values) % n == 0
        payload = struct.pack("<%d%s" % (len(values), _FMT[ctype]), *values)
        bv = self.view(payload, target=target)
        acc = {
            "bufferView": bv,
            "byteOffset": 0,
            "componentType": ctype,
            "count": len(values) // n if count is None else count,
            "type": atype,
        }
        if minmax:
            stored = list(struct.unpack("<%d%s" % (len(values), _FMT[ctype]), payload))
            cols = [[v for v in stored[c::n] if v == v] for c in range(n)]  # ignore NaN
            acc["min"] = [min(c) for c in cols]
            acc["max"] = [max(c) for c in cols]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def padded_data(self):
        self._align()
        return bytes(self.data)

    def data_uri(self):
        return "data:application/octet-stream;base64," + base64.b64encode(self.padded_data()).decode("ascii")

    def embedded(self):
        """The document's accessors, bufferViews and one buffer held in a data URI."""
        return {
            "accessors": self.accessors,
            "bufferViews": self.buffer_views,
            "buffers": [{"byteLength": len(self.padded_data()), "uri": self.data_uri()}],
        }


def dump_json(doc, compact=False):
    if compact:
        return json.dumps(doc, separators=(",", ":"), allow_nan=False)
    return json.dumps(doc, indent=2, allow_nan=False) + "\n"


def write_text(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)


def write_bytes(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as fh:
        fh.write(data)


def asset():
    return {"version": "2.0", "generator": "tests/data/gltf/make_generated.py"}


# ---------------------------------------------------------------- geometry

def unit_cube():
    """Unit cube centred at the origin (side 1), 24 vertices with per-face normals, 36 indices."""
    faces = [  # (normal, u axis, v axis); u x v == normal so winding is CCW seen from outside
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
        ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
        ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
        ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
    ]
    pos, nrm, idx = [], [], []
    for n, u, v in faces:
        base = len(pos) // 3
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            for k in range(3):
                pos.append(0.5 * n[k] + 0.5 * su * u[k] + 0.5 * sv * v[k])
            nrm.extend(n)
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, idx


def uv_sphere(radius, segments=24, rings=16):
    """UV sphere: (rings+1) x (segments+1) vertices (seam duplicated), normals, TEXCOORD_0."""
    pos, nrm, uv, idx = [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings  # 0 at +Y pole
        for j in range(segments + 1):
            phi = 2.0 * math.pi * j / segments
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            nrm.extend(n)
            pos.extend(radius * c for c in n)
            uv.extend((j / segments, i / rings))
    row = segments + 1
    for i in range(rings):
        for j in range(segments):
            a = i * row + j
            b = a + row
            if i != 0:
                idx += [a, b, a + 1]
            if i != rings - 1:
                idx += [a + 1, b, b + 1]
    return pos, nrm, uv, idx


# ---------------------------------------------------------------- a. interpolation.gltf

def make_interpolation():
    b = Builder()
    pos, nrm, idx = unit_cube()
    a_pos = b.accessor(pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    a_nrm = b.accessor(nrm, FLOAT, "VEC3", ARRAY_BUFFER)
    a_idx = b.accessor(idx, UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)

    # "Move": keys at t = 0, 1, 2 s; values (0,0,0), (1,0,0), (1,2,0)
    a_t3 = b.accessor([0.0, 1.0, 2.0], FLOAT, "SCALAR", minmax=True)
    values = [0, 0, 0, 1, 0, 0, 1, 2, 0]
    a_lin = b.accessor(values, FLOAT, "VEC3")
    # CUBICSPLINE: per key (in-tangent, value, out-tangent), tangents all zero -> 3 * 3 elements
    cubic = []
    for k in range(3):
        cubic += [0, 0, 0] + values[3 * k:3 * k + 3] + [0, 0, 0]
    a_cub = b.accessor(cubic, FLOAT, "VEC3")

    # "Spin": node "Linear" about +y, t=0 identity, t=2 90 degrees
    a_t2 = b.accessor([0.0, 2.0], FLOAT, "SCALAR", minmax=True)
    s45 = math.sin(math.pi / 4)
    a_rot = b.accessor([0, 0, 0, 1, 0, s45, 0, s45], FLOAT, "VEC4")

    # Sun: directional light pointing down-forward: rotate -45 degrees about +x, so the
    # light's -Z axis becomes (0, -0.7071, -0.7071).
    sun_q = [math.sin(math.radians(-22.5)), 0.0, 0.0, math.cos(math.radians(-22.5))]

    doc = {
        "asset": asset(),
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Sun", "type": "directional", "color": [1.0, 1.0, 1.0], "intensity": 3.0},
        ]}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 2, 3, 4]}],
        "nodes": [
            {"name": "Step", "mesh": 0},
            {"name": "Linear", "mesh": 0},
            {"name": "Cubic", "mesh": 0},
            {"name": "Cam", "camera": 0, "translation": [0.0, 1.0, 10.0]},
            {"name": "Sun", "rotation": sun_q, "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.6, "aspectRatio": 4.0 / 3.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": [{"name": "UnitCube", "primitives": [{
            "attributes": {"POSITION": a_pos, "NORMAL": a_nrm},
            "indices": a_idx, "material": 0, "mode": TRIANGLES}]}],
        "materials": [{"name": "Grey", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "animations": [
            {"name": "Move",
             "samplers": [
                 {"input": a_t3, "output": a_lin, "interpolation": "STEP"},
                 {"input": a_t3, "output": a_lin, "interpolation": "LINEAR"},
                 {"input": a_t3, "output": a_cub, "interpolation": "CUBICSPLINE"},
             ],
             "channels": [
                 {"sampler": 0, "target": {"node": 0, "path": "translation"}},
                 {"sampler": 1, "target": {"node": 1, "path": "translation"}},
                 {"sampler": 2, "target": {"node": 2, "path": "translation"}},
             ]},
            {"name": "Spin",
             "samplers": [{"input": a_t2, "output": a_rot, "interpolation": "LINEAR"}],
             "channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}}]},
        ],
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "interpolation.gltf"), dump_json(doc))


# ---------------------------------------------------------------- b. metal_rough.gltf

def make_metal_rough():
    b = Builder()
    pos, nrm, uv, idx = uv_sphere(0.9, 24, 16)
    a_pos = b.accessor(pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    a_nrm = b.accessor(nrm, FLOAT, "VEC3", ARRAY_BUFFER)
    a_uv = b.accessor(uv, FLOAT, "VEC2", ARRAY_BUFFER)
    a_idx = b.accessor(idx, UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)

    levels = [0.0, 0.5, 1.0]
    spacing = 2.2
    materials, meshes, nodes = [], [], []
    for mi, metallic in enumerate(levels):          # rows: metallic, bottom to top
        for ri, roughness in enumerate(levels):     # columns: roughness, left to right
            name = "m%g_r%g" % (metallic, roughness)
            materials.append({"name": name, "pbrMetallicRoughness": {
                "baseColorFactor": [0.9, 0.6, 0.2, 1.0],
                "metallicFactor": metallic, "roughnessFactor": roughness}})
            meshes.append({"name": name, "primitives": [{
                "attributes": {"POSITION": a_pos, "NORMAL": a_nrm, "TEXCOORD_0": a_uv},
                "indices": a_idx, "material": len(materials) - 1, "mode": TRIANGLES}]})
            nodes.append({"name": name, "mesh": len(meshes) - 1,
                          "translation": [(ri - 1) * spacing, (mi - 1) * spacing, 0.0]})
    nodes.append({"name": "Lamp", "translation": [0.0, 4.0, 6.0],
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"name": "Cam", "camera": 0, "translation": [0.0, 0.0, 9.0]})

    doc = {
        "asset": asset(),
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Lamp", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 50.0, "range": 40.0},
        ]}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.8, "aspectRatio": 4.0 / 3.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": meshes,
        "materials": materials,
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "metal_rough.gltf"), dump_json(doc))


# ---------------------------------------------------------------- smooth_sphere.gltf

def axis_angle(axis, angle):
    """The unit quaternion [x, y, z, w] of a turn by `angle` radians about `axis`."""
    n = math.sqrt(sum(c * c for c in axis))
    s = math.sin(angle / 2.0)
    return [axis[0] / n * s, axis[1] / n * s, axis[2] / n * s, math.cos(angle / 2.0)]


def make_smooth_sphere():
    b = Builder()
    pos, nrm, uv, idx = uv_sphere(0.9, 32, 24)
    a_pos = b.accessor(pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    a_nrm = b.accessor(nrm, FLOAT, "VEC3", ARRAY_BUFFER)
    a_idx = b.accessor(idx, UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    # The floor: one quad at y = -0.9 without NORMAL (so drawn flat), wound to face +y.
    floor = [-3.0, -0.9, -3.0, -3.0, -0.9, 3.0, 3.0, -0.9, 3.0, 3.0, -0.9, -3.0]
    a_floor = b.accessor(floor, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    a_fidx = b.accessor([0, 1, 2, 0, 2, 3], UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    # The light travels along d = (-0.4, -0.8, -0.45): the node turns -Z onto d.
    d = [-0.4, -0.8, -0.45]
    dn = math.sqrt(sum(c * c for c in d))
    d = [c / dn for c in d]
    axis = [d[1], -d[0], 0.0]  # (-Z) x d
    sun_q = axis_angle(axis, math.acos(-d[2]))
    cam_q = axis_angle([1.0, 0.0, 0.0], math.radians(-15.0))

    doc = {
        "asset": asset(),
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Sun", "type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 1.6},
        ]}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "Ball", "mesh": 0, "translation": [0.2, 0.0, 0.0]},
            {"name": "Floor", "mesh": 1},
            {"name": "Cam", "camera": 0, "translation": [0.0, 1.2, 4.5], "rotation": cam_q},
            {"name": "Sun", "rotation": sun_q, "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.7, "aspectRatio": 4.0 / 3.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": [
            {"name": "Ball", "primitives": [{
                "attributes": {"POSITION": a_pos, "NORMAL": a_nrm},
                "indices": a_idx, "material": 0, "mode": TRIANGLES}]},
            {"name": "Floor", "primitives": [{
                "attributes": {"POSITION": a_floor},
                "indices": a_fidx, "material": 1, "mode": TRIANGLES}]},
        ],
        "materials": [
            {"name": "Orange", "pbrMetallicRoughness": {
                "baseColorFactor": [0.9, 0.45, 0.2, 1.0], "metallicFactor": 0.3, "roughnessFactor": 0.4}},
            {"name": "Grey", "pbrMetallicRoughness": {
                "baseColorFactor": [0.6, 0.6, 0.6, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}},
        ],
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "smooth_sphere.gltf"), dump_json(doc))


# ---------------------------------------------------------------- alpha and emission

def png_rgba(rows):
    """A PNG (8-bit RGBA, no filter) of `rows`: lists of (r, g, b, a) bytes, top row first."""
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def png_uri(rows):
    return "data:image/png;base64," + base64.b64encode(png_rgba(rows)).decode("ascii")


def grid_quad(x0, x1, y0, y1, z, n, mirror_u1=False):
    """An n x n grid of cells over x0..x1, y0..y1 at z, facing +z, each cell with its own
    four vertices and TEXCOORD_0 spanning exactly its texel of an n x n image (v down
    from the top, glTF's way). Returns (pos, nrm, uv0, uv1, idx); uv1 is uv0 with u
    mirrored (1 - u) when `mirror_u1`."""
    pos, nrm, uv0, uv1, idx = [], [], [], [], []
    for j in range(n):          # rows from the top
        for i in range(n):      # columns from the left
            base = len(pos) // 3
            for (a, b) in ((0, 1), (1, 1), (1, 0), (0, 0)):  # bl, br, tr, tl in cell units
                u, v = (i + a) / n, (j + b) / n
                pos += [x0 + u * (x1 - x0), y1 - v * (y1 - y0), z]
                nrm += [0.0, 0.0, 1.0]
                uv0 += [u, v]
                uv1 += [1.0 - u if mirror_u1 else u, v]
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv0, uv1, idx


def quad_mesh(b, name, x0, x1, y0, y1, z, n, material, colors=None, mirror_u1=False):
    """A grid quad as a mesh of `b`'s accessors (TEXCOORD_1 only when mirrored; COLOR_0
    a VEC4 per vertex when `colors` gives one RGBA for all)."""
    pos, nrm, uv0, uv1, idx = grid_quad(x0, x1, y0, y1, z, n, mirror_u1)
    attrs = {
        "POSITION": b.accessor(pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True),
        "NORMAL": b.accessor(nrm, FLOAT, "VEC3", ARRAY_BUFFER),
        "TEXCOORD_0": b.accessor(uv0, FLOAT, "VEC2", ARRAY_BUFFER),
    }
    if mirror_u1:
        attrs["TEXCOORD_1"] = b.accessor(uv1, FLOAT, "VEC2", ARRAY_BUFFER)
    if colors is not None:
        attrs["COLOR_0"] = b.accessor(list(colors) * (len(pos) // 3), FLOAT, "VEC4", ARRAY_BUFFER)
    a_idx = b.accessor(idx, UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    return {"name": name, "primitives": [{
        "attributes": attrs, "indices": a_idx, "material": material, "mode": TRIANGLES}]}


def matte(name, rgba, **extra):
    m = {"name": name, "pbrMetallicRoughness": {
        "baseColorFactor": rgba, "metallicFactor": 0.0, "roughnessFactor": 1.0}}
    m.update(extra)
    return m


NEAREST_CLAMP = {"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}


def make_alpha_modes():
    b = Builder()
    # Checker of alpha 255 / 0 over 4 x 4 texels; the opaque ones green or yellow.
    checker = [[((40, 200, 70, 255) if i % 2 == 0 else (230, 200, 40, 255)) if (i + j) % 2 == 0
                else (255, 0, 255, 0) for i in range(4)] for j in range(4)]
    # 2 x 2 texels of alpha 1, 0.75 / 0.5, 0.25 (bytes 255, 191, 128, 64), all one blue.
    graded = [[(60, 90, 220, 255), (60, 90, 220, 191)], [(60, 90, 220, 128), (60, 90, 220, 64)]]
    meshes = [
        quad_mesh(b, "Veil", -2.8, -1.2, -0.4, 1.2, 0.0, 1, 0),
        quad_mesh(b, "Glass", -0.8, 0.8, -0.4, 1.2, 0.0, 2, 1),
        quad_mesh(b, "Lattice", 1.2, 2.8, -0.4, 1.2, 0.0, 4, 2),
    ]
    floor = [-4.0, -1.0, -3.0, -4.0, -1.0, 2.5, 4.0, -1.0, 2.5, 4.0, -1.0, -3.0]
    wall = [-4.5, -1.0, -2.5, 4.5, -1.0, -2.5, 4.5, 3.0, -2.5, -4.5, 3.0, -2.5]
    for name, pts, mat in (("Floor", floor, 3), ("Wall", wall, 4)):
        a_p = b.accessor(pts, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
        a_i = b.accessor([0, 1, 2, 0, 2, 3], UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": a_p}, "indices": a_i, "material": mat, "mode": TRIANGLES}]})
    # The light travels along d = (-0.35, -0.7, -0.6): from the upper right, in front.
    d = [-0.35, -0.7, -0.6]
    dn = math.sqrt(sum(c * c for c in d))
    d = [c / dn for c in d]
    sun_q = axis_angle([d[1], -d[0], 0.0], math.acos(-d[2]))
    cam_q = axis_angle([1.0, 0.0, 0.0], math.radians(-6.0))
    doc = {
        "asset": asset(),
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Sun", "type": "directional", "color": [1.0, 1.0, 1.0], "intensity": 1.5},
        ]}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": list(range(7))}],
        "nodes": [
            {"name": "Veil", "mesh": 0},
            {"name": "Glass", "mesh": 1},
            {"name": "Lattice", "mesh": 2},
            {"name": "Floor", "mesh": 3},
            {"name": "Wall", "mesh": 4},
            {"name": "Cam", "camera": 0, "translation": [0.0, 0.8, 6.5], "rotation": cam_q},
            {"name": "Sun", "rotation": sun_q, "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.75, "aspectRatio": 4.0 / 3.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": meshes,
        "materials": [
            matte("Veil", [0.9, 0.2, 0.1, 0.5], alphaMode="BLEND", doubleSided=True),
            matte("Glass", [1.0, 1.0, 1.0, 1.0], alphaMode="BLEND", doubleSided=True,
                  pbrMetallicRoughness={"baseColorTexture": {"index": 1}, "metallicFactor": 0.0,
                                        "roughnessFactor": 1.0}),
            matte("Lattice", [1.0, 1.0, 1.0, 1.0], alphaMode="MASK", doubleSided=True,
                  pbrMetallicRoughness={"baseColorTexture": {"index": 0}, "metallicFactor": 0.0,
                                        "roughnessFactor": 1.0}),
            matte("Floor", [0.6, 0.6, 0.6, 1.0]),
            matte("Wall", [0.3, 0.5, 0.8, 1.0]),
        ],
        "textures": [{"sampler": 0, "source": 0}, {"sampler": 0, "source": 1}],
        "samplers": [NEAREST_CLAMP],
        "images": [{"uri": png_uri(checker)}, {"uri": png_uri(graded)}],
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "alpha_modes.gltf"), dump_json(doc))


def make_alpha_blend():
    b = Builder()
    # 2 x 1 white texels of alpha 1 and 0.2 (byte 51).
    texture = [[(255, 255, 255, 255), (255, 255, 255, 51)]]
    half = [1.0, 1.0, 1.0, 0.5]
    meshes = [
        quad_mesh(b, "Whole", -2.5, -1.0, -0.75, 0.75, 0.0, 1, 0),
        quad_mesh(b, "Blend", -0.75, 0.75, -0.75, 0.75, 0.0, 1, 1, colors=half),
        quad_mesh(b, "Mask", 1.0, 2.5, -0.75, 0.75, 0.0, 1, 2, colors=half),
    ]
    textured = {"baseColorTexture": {"index": 0}, "baseColorFactor": [0.8, 0.8, 0.8, 0.8],
                "metallicFactor": 0.0, "roughnessFactor": 1.0}
    doc = {
        "asset": asset(),
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "Whole", "mesh": 0},
            {"name": "Blend", "mesh": 1},
            {"name": "Mask", "mesh": 2},
            {"name": "Cam", "camera": 0, "translation": [0.0, 0.0, 4.0]},
        ],
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.7, "aspectRatio": 2.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": meshes,
        "materials": [
            matte("Whole", [0.8, 0.8, 0.8, 1.0], alphaMode="BLEND"),
            matte("Blend", [0.8, 0.8, 0.8, 0.8], alphaMode="BLEND", pbrMetallicRoughness=textured),
            matte("Mask", [0.8, 0.8, 0.8, 0.8], alphaMode="MASK", alphaCutoff=0.3,
                  pbrMetallicRoughness=textured),
        ],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [NEAREST_CLAMP],
        "images": [{"uri": png_uri(texture)}],
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "alpha_blend.gltf"), dump_json(doc))


def make_emissive():
    b = Builder()
    # 2 x 1 sRGB texels: white, and (128, 64, 255).
    texture = [[(255, 255, 255, 255), (128, 64, 255, 255)]]
    meshes = [
        quad_mesh(b, "Glow", -1.6, -0.1, -0.75, 0.75, 0.0, 1, 0, mirror_u1=True),
        quad_mesh(b, "Lit", 0.1, 1.6, -0.75, 0.75, 0.0, 1, 1),
    ]
    doc = {
        "asset": asset(),
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "Glow", "mesh": 0},
            {"name": "Lit", "mesh": 1},
            {"name": "Cam", "camera": 0, "translation": [0.0, 0.0, 4.0]},
        ],
        "cameras": [{"name": "Cam", "type": "perspective", "perspective": {
            "yfov": 0.7, "aspectRatio": 2.0, "znear": 0.1, "zfar": 100.0}}],
        "meshes": meshes,
        "materials": [
            matte("Glow", [0.0, 0.0, 0.0, 1.0], emissiveFactor=[1.0, 0.5, 0.25],
                  emissiveTexture={"index": 0, "texCoord": 1},
                  extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}}),
            matte("Lit", [0.5, 0.5, 0.5, 1.0], emissiveFactor=[0.1, 0.2, 0.3]),
        ],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [NEAREST_CLAMP],
        "images": [{"uri": png_uri(texture)}],
        **b.embedded(),
    }
    write_text(os.path.join(GEN_DIR, "emissive.gltf"), dump_json(doc))


# ---------------------------------------------------------------- c. two_primitives.glb

def glb(doc, bin_data):
    """Pack a GLB: 12-byte header, JSON chunk (space padded), BIN chunk (zero padded)."""
    js = json.dumps(doc, separators=(",", ":"), allow_nan=False).encode("utf-8")
    js += b" " * (-len(js) % 4)
    bn = bytes(bin_data) + b"\x00" * (-len(bin_data) % 4)
    total = 12 + 8 + len(js) + 8 + len(bn)
    out = struct.pack("<III", 0x46546C67, 2, total)          # "glTF", version 2
    out += struct.pack("<II", len(js), 0x4E4F534A) + js       # "JSON"
    out += struct.pack("<II", len(bn), 0x004E4942) + bn       # "BIN\0"
    assert len(out) == total
    return out


def make_two_primitives():
    b = Builder()
    # primitive 0: indexed TRIANGLE_STRIP, 4 vertices -> 2 triangles (a unit quad)
    strip_pos = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]
    a_strip = b.accessor(strip_pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    a_strip_idx = b.accessor([0, 1, 2, 3], UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    # primitive 1: non-indexed TRIANGLE_FAN, 5 vertices -> 3 triangles (centre + 4 rim points)
    fan_pos = [2.5, 0.5, 0.0,
               2.0, 0.0, 0.0,
               3.0, 0.0, 0.0,
               3.0, 1.0, 0.0,
               2.0, 1.0, 0.0]
    a_fan = b.accessor(fan_pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    # mirror mesh: one triangle
    tri_pos = [0, 0, 0, 1, 0, 0, 0, 1, 0]
    a_tri = b.accessor(tri_pos, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)

    bin_data = b.padded_data()
    doc = {
        "asset": asset(),
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "Wheel", "mesh": 0, "translation": [-4.0, 0.0, 0.0]},
            {"name": "Wheel", "mesh": 0, "translation": [0.0, 0.0, 0.0]},
            {"name": "Mirror", "mesh": 1, "translation": [4.0, 0.0, 0.0], "scale": [-1.0, 1.0, 1.0]},
        ],
        "meshes": [
            {"name": "WheelMesh", "primitives": [
                {"attributes": {"POSITION": a_strip}, "indices": a_strip_idx, "mode": TRIANGLE_STRIP},
                {"attributes": {"POSITION": a_fan}, "mode": TRIANGLE_FAN},
            ]},
            {"name": "MirrorTriangle", "primitives": [
                {"attributes": {"POSITION": a_tri}, "mode": TRIANGLES},
            ]},
        ],
        "accessors": b.accessors,
        "bufferViews": b.buffer_views,
        "buffers": [{"byteLength": len(bin_data)}],   # no uri: the GLB BIN chunk
    }
    write_bytes(os.path.join(GEN_DIR, "two_primitives.glb"), glb(doc, bin_data))


# ---------------------------------------------------------------- d. hostile files

TRI = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]


def triangle_doc(indices=(0, 1, 2), positions=TRI, uri=None, extra_attrs=None):
    """Minimal valid one-triangle glTF (indexed). Returns (doc, builder)."""
    b = Builder()
    a_idx = b.accessor(list(indices), UNSIGNED_SHORT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    a_pos = b.accessor(list(positions), FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    attrs = {"POSITION": a_pos}
    for name, (vals, ctype, atype) in (extra_attrs or {}).items():
        attrs[name] = b.accessor(vals, ctype, atype, ARRAY_BUFFER)
    data = b.padded_data()
    doc = {
        "asset": asset(),
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Triangle", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": attrs, "indices": a_idx, "mode": TRIANGLES}]}],
        "accessors": b.accessors,
        "bufferViews": b.buffer_views,
        "buffers": [{"byteLength": len(data), "uri": uri if uri is not None else b.data_uri()}],
    }
    return doc


def write_bad(name, doc):
    write_text(os.path.join(BAD_DIR, name), dump_json(doc, compact=True) + "\n")


def make_bad():
    # buffer points at a file that does not exist
    write_bad("missing_buffer.gltf", triangle_doc(uri="nothere.bin"))

    # index 7 with only 3 vertices
    write_bad("index_past.gltf", triangle_doc(indices=(0, 1, 7)))

    # a NaN in POSITION (min/max computed over the finite values only)
    nan_pos = list(TRI)
    nan_pos[4] = float("nan")   # y of vertex 1
    write_bad("nan_position.gltf", triangle_doc(positions=nan_pos))

    # accessor claims 2,000,000,000 VEC3 floats; its bufferView is 36 bytes; file < 1 KB
    b = Builder()
    a_pos = b.accessor(TRI, FLOAT, "VEC3", ARRAY_BUFFER, minmax=True)
    b.accessors[a_pos]["count"] = 2000000000
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": a_pos}}]}],
        **b.embedded(),
    }
    write_bad("huge_count.gltf", doc)

    # skin whose only joint (node 1) exists in "nodes" but is in no scene's node tree
    doc = triangle_doc(extra_attrs={
        "JOINTS_0": ([0, 0, 0, 0] * 3, UNSIGNED_BYTE, "VEC4"),
        "WEIGHTS_0": ([1.0, 0.0, 0.0, 0.0] * 3, FLOAT, "VEC4"),
    })
    doc["nodes"][0]["skin"] = 0
    doc["nodes"].append({"name": "OrphanJoint"})     # node 1: the joint, in no scene
    doc["skins"] = [{"joints": [1]}]
    write_bad("skin_joint_outside.gltf", doc)

    # buffer uri climbs out of the directory
    write_bad("climbs.gltf", triangle_doc(uri="../secret.bin"))

    # requires an extension the reader does not implement
    doc = triangle_doc()
    doc["extensionsUsed"] = ["KHR_draco_mesh_compression"]
    doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    write_bad("requires_unknown.gltf", doc)

    # node 0 child of node 1 and node 1 child of node 0; scene nodes [0]
    doc = triangle_doc()
    doc["nodes"] = [
        {"name": "A", "mesh": 0, "children": [1]},
        {"name": "B", "children": [0]},
    ]
    write_bad("cycle.gltf", doc)


def main():
    make_interpolation()
    make_metal_rough()
    make_smooth_sphere()
    make_alpha_modes()
    make_alpha_blend()
    make_emissive()
    make_two_primitives()
    make_bad()
    for d in (GEN_DIR, BAD_DIR):
        for name in sorted(os.listdir(d)):
            p = os.path.join(d, name)
            print("%7d  %s" % (os.path.getsize(p), os.path.relpath(p, HERE)))


if __name__ == "__main__":
    main()
