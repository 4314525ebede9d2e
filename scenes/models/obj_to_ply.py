#!/usr/bin/env python3
"""Converts a Wavefront OBJ mesh into a binary little-endian PLY: positions only.

    python3 scenes/models/obj_to_ply.py ../shared/models/bunny.obj scenes/models/bunny.ply

Reads `v x y z` (any extra values, such as vertex colours, are dropped) and `f` records
(`f a b c`, `f a/t/n ...`, negative indices counted back from the last vertex); a face of
more than three corners is kept as one polygon (the tracer fans it). Normals, texture
coordinates, groups and materials are not written: the tracer computes smooth normals for
a mesh without them (`smooth 30` by default). Writes

    element vertex N   property float x, y, z
    element face M     property list uchar int vertex_indices

Python 3 standard library only; the output depends on the input alone (same bytes on
every run). The file is written beside its final name and renamed when complete.
"""

import os
import struct
import sys


def read_obj(path):
    """Returns (vertices, faces) of the OBJ at `path`: [(x, y, z)], [[i, ...]] from 0."""
    vertices, faces = [], []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "v":
                if len(words) < 4:
                    sys.exit(f"{path}:{number}: a vertex needs x y z")
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "f":
                face = []
                for w in words[1:]:
                    i = int(w.split("/", 1)[0])
                    i = i - 1 if i > 0 else len(vertices) + i
                    if not 0 <= i < len(vertices):
                        sys.exit(f"{path}:{number}: vertex index {w} out of range")
                    face.append(i)
                if not 3 <= len(face) <= 255:
                    sys.exit(f"{path}:{number}: a face needs 3 to 255 corners")
                faces.append(face)
    return vertices, faces


def write_ply(path, vertices, faces):
    """Writes the binary little-endian PLY, through a temporary file renamed at the end."""
    header = (
        "ply\n"
        "format binary_little_endian 1.0\n"
        "comment converted from OBJ by scenes/models/obj_to_ply.py\n"
        f"element vertex {len(vertices)}\n"
        "property float x\n"
        "property float y\n"
        "property float z\n"
        f"element face {len(faces)}\n"
        "property list uchar int vertex_indices\n"
        "end_header\n"
    )
    tmp = path + ".part"
    with open(tmp, "wb") as f:
        f.write(header.encode("ascii"))
        for v in vertices:
            f.write(struct.pack("<3f", *v))
        for face in faces:
            f.write(struct.pack(f"<B{len(face)}i", len(face), *face))
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: obj_to_ply.py IN.obj OUT.ply")
    vertices, faces = read_obj(sys.argv[1])
    write_ply(sys.argv[2], vertices, faces)
    print(f"{sys.argv[2]}: {len(vertices)} vertices, {len(faces)} faces")


if __name__ == "__main__":
    main()
