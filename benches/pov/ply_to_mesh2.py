#!/usr/bin/env python3
"""Writes a binary little-endian PLY triangle mesh as a POV-Ray `mesh2` with smooth
normals, for timing POV-Ray against our tracer on the same model (benches/pov/models.sh).

    python3 benches/pov/ply_to_mesh2.py IN.ply OUT.inc FIT TX TY TZ

Reads `element vertex` with float x, y, z (first three properties) and `element face`
with `property list uchar int vertex_indices` (triangles only), as
scenes/models/obj_to_ply.py and examples/torus_ply.rs write them. The mesh is placed as
the tracer's `fit FIT  pivot center  translate TX TY TZ` places it (largest side FIT, its
bounds' centre at T), and its normals are the area-weighted mean of the faces around each
vertex: close to the tracer's `smooth 30` on a scan, and the same work for POV-Ray's
smooth triangles. Needs numpy.
"""

import sys

import numpy as np


def read_ply(path):
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        body = f.read()
    nv = nf = 0
    props = 0
    for line in header:
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            nv, current = int(w[2]), "v"
        elif w[:2] == ["element", "face"]:
            nf, current = int(w[2]), "f"
        elif w and w[0] == "property" and current == "v":
            props += 1
    assert "format binary_little_endian 1.0" in header, "binary little-endian only"
    verts = np.frombuffer(body, dtype="<f4", count=nv * props).reshape(nv, props)[:, :3]
    faces = np.frombuffer(
        body, dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]), count=nf, offset=nv * props * 4
    )
    assert (faces["n"] == 3).all(), "triangles only"
    return verts.astype(np.float64), faces["i"].astype(np.int64)


def main():
    src, out, fit = sys.argv[1], sys.argv[2], float(sys.argv[3])
    t = np.array([float(x) for x in sys.argv[4:7]])
    v, f = read_ply(src)
    lo, hi = v.min(axis=0), v.max(axis=0)
    v = (v - (lo + hi) / 2) * (fit / (hi - lo).max()) + t
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    vn = np.zeros_like(v)
    for k in range(3):
        np.add.at(vn, f[:, k], n)
    vn /= np.maximum(np.linalg.norm(vn, axis=1, keepdims=True), 1e-300)
    with open(out, "w") as o:
        # POV-Ray is left-handed: z is negated (the scene's camera and lights too).
        o.write("mesh2 {\nvertex_vectors { %d,\n" % len(v))
        o.write(",\n".join("<%.7g,%.7g,%.7g>" % (x, y, -z) for x, y, z in v))
        o.write("}\nnormal_vectors { %d,\n" % len(vn))
        o.write(",\n".join("<%.7g,%.7g,%.7g>" % (x, y, -z) for x, y, z in vn))
        o.write("}\nface_indices { %d,\n" % len(f))
        o.write(",\n".join("<%d,%d,%d>" % tuple(t) for t in f))
        o.write("}\n}\n")


if __name__ == "__main__":
    main()
