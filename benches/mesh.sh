#!/usr/bin/env bash
# The meshes goal of docs/performance.md: a binary PLY of a million triangles (a torus,
# examples/torus_ply.rs, written with ply-rs-bw) loaded, put in the tree and drawn at
# 640x480 by one whole `raytrace` process on two threads: wall time and peak memory
# (GNU time's "Maximum resident set size"), then the instructions of the same run on one
# thread (callgrind), which a loaded machine does not blur.
#
#   benches/mesh.sh [BIN_DIR]     # default: $CARGO_TARGET_DIR/release or target/release
#   CALLGRIND=0 benches/mesh.sh   # skip the (slow) instruction count
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
BIN_DIR=${1:-${CARGO_TARGET_DIR:-$repo/target}/release}
rt="$BIN_DIR/raytrace"
work=$(mktemp -d /tmp/mesh-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
cargo run -q --release --features examples --example torus_ply -- "$work/torus.ply" 1000 500
ls -l "$work/torus.ply"
cat >"$work/torus.txt" <<'SCENE'
640 480  0 4 7  0 -0.1 0  0 0  0 1 0 1
0 -0.45 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
mesh "torus.ply" 1 0.9 0.6 0.2  0.7 0 0 1 0 0 rotate 25 0 10
SCENE
echo "== $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/time -v "$rt" "$work/torus.txt" -o "$work/torus.png" --threads 2 2>"$work/time.txt"
grep -E "Elapsed|Maximum resident|User time|System time" "$work/time.txt"
if [ "${CALLGRIND:-1}" != 0 ]; then
  valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
    "$rt" "$work/torus.txt" -o "$work/torus.raw" --threads 1 2>&1 | grep refs
fi
if [ -n "${KEEP:-}" ]; then cp "$work/torus.png" "$KEEP"; fi
