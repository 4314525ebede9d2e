#!/usr/bin/env python3
"""Writes the two meshes of scenes/meshes.txt (deterministic, no third-party module):

    python3 benches/gen_meshes.py scenes/meshes

trefoil.ply: a tube of radius 0.32 around the trefoil knot
(sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t), 240 x 16 quads, a unit normal per
vertex (smooth shading), binary little-endian PLY with quad faces (the reader fans
them into triangles). The tube's frame is carried along the curve without twisting
(rotation minimising, double reflection) and its remaining twist at the join spread
over the length, so the tube closes without a seam.

gem.obj: a twelve-sided gem (a crown, a girdle and a pavilion), vertex positions only,
so the mesh is shaded flat, one normal per facet.
"""
import math
import os
import struct
import sys

def sub(a, b): return (a[0]-b[0], a[1]-b[1], a[2]-b[2])
def add(a, b): return (a[0]+b[0], a[1]+b[1], a[2]+b[2])
def mul(a, k): return (a[0]*k, a[1]*k, a[2]*k)
def dot(a, b): return a[0]*b[0]+a[1]*b[1]+a[2]*b[2]
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def unit(a): return mul(a, 1.0/math.sqrt(dot(a, a)))

def knot(t):
    return (math.sin(t) + 2*math.sin(2*t), math.cos(t) - 2*math.cos(2*t), -math.sin(3*t))

def trefoil(path, n=240, m=16, r=0.32):
    pts = [knot(2*math.pi*i/n) for i in range(n+1)]
    tang = [unit(sub(pts[(i+1) % n], pts[(i-1) % n])) for i in range(n)] + [None]
    tang[n] = tang[0]
    # rotation-minimising frame by double reflection (Wang et al. 2008)
    t0 = tang[0]
    u = unit(cross(t0, (0.0, 0.0, 1.0)))
    frames = [u]
    for i in range(n):
        v1 = sub(pts[i+1], pts[i]); c1 = dot(v1, v1)
        rl = sub(frames[i], mul(v1, 2*dot(v1, frames[i])/c1))
        tl = sub(tang[i], mul(v1, 2*dot(v1, tang[i])/c1))
        v2 = sub(tang[i+1], tl); c2 = dot(v2, v2)
        frames.append(unit(sub(rl, mul(v2, 2*dot(v2, rl)/c2))) if c2 > 0 else rl)
    # twist left at the join, spread over the length
    w0 = cross(t0, frames[0]); end = frames[n]
    twist = math.atan2(dot(end, w0), dot(end, frames[0]))
    verts = []
    for i in range(n):
        a = -twist*i/n
        uu = frames[i]; ww = cross(tang[i], uu)
        uu, ww = add(mul(uu, math.cos(a)), mul(ww, math.sin(a))), sub(mul(ww, math.cos(a)), mul(uu, math.sin(a)))
        for j in range(m):
            b = 2*math.pi*j/m
            nrm = unit(add(mul(uu, math.cos(b)), mul(ww, math.sin(b))))
            verts.append(add(pts[i], mul(nrm, r)) + nrm)
    faces = []
    for i in range(n):
        for j in range(m):
            a, b = i*m + j, i*m + (j+1) % m
            c, d = ((i+1) % n)*m + (j+1) % m, ((i+1) % n)*m + j
            faces.append((a, d, c, b))
    head = ("ply\nformat binary_little_endian 1.0\ncomment trefoil knot tube, benches/gen_meshes.py\n"
            f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\n"
            "property float nx\nproperty float ny\nproperty float nz\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as f:
        f.write(head.encode())
        for v in verts:
            f.write(struct.pack("<6f", *v))
        for q in faces:
            f.write(struct.pack("<B4i", 4, *q))

def gem(path, k=12):
    lines = ["# a twelve-sided gem: table, crown, girdle, pavilion (benches/gen_meshes.py)"]
    rings = [(0.55, 0.45), (1.0, 0.15), (1.0, 0.0)]  # (radius, height): table, crown, girdle
    verts = []
    for ring, (rad, h) in enumerate(rings):
        for i in range(k):
            a = 2*math.pi*(i + 0.5*(ring >= 1))/k
            verts.append((rad*math.cos(a), h, rad*math.sin(a)))
    verts.append((0.0, -0.9, 0.0))  # the pavilion's point
    for v in verts:
        lines.append("v %.6f %.6f %.6f" % v)
    tip = len(verts)
    lines.append("f " + " ".join(str(i+1) for i in reversed(range(k))))  # table, facing up
    for i in range(k):
        j = (i+1) % k
        # crown: table ring (0) to the staggered ring (1), triangles both ways
        lines.append("f %d %d %d" % (1+i, 1+k+i, 1+j))
        lines.append("f %d %d %d" % (1+j, 1+k+i, 1+k+j))
        # girdle band: ring 1 to ring 2
        lines.append("f %d %d %d %d" % (1+k+i, 1+2*k+i, 1+2*k+j, 1+k+j))
        # pavilion
        lines.append("f %d %d %d" % (1+2*k+i, tip, 1+2*k+j))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/meshes"
    os.makedirs(out, exist_ok=True)
    trefoil(os.path.join(out, "trefoil.ply"))
    gem(os.path.join(out, "gem.obj"))
