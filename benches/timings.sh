#!/usr/bin/env bash
# Wall-clock figures of docs/performance.md, in one go (run it on an idle machine: the
# ratios only mean something when nothing else competes for the cores).
#
#   benches/timings.sh [BIN_DIR]     # default: $CARGO_TARGET_DIR/release or target/release
#
# - the orbit frame (benches/pov/orbit.txt, 640x480) with --threads 1 and --threads 2, and
#   the Mrays/s of raytrace's summary line;
# - 10 vs 10,000 spheres (benches/gen_spheres.py, 640x480), whole runs (parse, BVH, render,
#   PNG), and the 10,000-sphere scene at 1x1 pixel: parse + BVH build alone;
# - the orbit video: animate on animations/orbit.toml (250 frames 640x480 PNG).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
BIN_DIR=${1:-${CARGO_TARGET_DIR:-$repo/target}/release}
rt="$BIN_DIR/raytrace"
work=$(mktemp -d /tmp/timings.XXXXXX)
trap 'rm -rf "$work"' EXIT
python3 "$here/gen_spheres.py" 10 >"$work/spheres10.txt"
python3 "$here/gen_spheres.py" 10000 >"$work/spheres10000.txt"
python3 "$here/gen_spheres.py" 10000 1 1 >"$work/spheres10000_1px.txt"
echo "== $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
hf() { hyperfine -N -w 3 -r "${RUNS:-20}" "$@" 2>&1 | grep -E "Benchmark|Time|±|faster"; }

echo "== orbit frame, 1 vs 2 threads"
hf "$rt $here/pov/orbit.txt -o $work/o1.png -q --threads 1" \
   "$rt $here/pov/orbit.txt -o $work/o2.png -q --threads 2"
for t in 1 2; do "$rt" "$here/pov/orbit.txt" -o "$work/o.png" --threads $t; done

echo "== 10 vs 10,000 spheres (2 threads)"
hf "$rt $work/spheres10.txt -o $work/s10.png -q" \
   "$rt $work/spheres10000.txt -o $work/s10000.png -q"
echo "== 10,000 spheres at 1x1: parse + BVH build"
hf "$rt $work/spheres10000_1px.txt -o $work/s1px.png -q"

if [ -x "$BIN_DIR/animate" ] && [ -f "$repo/animations/orbit.toml" ]; then
  echo "== orbit video: animate animations/orbit.toml (250 frames)"
  /usr/bin/time -f "%e s wall, %U s user, %S s sys, %M KB max RSS" \
    "$BIN_DIR/animate" "$repo/animations/orbit.toml" -o "$work/video" 2>&1 | tail -2
fi
