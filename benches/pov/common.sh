# Sourced by compare.sh and adaptive.sh (POV-Ray 3.7 against our tracer on the orbit of
# orbit.txt / orbit.pov): the folders, the work folder, POV-Ray's command, the orbit
# manifest and /usr/bin/time's figures.
#
#   . "$(dirname "$0")/common.sh"; pov_setup NAME
#
# POV-Ray is not installed by .ci/run (CI does not run the benches): on Debian,
# `apt-get install povray` (3.7).
#
# Environment: BIN_DIR, the folder of our binaries (default: the release folder of
# $CARGO_TARGET_DIR, else target/release); THREADS (default 2); KEEP=1 keeps the work folder.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
THREADS=${THREADS:-2}
BIN_DIR=${BIN_DIR:-${CARGO_TARGET_DIR:-$repo/target}/release}

pov_setup() { # pov_setup NAME: $work = /tmp/pov-NAME.XXXXXX (removed at exit unless KEEP=1)
  work=$(mktemp -d "/tmp/pov-$1.XXXXXX")
  [ "${KEEP:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
  command -v povray >/dev/null || {
    echo "povray is not installed (Debian: apt-get install povray)" >&2
    exit 2
  }
}

median() { # median < NUMBERS: the middle one of the lines read (the lower middle of an even count)
  sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'
}

times() { # times TIMEFILE: wall and CPU (user + sys) seconds from a /usr/bin/time -v report
  awk -F': ' '
    /Elapsed \(wall clock\)/ { n = split($2, a, ":"); w = 0; for (i = 1; i <= n; i++) w = w * 60 + a[i] }
    /User time/ { u = $2 } /System time/ { s = $2 }
    END { printf "%.3f %.3f\n", w, u + s }' "$1"
}

pov() { # pov OUT.png TIMEFILE [options...]: POV-Ray on orbit.pov at 640x480, timed
  local out=$1 tf=$2; shift 2
  /usr/bin/time -v -o "$tf" povray +I"$here/orbit.pov" +O"$out" +W640 +H480 +WT"$THREADS" \
    -D +FN File_Gamma=1.0 -GA "$@" >"$work/pov.log" 2>&1 || { tail -20 "$work/pov.log" >&2; exit 1; }
}

pov_frames() { # pov_frames N: POV-Ray's options for an animation of N frames (clock = frame)
  local last=$(($1 - 1))
  echo "+KFI0 +KFF$last +KI0 +KF$last Declare=Frames=$1"
}

orbit_manifest() { # orbit_manifest FILE FRAMES OUTDIR [RENDER-LINES]: the orbit as a manifest
  cat >"$1" <<TOML
scene = "$here/orbit.txt"
frames = $2
fps = 25

[camera]
path = "circle"
center = [0.0, 1.0, 0.0]
radius = 12.0
height = 3.0
start_angle = 0.0
turns = 1.0

[output]
dir = "$3"
name = "frame_####"
format = "png"
TOML
  if [ -n "${4:-}" ]; then printf '\n[render]\n%s\n' "$4" >>"$1"; fi
}
