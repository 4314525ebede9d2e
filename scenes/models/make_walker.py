#!/usr/bin/env python3
"""Writes walker.glb beside this script: the README's worked glTF example, ours (CC0).

A stylised humanoid, 1.8 m tall, standing on y = 0 and facing +z: ONE skinned mesh
(four primitives, one per material: shirt, skin, trousers, shoes) over a skeleton of
12 joints, two animations ("Walk", a 1 s loop; "Wave", the right arm, 2 s), a static
10 x 10 m ground quad, a perspective camera "Cam" and two KHR_lights_punctual lights
("Sun", directional 3 lux; "Fill", point 20 cd). Python 3 standard library only; the
output is the same bytes on every run.

    python3 scenes/models/make_walker.py
"""

import json
import math
import os
import struct

# ---------------------------------------------------------------- small vector maths


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def mul(a, s):
    return [a[0] * s, a[1] * s, a[2] * s]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    n = math.sqrt(dot(a, a))
    return [a[0] / n, a[1] / n, a[2] / n] if n > 0 else [0.0, 1.0, 0.0]


def smooth(e0, e1, x):
    """Smoothstep from 0 at e0 to 1 at e1."""
    t = min(1.0, max(0.0, (x - e0) / (e1 - e0)))
    return t * t * (3.0 - 2.0 * t)


def quat_axis(axis, deg):
    """Quaternion [x, y, z, w] for a rotation of deg degrees about a unit axis."""
    h = math.radians(deg) / 2.0
    s = math.sin(h)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(h)]


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]


def quat_rotate(q, v):
    x, y, z, w = q
    u = [x, y, z]
    t = mul(cross(u, v), 2.0)
    return add(add(v, mul(t, w)), cross(u, t))


