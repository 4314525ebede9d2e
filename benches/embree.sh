#!/usr/bin/env bash
# The Embree goal of docs/performance.md: on the three polygon-only SPD databases (tetra,
# teapot, gears: their polygons fanned into triangles), the rays our tracer casts for a
# frame (`raytrace NAME.nff`: 512x512, camera rays through the pixel centres, shadow rays,
# reflection and refraction) cast again by Intel Embree 4 through PyPI embreex, only its
# traversal calls timed, against our whole `raytrace` process on one thread (parse, tree
# build, shading, PNG). Each database is dumped once (examples/embree_rays, not timed),
# then RUNS runs (default 5) of ours and of Embree in turn, both pinned to CPU $CPU
# (default 0; PIN=0 leaves them free); medians printed: wall and CPU seconds of each, the
# rays per second, ours over Embree, and the share of Embree's answers that agree with ours.
#
#   cargo build --release --bin raytrace --features examples --example embree_rays
#   benches/embree.sh [NAME...]            # default: tetra teapot gears
#   SPD=/path/to/spd RUNS=9 benches/embree.sh
#
# Needs python3 with embreex (`pip install embreex`: numpy comes with it).
# Environment: BIN_DIR (default: the release folder of $CARGO_TARGET_DIR, else
# target/release); KEEP=1 keeps the work folder (the dumps are 30 to 180 MB each).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
SPD=${SPD:-$repo/../shared/spd}
RUNS=${RUNS:-5}
CPU=${CPU:-0}
BIN_DIR=${BIN_DIR:-${CARGO_TARGET_DIR:-$repo/target}/release}
dump="$BIN_DIR/examples/embree_rays"
for f in "$BIN_DIR/raytrace" "$dump"; do
  [ -x "$f" ] || {
    echo "$f is missing: cargo build --release --bin raytrace --features examples --example embree_rays" >&2
    exit 2
  }
done
python3 -c 'import embreex' 2>/dev/null || {
  echo "python3 cannot import embreex (pip install embreex)" >&2
  exit 2
}
pin=()
if [ "${PIN:-1}" = 1 ] && command -v taskset >/dev/null; then pin=(taskset -c "$CPU"); fi
work=$(mktemp -d /tmp/embree-spd.XXXXXX)
[ "${KEEP:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(tetra teapot gears)
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
field() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$@"; }
printf "%-7s %9s %9s %9s %9s %9s %8s %8s %7s %7s %8s\n" scene rays our_wall our_cpu \
  emb_wall emb_cpu our_Mr/s emb_Mr/s wall_x cpu_x agree
tw=0; tc=0; ew=0; ec=0; tr=0
for n in "${names[@]}"; do
  "$dump" "$SPD/$n.nff" "$work/$n" >/dev/null
  : >"$work/our.t"; : >"$work/emb.t"
  for _ in $(seq "$RUNS"); do
    "${pin[@]}" python3 "$here/embree/timeproc.py" "$BIN_DIR/raytrace" "$SPD/$n.nff" \
      -o "$work/$n.png" --threads 1 -q >>"$work/our.t"
    "${pin[@]}" python3 "$here/embree/cast.py" "$work/$n" >"$work/$n.json"
    field "$work/$n.json" '"%s %s" % (d["seconds"]["total"], d["seconds"]["cpu"])' >>"$work/emb.t"
  done
  rays=$(field "$work/$n.json" 'sum(d["rays"].values())')
  agree=$(field "$work/$n.json" 'd["agree_all"]')
  ow=$(cut -d' ' -f1 "$work/our.t" | median); oc=$(cut -d' ' -f2 "$work/our.t" | median)
  w=$(cut -d' ' -f1 "$work/emb.t" | median); c=$(cut -d' ' -f2 "$work/emb.t" | median)
  tw=$(echo "$tw + $ow" | bc -l); tc=$(echo "$tc + $oc" | bc -l)
  ew=$(echo "$ew + $w" | bc -l); ec=$(echo "$ec + $c" | bc -l); tr=$((tr + rays))
  printf "%-7s %9d %9.3f %9.3f %9.3f %9.3f %8.2f %8.2f %7.2f %7.2f %8.5f\n" "$n" "$rays" \
    "$ow" "$oc" "$w" "$c" "$(echo "$rays / $ow / 1000000" | bc -l)" \
    "$(echo "$rays / $w / 1000000" | bc -l)" "$(echo "$ow / $w" | bc -l)" \
    "$(echo "$oc / $c" | bc -l)" "$agree"
done
printf "%-7s %9d %9.3f %9.3f %9.3f %9.3f %8.2f %8.2f %7.2f %7.2f\n" all "$tr" "$tw" "$tc" \
  "$ew" "$ec" "$(echo "$tr / $tw / 1000000" | bc -l)" "$(echo "$tr / $ew / 1000000" | bc -l)" \
  "$(echo "$tw / $ew" | bc -l)" "$(echo "$tc / $ec" | bc -l)"
