#!/usr/bin/env bash
# The SPD goal of docs/performance.md: POV-Ray 3.7 on the SPD's own POV-Ray translations
# (../shared/spd/pov/NAME.pov) against our `raytrace` on the NFF files, each database at
# 512x512, one ray a pixel (POV-Ray -A), both on THREADS threads (default 2), whole
# processes timed by /usr/bin/time, RUNS runs each (default 3) in turn, medians printed:
# wall and CPU (user + system) seconds, and POV-Ray's CPU over ours.
#
#   benches/pov/spd.sh [NAME...]      # default: the seven databases
#   SPD=/path/to/spd RUNS=5 benches/pov/spd.sh
. "$(dirname "$0")/common.sh"
set -euo pipefail
SPD=${SPD:-$repo/../shared/spd}
RUNS=${RUNS:-3}
pov_setup spd
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(balls gears mount rings teapot tetra tree)
printf "%-7s %9s %9s %9s %9s %8s\n" scene pov_wall pov_cpu our_wall our_cpu cpu_x
tp=0; to=0
for n in "${names[@]}"; do
  : >"$work/pov.t"; : >"$work/our.t"
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -v -o "$work/t" povray +I"$SPD/pov/$n.pov" +O"$work/$n.png" +W512 +H512 \
      +WT"$THREADS" -A -D +FN File_Gamma=1.0 -GA >"$work/pov.log" 2>&1 ||
      { tail -20 "$work/pov.log" >&2; exit 1; }
    times "$work/t" >>"$work/pov.t"
    /usr/bin/time -v -o "$work/t" "$BIN_DIR/raytrace" "$SPD/$n.nff" -o "$work/$n-ours.png" \
      --threads "$THREADS" -q
    times "$work/t" >>"$work/our.t"
  done
  pw=$(cut -d' ' -f1 "$work/pov.t" | median); pc=$(cut -d' ' -f2 "$work/pov.t" | median)
  ow=$(cut -d' ' -f1 "$work/our.t" | median); oc=$(cut -d' ' -f2 "$work/our.t" | median)
  tp=$(echo "$tp + $pc" | bc -l); to=$(echo "$to + $oc" | bc -l)
  printf "%-7s %9.2f %9.2f %9.2f %9.2f %8.2f\n" "$n" "$pw" "$pc" "$ow" "$oc" \
    "$(echo "$pc / ($oc + 0.005)" | bc -l)"
done
printf "%-7s %9s %9.2f %9s %9.2f %8.2f\n" all "" "$tp" "" "$to" "$(echo "$tp / $to" | bc -l)"