def quat_from_basis(x, y, z):
    """Quaternion of the rotation whose matrix has columns x, y, z."""
    m00, m10, m20 = x
    m01, m11, m21 = y
    m02, m12, m22 = z
    tr = m00 + m11 + m22
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s]
    elif m00 > m11 and m00 > m22:
        s = math.sqrt(1.0 + m00 - m11 - m22) * 2
        q = [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s]
    elif m11 > m22:
        s = math.sqrt(1.0 + m11 - m00 - m22) * 2
        q = [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s]
    else:
        s = math.sqrt(1.0 + m22 - m00 - m11) * 2
        q = [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def look_rotation(eye, target):
    """The node rotation that points a glTF camera (or light: its -z) from eye at target."""
    f = norm(sub(target, eye))
    z = mul(f, -1.0)
    x = norm(cross([0.0, 1.0, 0.0], z))
    y = cross(z, x)
    return quat_from_basis(x, y, z)


# ---------------------------------------------------------------- the skeleton

# name, parent, translation (the bind pose has no rotation, so each joint's inverse bind
# matrix is a translation by minus its world position).
JOINTS = [
    ("Hips", None, [0.0, 0.95, 0.0]),
    ("Spine", "Hips", [0.0, 0.15, 0.0]),
    ("Chest", "Spine", [0.0, 0.22, 0.0]),
    ("Head", "Chest", [0.0, 0.18, 0.0]),
    ("UpperArm.L", "Chest", [0.235, 0.12, 0.0]),
    ("LowerArm.L", "UpperArm.L", [0.0, -0.29, 0.0]),
    ("UpperArm.R", "Chest", [-0.235, 0.12, 0.0]),
    ("LowerArm.R", "UpperArm.R", [0.0, -0.29, 0.0]),
    ("UpperLeg.L", "Hips", [0.1, -0.06, 0.0]),
    ("LowerLeg.L", "UpperLeg.L", [0.0, -0.42, 0.0]),
    ("UpperLeg.R", "Hips", [-0.1, -0.06, 0.0]),
    ("LowerLeg.R", "UpperLeg.R", [0.0, -0.42, 0.0]),
]
J = {name: k for k, (name, _, _) in enumerate(JOINTS)}


def joint_world(name):
    _, parent, t = JOINTS[J[name]]
    return t if parent is None else add(joint_world(parent), t)


WORLD = {name: joint_world(name) for name, _, _ in JOINTS}

# ---------------------------------------------------------------- the body's parts


class Part:
    """Vertices, per-vertex joint weights and triangles of one closed surface."""

    def __init__(self, look):
        self.look = look
        self.p, self.w, self.tris = [], [], []


def tube(look, a, b, radius, weigh, rings=24, segs=20, squash=1.0):
    """A closed capsule-like surface from point a to b: rings of radius radius(s) (s in
    0..1 along the axis, 0 at both ends, the ends rounded) and weights weigh(point)."""
    part = Part(look)
    d = sub(b, a)
    length = math.sqrt(dot(d, d))
    d = norm(d)
    u = norm(cross(d, [0.0, 0.0, 1.0])) if abs(d[2]) < 0.9 else norm(cross(d, [1.0, 0.0, 0.0]))
    v = cross(d, u)
    part.p.append(a)
    for i in range(1, rings):
        s = i / rings
        # Cosine spacing puts more rings near the rounded ends.
        s = 0.5 - 0.5 * math.cos(math.pi * s)
        r = radius(s)
        c = add(a, mul(d, s * length))
        for k in range(segs):
            ang = 2.0 * math.pi * k / segs
            off = add(mul(u, r * math.cos(ang)), mul(v, r * squash * math.sin(ang)))
            part.p.append(add(c, off))
    part.p.append(b)
    last = len(part.p) - 1
    for k in range(segs):
        k2 = (k + 1) % segs
        part.tris.append([0, 1 + k2, 1 + k])
    for i in range(rings - 2):
        r0, r1 = 1 + i * segs, 1 + (i + 1) * segs
        for k in range(segs):
            k2 = (k + 1) % segs
            part.tris.append([r0 + k, r0 + k2, r1 + k])
            part.tris.append([r0 + k2, r1 + k2, r1 + k])
    r0 = 1 + (rings - 2) * segs
    for k in range(segs):
        k2 = (k + 1) % segs
        part.tris.append([r0 + k, r0 + k2, last])
    part.w = [weigh(p) for p in part.p]
    return part


def rounded(r0, r1, cap):
    """A radius profile from r0 to r1 with ends rounded over a fraction cap of the length."""

    def f(s):
        r = r0 + (r1 - r0) * s
        e = min(s, 1.0 - s)
        if e < cap:
            r *= math.sqrt(max(0.0, 1.0 - ((cap - e) / cap) ** 2))
        return r

    return f


def blend(j0, j1, e0, e1, axis=1):
    """Weights from joint j0 (coordinate below e0) to j1 (above e1), smoothly between."""

    def f(p):
        t = smooth(e0, e1, p[axis])
        return {j0: 1.0 - t, j1: t}

    return f


def chain(*pieces):
    """Weights by height through several blends: pieces are (joint, y from which it
    starts to take over, y at which it has taken over), lowest first."""

    def f(p):
        w = {pieces[0][0]: 1.0}
        for joint, e0, e1 in pieces[1:]:
            t = smooth(e0, e1, p[1])
            w = {k: x * (1.0 - t) for k, x in w.items()}
            w[joint] = w.get(joint, 0.0) + t
        return w

    return f


def body():
    parts = []
    # Torso: hips to shoulders, wider at the chest, an ellipse in section (deeper than
    # wide is wrong for a person: squash the z radius).
    def torso_r(s):
        r = 0.16 - 0.025 * math.sin(math.pi * s) + 0.04 * smooth(0.45, 0.8, s)
        e = min(s, 1.0 - s)
        cap = 0.12
        if e < cap:
            r *= math.sqrt(max(0.0, 1.0 - ((cap - e) / cap) ** 2))
        return r

    parts.append(
        tube(
            "shirt",
            [0.0, 0.80, 0.0],
            [0.0, 1.50, 0.0],
            torso_r,
            chain((J["Hips"], 0, 0), (J["Spine"], 1.0, 1.14), (J["Chest"], 1.2, 1.36)),
            rings=30,
            segs=28,
            squash=0.62,
        )
    )
    # Neck and head.
    parts.append(
        tube("skin", [0.0, 1.44, 0.0], [0.0, 1.62, 0.0], rounded(0.05, 0.048, 0.2),
             blend(J["Chest"], J["Head"], 1.47, 1.53), rings=10, segs=16)
    )
    parts.append(
        tube("skin", [0.0, 1.57, 0.0], [0.0, 1.80, 0.005], rounded(0.1, 0.1, 0.5),
             lambda p: {J["Head"]: 1.0}, rings=18, segs=24, squash=1.1)
    )
    # A nose, so that the head shows which way it faces (+z).
    parts.append(
        tube("skin", [0.0, 1.69, 0.07], [0.0, 1.66, 0.125], rounded(0.022, 0.016, 0.4),
             lambda p: {J["Head"]: 1.0}, rings=8, segs=10)
    )
    for side, sx in (("L", 1.0), ("R", -1.0)):
        up, low = J["UpperArm." + side], J["LowerArm." + side]
        sh = WORLD["UpperArm." + side]
        elbow_y = WORLD["LowerArm." + side][1]
        # Arm: from just above the shoulder down to the wrist; the top blends with the
        # chest, the elbow between the two arm joints.
        arm_top = [sh[0], sh[1] + 0.04, 0.0]
        wrist = [sh[0], sh[1] - 0.56, 0.0]

        def arm_w(p, up=up, low=low, sh=sh, elbow_y=elbow_y):
            t = smooth(elbow_y + 0.05, elbow_y - 0.05, p[1])
            w = {up: 1.0 - t, low: t}
            # The shoulder: the arm's top keeps a little of the chest's motion (a full
            # blend would pinch the arm when it is raised over the head).
            c = 0.35 * smooth(sh[1] - 0.03, sh[1] + 0.04, p[1])
            if c > 0:
                w = {k: x * (1.0 - c) for k, x in w.items()}
                w[J["Chest"]] = w.get(J["Chest"], 0.0) + c
            return w

        parts.append(
            tube("shirt", arm_top, wrist, rounded(0.055, 0.04, 0.12), arm_w, rings=26,
                 segs=16)
        )
        # Hand: a small rounded lump below the wrist, on the forearm.
        parts.append(
            tube("skin", [sh[0], sh[1] - 0.54, 0.0], [sh[0], sh[1] - 0.71, 0.01],
                 rounded(0.045, 0.04, 0.5), lambda p, low=low: {low: 1.0}, rings=10,
                 segs=12, squash=0.6)
        )
        # Leg: from inside the hips down to the ankle; the top blends with the hips,
        # the knee between the two leg joints.
        hip = WORLD["UpperLeg." + side]
        knee_y = WORLD["LowerLeg." + side][1]
        ul, ll = J["UpperLeg." + side], J["LowerLeg." + side]

        def leg_w(p, ul=ul, ll=ll, knee_y=knee_y, hip=hip):
            t = smooth(knee_y + 0.06, knee_y - 0.06, p[1])
            w = {ul: 1.0 - t, ll: t}
            c = smooth(hip[1] - 0.02, hip[1] + 0.08, p[1])
            if c > 0:
                w = {k: x * (1.0 - c) for k, x in w.items()}
                w[J["Hips"]] = w.get(J["Hips"], 0.0) + c
            return w

        parts.append(
            tube("trousers", [hip[0] * 1.05, 0.98, 0.0], [hip[0], 0.06, 0.0],
                 rounded(0.085, 0.05, 0.08), leg_w, rings=34, segs=20)
        )
        # Shoe: an elongated lump from the heel forward, on the lower leg.
        parts.append(
            tube("shoes", [hip[0], 0.045, -0.07], [hip[0], 0.045, 0.17],
                 rounded(0.05, 0.042, 0.35), lambda p, ll=ll: {ll: 1.0}, rings=12,
                 segs=16, squash=0.85)
        )
    return parts


def smooth_normals(part):
    n = [[0.0, 0.0, 0.0] for _ in part.p]
    for a, b, c in part.tris:
        fn = cross(sub(part.p[b], part.p[a]), sub(part.p[c], part.p[a]))
        for k in (a, b, c):
            n[k] = add(n[k], fn)
    return [norm(x) for x in n]


def top2(w):
    """The vertex's two largest weights, normalised to sum to 1 (as glTF requires)."""
    items = sorted(((x, k) for k, x in w.items() if x > 1e-6), key=lambda e: (-e[0], e[1]))[:2]
    total = sum(x for x, _ in items)
    joints = [k for _, k in items] + [0] * (4 - len(items))
    weights = [x / total for x, _ in items] + [0.0] * (4 - len(items))
    # Stored as float32: put any rounding into the first weight so the sum stays 1.
    f32 = [struct.unpack("<f", struct.pack("<f", x))[0] for x in weights]
    f32[0] = struct.unpack("<f", struct.pack("<f", 1.0 - sum(f32[1:])))[0]
    return joints, f32


# ---------------------------------------------------------------- the animations


def fk(rotations, hips_t):
    """World (rotation, position) of every joint given local rotations by joint name."""
    out = {}
    for name, parent, t in JOINTS:
        q = rotations.get(name, [0.0, 0.0, 0.0, 1.0])
        if parent is None:
            out[name] = (q, hips_t)
        else:
            pq, pp = out[parent]
            out[name] = (quat_mul(pq, q), add(pp, quat_rotate(pq, t)))
    return out


X, Y, Z = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]


