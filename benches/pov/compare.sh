#!/usr/bin/env bash
# POV-Ray 3.7 against our tracer on the same orbit: N frames of 640x480, camera on the
# circle of radius 12 at height 3 around (0, 1, 0), both on 2 threads, no anti-aliasing,
# the same recursion depth (max_trace_level 6 = primary ray + our 5 bounces).
#
#   benches/pov/compare.sh [N]        # N frames (default 25); PNG files into a temp folder
#
# Environment: BIN_DIR, the folder of our `animate` and `raytrace` (default: the release
# folder of $CARGO_TARGET_DIR, else target/release); THREADS (default 2); KEEP=1 keeps the
# frames. Ours: `animate` on a manifest written here (the same circle path) when it works,
# otherwise `raytrace` looped over per-frame scene files made with sed beforehand (not
# timed). POV-Ray: one `povray` run over the animation (+KFI0 +KFF<N-1>, clock = frame).
# Both are timed with /usr/bin/time -v: wall clock, and CPU = user + sys.
# POV-Ray: `apt-get install povray` (see common.sh, which this sources).
set -euo pipefail
N=${1:-25}
. "$(dirname "$0")/common.sh"
pov_setup compare
[ -x "$BIN_DIR/raytrace" ] || { echo "no $BIN_DIR/raytrace: cargo build --release" >&2; exit 2; }

# --- POV-Ray -----------------------------------------------------------------------
mkdir -p "$work/pov"
# shellcheck disable=SC2046 # the frame options are words
pov "$work/pov/frame.png" "$work/pov.time" -A $(pov_frames "$N")
read -r pov_wall pov_cpu < <(times "$work/pov.time")

# --- ours --------------------------------------------------------------------------
mkdir -p "$work/ours"
how=""
if [ -x "$BIN_DIR/animate" ]; then
  orbit_manifest "$work/orbit.toml" "$N" "$work/ours"
  if /usr/bin/time -v -o "$work/ours.time" "$BIN_DIR/animate" "$work/orbit.toml" -q \
       --threads "$THREADS" >"$work/ours.log" 2>&1 \
     && [ "$(ls "$work/ours" | grep -c '\.png$')" -eq "$N" ]; then
    how="animate"
  else
    echo "animate did not work (see below); falling back to raytrace" >&2
    tail -5 "$work/ours.log" >&2
    rm -rf "$work/ours"; mkdir -p "$work/ours"
  fi
fi
if [ -z "$how" ]; then
  # One scene file per frame (made before timing), the camera line replaced.
  mkdir -p "$work/scenes"
  for ((i = 0; i < N; i++)); do
    read -r x z < <(awk -v i="$i" -v n="$N" \
      'BEGIN { a = 2 * atan2(0, -1) * i / n; printf "%.17g %.17g\n", 12 * sin(a), 12 * cos(a) }')
    sed "0,/^0 3 12 /s//$x 3 $z /" "$here/orbit.txt" >"$work/scenes/$(printf 'frame_%04d' "$i").txt"
  done
  cat >"$work/loop.sh" <<LOOP
#!/usr/bin/env bash
set -e
for s in "$work"/scenes/*.txt; do
  "$BIN_DIR/raytrace" "\$s" -o "$work/ours/\$(basename "\$s" .txt).png" -q --threads $THREADS
done
LOOP
  chmod +x "$work/loop.sh"
  /usr/bin/time -v -o "$work/ours.time" "$work/loop.sh"
  how="raytrace loop"
fi
read -r our_wall our_cpu < <(times "$work/ours.time")

# --- report ------------------------------------------------------------------------
awk -v n="$N" -v t="$THREADS" -v how="$how" -v pw="$pov_wall" -v pc="$pov_cpu" \
    -v ow="$our_wall" -v oc="$our_cpu" 'BEGIN {
  printf "%d frames 640x480, %d threads (ours: %s)\n", n, t, how
  printf "%-10s %10s %10s %10s\n", "", "wall s", "CPU s", "frames/s"
  printf "%-10s %10.2f %10.2f %10.2f\n", "POV-Ray", pw, pc, n / pw
  printf "%-10s %10.2f %10.2f %10.2f\n", "ours", ow, oc, n / ow
  printf "ratios POV-Ray / ours: wall %.2fx, CPU %.2fx (issue 14 targets: >= 10x, >= 6x)\n", pw / ow, pc / oc
}'
