#!/usr/bin/env python3
"""Casts the rays our tracer cast for a frame with Intel Embree 4 (PyPI `embreex`).

    python3 benches/embree/cast.py DUMP_DIR

DUMP_DIR is what `cargo run --release --features examples --example embree_rays -- SCENE.nff DUMP_DIR` wrote
(triangles.f64, rays.f64, counts.json: examples/embree_rays/dump.rs says their layout).
The triangles go into one Embree triangle geometry (robust scene flag, embreex's
default); the scene is committed (its tree built) before any timing. Then, on the calling
thread only, two calls are timed with time.perf_counter (and time.process_time, whose
ratio to the wall time says whether any other thread worked meanwhile):

- the camera, reflection and refraction rays as nearest-hit queries (rtcIntersect1),
- the shadow rays as occlusion queries (rtcOccluded1) over their own t range.

Embree takes f32: every ray and corner is rounded from our f64 once. embreex starts every
ray at tnear = 0, so a ray's range (t_min, t_max) is given as the origin moved to t_min
along the ray (in f64, then rounded) and t_max - t_min. Embree's hits are then held to
ours: a nearest hit agrees when both miss, or both hit at t within 1e-4 relative; a shadow
ray agrees when both say blocked or both say clear. Where they differ, the counts say which
side found the nearer hit: Embree's f32 ray meets the surface it leaves (t near 0) on a
few secondary and shadow rays, where our f64 one starts past the scene's epsilon (1e-7 of
its size, below f32's resolution). Prints one JSON object.
"""

import json
import os
import sys
import time

import numpy as np

RAY_FLOATS = 11
KINDS = {"camera": 0, "reflect": 1, "refract": 2, "shadow": 3}
REL = 1e-4


def load(folder):
    tris = np.fromfile(os.path.join(folder, "triangles.f64"), dtype="<f8")
    rays = np.fromfile(os.path.join(folder, "rays.f64"), dtype="<f8")
    if tris.size % 9 or rays.size % RAY_FLOATS:
        sys.exit(f"cast.py: {folder}: truncated dump")
    with open(os.path.join(folder, "counts.json"), encoding="utf-8") as f:
        counts = json.load(f)
    return tris.reshape(-1, 3, 3), rays.reshape(-1, RAY_FLOATS), counts


def embree_inputs(rays):
    """f32 origins moved to t_min, f32 unit directions, f32 tfar = t_max - t_min."""
    org, d = rays[:, 1:4], rays[:, 4:7]
    t_min, t_max = rays[:, 7], rays[:, 8]
    origins = np.ascontiguousarray((org + d * t_min[:, None]).astype(np.float32))
    dirs = np.ascontiguousarray(d.astype(np.float32))
    tfar = np.where(np.isinf(t_max), 1e37, t_max - t_min).astype(np.float32)
    return origins, dirs, np.ascontiguousarray(tfar)


def agreement(mask, n):
    return float(mask.sum()) / n if n else 1.0


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: cast.py DUMP_DIR")
    try:
        from embreex import rtcore as rtc
        from embreex import rtcore_scene as rtcs
        from embreex.mesh_construction import TriangleMesh
    except ImportError as e:
        sys.exit(f"cast.py: embreex is not installed (pip install embreex): {e}")
    tris, rays, counts = load(sys.argv[1])
    kind = rays[:, 0]
    near, shad = rays[kind != KINDS["shadow"]], rays[kind == KINDS["shadow"]]
    n_org, n_dir, _ = embree_inputs(near)
    s_org, s_dir, s_far = embree_inputs(shad)

    device = rtc.EmbreeDevice()
    scene = rtcs.EmbreeScene(device)
    TriangleMesh(scene, np.ascontiguousarray(tris.astype(np.float32)))
    # The first query commits the scene (builds its tree): not timed.
    scene.run(np.zeros((1, 3), np.float32), np.ones((1, 3), np.float32))

    w0, c0 = time.perf_counter(), time.process_time()
    hit = scene.run(n_org, n_dir, query="INTERSECT", output=1)
    w1, c1 = time.perf_counter(), time.process_time()
    occ = scene.run(s_org, s_dir, dists=s_far, query="OCCLUDED")
    w2, c2 = time.perf_counter(), time.process_time()

    # Nearest hits: Embree's t counts from the moved origin.
    ours_t, ours_i = near[:, 9], near[:, 10]
    e_hit = hit["primID"] >= 0
    e_t = hit["tfar"].astype(np.float64) + near[:, 7]
    o_hit = np.isfinite(ours_t)
    close = np.abs(e_t - ours_t) <= REL * np.abs(ours_t)
    agree = (~e_hit & ~o_hit) | (e_hit & o_hit & close)
    same_prim = (~e_hit & ~o_hit) | (e_hit & o_hit & (hit["primID"] == ours_i))
    # Shadow rays: ours blocked when our nearest t is inside the ray's range.
    o_blocked = shad[:, 9] < shad[:, 8]
    s_agree = (occ == 0) == o_blocked
    # Where they differ, Embree nearer: it hit (blocked) where we found nothing nearer,
    # the f32 ray meeting the surface it leaves; Embree farther: it missed what we hit.
    nearer = int((~agree & e_hit & (~o_hit | (e_t < ours_t))).sum())
    nearer += int((~s_agree & (occ == 0)).sum())
    farther = int((~agree).sum() + (~s_agree).sum()) - nearer

    nk = near[:, 0]
    by_kind = {}
    for name in ("camera", "reflect", "refract"):
        m = nk == KINDS[name]
        by_kind[name] = agreement(agree[m], int(m.sum()))
    by_kind["shadow"] = agreement(s_agree, len(shad))
    wall = (w1 - w0) + (w2 - w1)
    total = len(rays)
    out = {
        "embree": repr(device).split(":")[-1].strip(),
        "triangles": len(tris),
        "rays": {k: int((kind == v).sum()) for k, v in KINDS.items()},
        "counts": counts,
        "seconds": {"nearest": w1 - w0, "shadow": w2 - w1, "total": wall, "cpu": c2 - c0},
        "cpu_over_wall": ((c1 - c0) + (c2 - c1)) / wall if wall > 0 else 0.0,
        "mrays_per_s": total / wall / 1e6 if wall > 0 else 0.0,
        "agree": by_kind,
        "agree_nearest": agreement(agree, len(near)),
        "same_triangle": agreement(same_prim, len(near)),
        "agree_all": (float(agree.sum()) + float(s_agree.sum())) / total if total else 1.0,
        "differ_embree_nearer": nearer,
        "differ_embree_farther": farther,
    }
    print(json.dumps(out))


if __name__ == "__main__":
    main()