def walk_pose(phase):
    """Local rotations at phase (radians) of the stride. The left leg is forward at
    phase pi/2; a thigh rotation of -a about x swings the foot forward (+z)."""
    s, c = math.sin(phase), math.cos(phase)
    rot = {}
    for side, sign in (("L", 1.0), ("R", -1.0)):
        fwd = sign * s
        swing = sign * c  # > 0 while this leg moves forward (its swing phase)
        rot["UpperLeg." + side] = quat_axis(X, -24.0 * fwd)
        rot["LowerLeg." + side] = quat_axis(X, 6.0 + 40.0 * max(0.0, swing) ** 1.5)
        rot["UpperArm." + side] = quat_mul(quat_axis(Z, sign * 6.0), quat_axis(X, 22.0 * fwd))
        rot["LowerArm." + side] = quat_axis(X, -18.0 - 8.0 * max(0.0, -fwd))
    return rot


def lowest_foot(rot, hips_t, shoes):
    """The lowest shoe vertex in the world, shoes = [(joint name, bind position)]."""
    pose = fk(rot, hips_t)
    low = 1e9
    for name, p in shoes:
        q, o = pose[name]
        w = add(o, quat_rotate(q, sub(p, WORLD[name])))
        low = min(low, w[1])
    return low


def walk(shoes):
    keys = 8
    times = [k / keys for k in range(keys + 1)]
    rots, hips = [], []
    for k in range(keys):
        rot = walk_pose(2.0 * math.pi * k / keys)
        # Hips bob: as low as keeps the lower shoe on the ground (y = 0.005).
        base = [0.0, 0.95, 0.0]
        drop = lowest_foot(rot, base, shoes) - 0.005
        rots.append(rot)
        hips.append([0.0, 0.95 - drop, 0.0])
    rots.append(rots[0])
    hips.append(hips[0])
    channels = [("Hips", "translation", "LINEAR", times, hips)]
    for name in ("UpperLeg.L", "LowerLeg.L", "UpperLeg.R", "LowerLeg.R",
                 "UpperArm.L", "LowerArm.L", "UpperArm.R", "LowerArm.R"):
        channels.append((name, "rotation", "LINEAR", times, [r[name] for r in rots]))
    # The chest turns against the hips, a smooth curve: CUBICSPLINE with exact tangents
    # of a(t) = 5 sin(2 pi t) degrees about y (in-tangent, value, out-tangent per key).
    cubic = []
    for t in times:
        a = math.radians(5.0) * math.sin(2.0 * math.pi * (t % 1.0))
        da = math.radians(5.0) * 2.0 * math.pi * math.cos(2.0 * math.pi * (t % 1.0))
        q = [0.0, math.sin(a / 2.0), 0.0, math.cos(a / 2.0)]
        dq = [0.0, math.cos(a / 2.0) * da / 2.0, 0.0, -math.sin(a / 2.0) * da / 2.0]
        cubic.append((dq, q, dq))
    channels.append(("Chest", "rotation", "CUBICSPLINE", times, cubic))
    return channels


