#!/usr/bin/env bash
# The models goal of docs/performance.md: POV-Ray 3.7's `mesh2` against our `mesh` record
# on the same model at 1920x1080, lit by a 2x2 area light sampled on a 4x4 grid (POV-Ray:
# `area_light` without `adaptive` or `jitter`, so every one of the 16 points is shot, as
# ours are), one ray a pixel (-A), THREADS threads (default 2), whole processes timed by
# /usr/bin/time, RUNS runs each in turn (default 3), medians of wall and CPU (user +
# system) seconds, and POV-Ray's CPU over ours.
#
#   benches/pov/models.sh [bunny] [torus]
#
# bunny: the Stanford bunny (scenes/models/bunny.ply, 69,451 triangles);
# torus: a million-triangle torus written by examples/torus_ply.rs. POV-Ray's mesh2 gets
# area-weighted vertex normals (benches/pov/ply_to_mesh2.py, numpy), placed as our
# `fit` and `pivot center` place the model; ours are `smooth 180` (no crease splits, as
# POV-Ray's), so both trace smooth triangles everywhere.
. "$(dirname "$0")/common.sh"
set -euo pipefail
RUNS=${RUNS:-3}
pov_setup models
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(bunny torus)
model() { # model NAME: the PLY, fit, and centre height
  case $1 in
  bunny) echo "$repo/scenes/models/bunny.ply 2 0.992" ;;
  torus)
    [ -f "$work/torus.ply" ] ||
      (cd "$repo" && cargo run -q --release --features examples --example torus_ply -- "$work/torus.ply" 1000 500)
    echo "$work/torus.ply 3 0.6"
    ;;
  *) echo "unknown model $1 (bunny, torus)" >&2; exit 2 ;;
  esac
}
printf "%-6s %9s %9s %9s %9s %8s\n" model pov_wall pov_cpu our_wall our_cpu cpu_x
for n in "${names[@]}"; do
  read -r ply fit cy < <(model "$n")
  [ "$ply" -ef "$work/$n.ply" ] || cp "$ply" "$work/$n.ply"
  cat >"$work/$n.txt" <<SCENE
1920 1080  0 1.9 7.5  0 0.9 0  0 0  0 1 0 0
0 0 0  0 1 0   1 0.8 0.8 0.8   0.8 0 0 1 0 0
area 0 6 2  2 0 0  0 0 2  4 4   1 1 1  1
mesh "$n.ply"  1 0.9 0.72 0.55   0.85 0 0 1 0 0  fit $fit  pivot center  smooth 180  translate 0 $cy 0
SCENE
  python3 "$here/ply_to_mesh2.py" "$work/$n.ply" "$work/$n.inc" "$fit" 0 "$cy" 0
  cat >"$work/$n.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 1.9, -7.5> look_at <0, 0.9, 0> right x*0.5 up y*0.35 direction z }
light_source { <0, 6, -2> color rgb 1 area_light <2, 0, 0>, <0, 0, -2>, 4, 4 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }
object { #include "$n.inc" pigment { rgb <0.9, 0.72, 0.55> } finish { ambient 0.1 diffuse 0.85 } }
POV
  : >"$work/pov.t"; : >"$work/our.t"
  for _ in $(seq "$RUNS"); do
    (cd "$work" && /usr/bin/time -v -o t povray +I"$n.pov" +O"$n-pov.png" +W1920 +H1080 \
      +WT"$THREADS" -A -D +FN File_Gamma=1.0 -GA >pov.log 2>&1) ||
      { tail -20 "$work/pov.log" >&2; exit 1; }
    times "$work/t" >>"$work/pov.t"
    /usr/bin/time -v -o "$work/t" "$BIN_DIR/raytrace" "$work/$n.txt" -o "$work/$n-ours.png" \
      --threads "$THREADS" -q
    times "$work/t" >>"$work/our.t"
  done
  pw=$(cut -d' ' -f1 "$work/pov.t" | median); pc=$(cut -d' ' -f2 "$work/pov.t" | median)
  ow=$(cut -d' ' -f1 "$work/our.t" | median); oc=$(cut -d' ' -f2 "$work/our.t" | median)
  printf "%-6s %9.2f %9.2f %9.2f %9.2f %8.2f\n" "$n" "$pw" "$pc" "$ow" "$oc" \
    "$(echo "$pc / ($oc + 0.005)" | bc -l)"
done
