#!/usr/bin/env python3
"""Writes a Scene.txt with N small spheres scattered over the checker floor.

    python3 benches/gen_spheres.py 10     > /tmp/spheres10.txt
    python3 benches/gen_spheres.py 10000  > /tmp/spheres10000.txt

The positions come from a fixed linear congruential generator, so a given N always gives
the same file, and the first k spheres of any two files are the same. Spheres lie on the
floor (y = r) in x in [-20, 20], z in [-40, 6], radius 0.05..0.12, each with its own uniform
colour; one sphere in ten is a mirror and one in twenty-five is glass, so the shadow and
secondary-ray paths are exercised too. Camera and lights are those of benches/pov/orbit.txt.
"""
import sys

def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
    w = int(sys.argv[2]) if len(sys.argv) > 2 else 640
    h = int(sys.argv[3]) if len(sys.argv) > 3 else 480
    state = 12345

    def rnd():
        nonlocal state
        state = (state * 6364136223846793005 + 1442695040888963407) % (1 << 64)
        return (state >> 11) / float(1 << 53)

    out = [f"# {n} small spheres over a checker floor (benches/gen_spheres.py {n})",
           f"{w} {h}", "0 3 12", "0 1 0", "2 40", f"{n} 1 0 2"]
    for i in range(n):
        r = 0.05 + 0.07 * rnd()
        x = -20.0 + 40.0 * rnd()
        z = -40.0 + 46.0 * rnd()
        cr, cg, cb = 0.2 + 0.8 * rnd(), 0.2 + 0.8 * rnd(), 0.2 + 0.8 * rnd()
        if i % 25 == 7:
            mat = "0.1 0.1 0.8 1.5 0 0"
        elif i % 10 == 3:
            mat = "0.2 0.8 0.0 1.0 0 0"
        else:
            mat = "0.8 0.0 0.0 1.0 0 0"
        out.append(f"{r:.4f} {x:.4f} {r:.4f} {z:.4f}  1 {cr:.3f} {cg:.3f} {cb:.3f}  {mat}")
    out.append("0 0 0  0 1 0  2 1 1 1 1 0.1 0.1 0.1 0 0 0  0.9 0.0 0.0 1.0 0 0")
    out.append("5 10 5  1 1 1  0.8")
    out.append("-6 8 3  1 0.9 0.8  0.5")
    print("\n".join(out))

main()