def wave():
    times = [0.0, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 2.0]
    raise_ = quat_mul(quat_axis(Z, -125.0), quat_axis(X, -10.0))
    rest = [0.0, 0.0, 0.0, 1.0]
    upper = [rest] + [raise_] * 7 + [rest]
    fore = [rest]
    for k in range(1, 8):
        swing = 0.0 if k == 7 else (25.0 if k % 2 else -25.0)
        fore.append(quat_axis(Z, -20.0 + swing))
    fore.append(rest)
    head = [rest, quat_axis(Z, -6.0), quat_axis(Z, -6.0), quat_axis(Z, -6.0),
            quat_axis(Z, -6.0), quat_axis(Z, -6.0), quat_axis(Z, -6.0), quat_axis(Z, -6.0),
            rest]
    return [
        ("UpperArm.R", "rotation", "LINEAR", times, upper),
        ("LowerArm.R", "rotation", "LINEAR", times, fore),
        ("Head", "rotation", "LINEAR", times, head),
    ]


# ---------------------------------------------------------------- the glTF writer


class Writer:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors = [], []

    def _view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin.extend(data)
        self.views.append(view)
        return len(self.views) - 1

    def accessor(self, rows, kind, comp, fmt, target=None, minmax=False, normalized=False):
        flat = [x for row in rows for x in (row if isinstance(row, (list, tuple)) else [row])]
        data = struct.pack("<%d%s" % (len(flat), fmt), *flat)
        acc = {"bufferView": self._view(data, target), "componentType": comp,
               "count": len(rows), "type": kind}
        if normalized:
            acc["normalized"] = True
        if minmax:
            width = len(rows[0]) if isinstance(rows[0], (list, tuple)) else 1
            f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
            cols = [[f32(r[c]) if width > 1 else f32(r) for r in rows] for c in range(width)]
            acc["min"] = [min(c) for c in cols]
            acc["max"] = [max(c) for c in cols]
        self.accessors.append(acc)
        return len(self.accessors) - 1


