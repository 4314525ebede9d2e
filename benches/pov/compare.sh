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
set -euo pipefail
N=${1:-25}
THREADS=${THREADS:-2}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
BIN_DIR=${BIN_DIR:-${CARGO_TARGET_DIR:-$repo/target}/release}
work=$(mktemp -d /tmp/pov-compare.XXXXXX)
[ "${KEEP:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
command -v povray >/dev/null || { echo "povray is not installed" >&2; exit 2; }
[ -x "$BIN_DIR/raytrace" ] || { echo "no $BIN_DIR/raytrace: cargo build --release" >&2; exit 2; }

# wall and CPU seconds from a /usr/bin/time -v report
times() {
  awk -F': ' '
    /Elapsed \(wall clock\)/ { n = split($2, a, ":"); w = 0; for (i = 1; i <= n; i++) w = w * 60 + a[i] }
    /User time/ { u = $2 } /System time/ { s = $2 }
    END { printf "%.3f %.3f\n", w, u + s }' "$1"
}

# --- POV-Ray -----------------------------------------------------------------------
mkdir -p "$work/pov"
last=$((N - 1))
/usr/bin/time -v -o "$work/pov.time" \
  povray +I"$here/orbit.pov" +O"$work/pov/frame.png" +W640 +H480 +WT"$THREADS" -A -D +FN \
    File_Gamma=1.0 +KFI0 +KFF"$last" +KI0 +KF"$last" Declare=Frames="$N" -GA \
    >"$work/pov.log" 2>&1 || { tail -20 "$work/pov.log" >&2; exit 1; }
read -r pov_wall pov_cpu < <(times "$work/pov.time")

# --- ours --------------------------------------------------------------------------
mkdir -p "$work/ours"
how=""
if [ -x "$BIN_DIR/animate" ]; then
  cat >"$work/orbit.toml" <<TOML
scene = "$here/orbit.txt"
frames = $N
fps = 25

[camera]
path = "circle"
center = [0.0, 1.0, 0.0]
radius = 12.0
height = 3.0
start_angle = 0.0
turns = 1.0

[output]
dir = "$work/ours"
name = "frame_####"
format = "png"
TOML
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