FLOAT, USHORT, UBYTE = 5126, 5123, 5121
ARRAY, ELEMENT = 34962, 34963


def material(name, colour, roughness):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": colour + [1.0],
            "metallicFactor": 0.0, "roughnessFactor": roughness}}


def build():
    looks = ["shirt", "skin", "trousers", "shoes"]
    materials = [
        material("Shirt", [0.025, 0.07, 0.2], 0.6),
        material("Skin", [0.38, 0.22, 0.15], 0.7),
        material("Trousers", [0.09, 0.08, 0.07], 0.9),
        material("Shoes", [0.05, 0.03, 0.02], 0.4),
        material("Ground", [0.12, 0.12, 0.12], 1.0),
    ]
    parts = body()
    w = Writer()
    prims = []
    shoes = []
    for li, look in enumerate(looks):
        pos, nor, jnt, wgt, idx = [], [], [], [], []
        for part in (p for p in parts if p.look == look):
            base = len(pos)
            normals = smooth_normals(part)
            for p, n, weights in zip(part.p, normals, part.w):
                js, ws = top2(weights)
                pos.append(p)
                nor.append(n)
                jnt.append(js)
                wgt.append(ws)
                if look == "shoes":
                    shoes.append((JOINTS[js[0]][0], p))
            idx.extend(base + k for t in part.tris for k in t)
        prims.append({
            "attributes": {
                "POSITION": w.accessor(pos, "VEC3", FLOAT, "f", ARRAY, minmax=True),
                "NORMAL": w.accessor(nor, "VEC3", FLOAT, "f", ARRAY),
                "JOINTS_0": w.accessor(jnt, "VEC4", UBYTE, "B", ARRAY),
                "WEIGHTS_0": w.accessor(wgt, "VEC4", FLOAT, "f", ARRAY),
            },
            "indices": w.accessor(idx, "SCALAR", USHORT, "H", ELEMENT),
            "material": li,
        })
    ground = {
        "attributes": {
            "POSITION": w.accessor([[-5.0, 0.0, -5.0], [5.0, 0.0, -5.0], [5.0, 0.0, 5.0],
                                    [-5.0, 0.0, 5.0]], "VEC3", FLOAT, "f", ARRAY, minmax=True),
            "NORMAL": w.accessor([[0.0, 1.0, 0.0]] * 4, "VEC3", FLOAT, "f", ARRAY),
        },
        "indices": w.accessor([0, 2, 1, 0, 3, 2], "SCALAR", USHORT, "H", ELEMENT),
        "material": 4,
    }
    ibm = []
    for name, _, _ in JOINTS:
        p = WORLD[name]
        ibm.append([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -p[0], -p[1], -p[2], 1])
    ibm_acc = w.accessor(ibm, "MAT4", FLOAT, "f")

    nodes = [{"name": "Walker", "mesh": 0, "skin": 0}]
    first_joint = len(nodes)
    for name, parent, t in JOINTS:
        node = {"name": name, "translation": t}
        kids = [first_joint + k for k, (_, par, _) in enumerate(JOINTS) if par == name]
        if kids:
            node["children"] = kids
        nodes.append(node)
    nodes.append({"name": "Ground", "mesh": 1})
    eye, chest = [2.5, 1.6, 4.0], [0.0, 1.2, 0.0]
    nodes.append({"name": "Cam", "camera": 0, "translation": eye,
                  "rotation": look_rotation(eye, chest)})
    sun_from = [-3.0, 6.0, 4.0]
    nodes.append({"name": "Sun", "translation": sun_from,
                  "rotation": look_rotation(sun_from, [0.0, 0.0, 0.0]),
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"name": "Fill", "translation": [3.0, 2.2, 1.5],
                  "extensions": {"KHR_lights_punctual": {"light": 1}}})

    def animation(name, channels):
        out = {"name": name, "channels": [], "samplers": []}
        for node_name, path, interp, times, values in channels:
            flat = []
            for v in values:
                flat.extend(v if interp != "CUBICSPLINE" else [c for part in v for c in part])
            width = 3 if path == "translation" else 4
            rows = [flat[i:i + width] for i in range(0, len(flat), width)]
            kind = "VEC3" if width == 3 else "VEC4"
            inp = w.accessor(times, "SCALAR", FLOAT, "f", minmax=True)
            outp = w.accessor(rows, kind, FLOAT, "f")
            out["samplers"].append({"input": inp, "output": outp, "interpolation": interp})
            out["channels"].append({"sampler": len(out["samplers"]) - 1,
                                    "target": {"node": first_joint + J[node_name],
                                               "path": path}})
        return out

    animations = [animation("Walk", walk(shoes)), animation("Wave", wave())]
    gltf = {
        "asset": {"version": "2.0", "generator": "whitted scenes/models/make_walker.py",
                  "copyright": "CC0 1.0: no rights reserved"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"name": "Walker", "nodes": [0, first_joint] + list(
            range(first_joint + len(JOINTS), len(nodes)))}],
        "nodes": nodes,
        "meshes": [{"name": "Walker", "primitives": prims},
                   {"name": "Ground", "primitives": [ground]}],
        "skins": [{"name": "Walker", "skeleton": first_joint, "inverseBindMatrices": ibm_acc,
                   "joints": [first_joint + k for k in range(len(JOINTS))]}],
        "materials": materials,
        "cameras": [{"name": "Cam", "type": "perspective",
                     "perspective": {"yfov": 0.62, "aspectRatio": 4.0 / 3.0, "znear": 0.05,
                                     "zfar": 100.0}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Sun", "type": "directional", "color": [1.0, 0.96, 0.9],
             "intensity": 3.0},
            {"name": "Fill", "type": "point", "color": [0.85, 0.9, 1.0], "intensity": 20.0,
             "range": 20.0},
        ]}},
        "animations": animations,
        "accessors": w.accessors,
        "bufferViews": w.views,
        "buffers": [{"byteLength": 0}],
    }
    while len(w.bin) % 4:
        w.bin.append(0)
    gltf["buffers"][0]["byteLength"] = len(w.bin)
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    total = 12 + 8 + len(text) + 8 + len(w.bin)
    glb = struct.pack("<III", 0x46546C67, 2, total)
    glb += struct.pack("<II", len(text), 0x4E4F534A) + text
    glb += struct.pack("<II", len(w.bin), 0x004E4942) + bytes(w.bin)
    return glb


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "walker.glb")
    data = build()
    with open(out + ".tmp", "wb") as f:
        f.write(data)
    os.replace(out + ".tmp", out)
    print("%s: %d bytes" % (out, len(data)))


if __name__ == "__main__":
    main()
