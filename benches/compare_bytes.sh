#!/usr/bin/env bash
# Byte-for-byte regression of the tracer against reference renders.
#
#   benches/compare_bytes.sh make  REFDIR BIN   # render the references with BIN (e.g. a copy
#                                               # of the binary before an optimisation)
#   benches/compare_bytes.sh check REFDIR BIN   # render again with BIN and `cmp` every image
#
# Scenes: benches/pov/orbit.txt at six orbit angles, benches/scenes/*.txt, the project's
# scenes/*.txt, and the 10 and
# 10,000 sphere scenes of benches/gen_spheres.py (the latter at 320x240 to keep the linear
# reference build bearable); each at 1 sample/px, and orbit + edge also at 2x2 samples and
# with one thread. Output is .raw (the report's format), so nothing but pixels is compared.
# When BIN writes EXR (`--passes`), orbit_0 and edge are also rendered as .exr with every
# pass (half and float, 1 and 2 threads, 2x2 samples) and compared byte for byte: the
# layered path must be as deterministic as the default one.
set -euo pipefail
mode=${1:?make or check}; ref=${2:?REFDIR}; bin=${3:?BIN}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -p "$ref"

scenes=()
for deg in 0 45 110 180 250 320; do
  read -r x z < <(awk -v d="$deg" 'BEGIN{a=d*atan2(0,-1)/180; printf "%.17g %.17g\n", 12*sin(a), 12*cos(a)}')
  sed "0,/^0 3 12 /s//$x 3 $z /" "$here/pov/orbit.txt" > "$work/orbit_$deg.txt"
  scenes+=("$work/orbit_$deg.txt")
done
for s in "$here"/scenes/*.txt; do cp "$s" "$work/"; scenes+=("$work/$(basename "$s")"); done
# The project's own scenes, when there are some (read, never changed), with the folders
# their meshes and images are read from beside them.
for d in "$here"/../scenes/*/; do [ -d "$d" ] && ln -s "$d" "$work/$(basename "$d")"; done
for s in "$here"/../scenes/*.txt; do
  [ -e "$s" ] || continue
  cp "$s" "$work/proj-$(basename "$s")"; scenes+=("$work/proj-$(basename "$s")")
done
python3 "$here/gen_spheres.py" 10 > "$work/spheres10.txt"
python3 "$here/gen_spheres.py" 10000 320 240 > "$work/spheres10000.txt"
scenes+=("$work/spheres10.txt" "$work/spheres10000.txt")

fail=0
ext=raw
run() { # name scene args...
  local name=$1 scene=$2; shift 2
  local out="$work/$name.$ext"
  "$bin" "$scene" -o "$out" -q "$@"
  if [ "$mode" = make ]; then
    cp "$out" "$ref/$name.$ext"; echo "made  $name.$ext"
  elif cmp -s "$out" "$ref/$name.$ext"; then
    echo "same  $name.$ext"
  else
    echo "DIFF  $name.$ext: $(cmp -l "$out" "$ref/$name.$ext" | wc -l) bytes differ"; fail=1
  fi
}
for s in "${scenes[@]}"; do
  n=$(basename "$s" .txt)
  run "$n" "$s"
  case $n in orbit_0|orbit_110|edge)
    run "${n}_s2" "$s" --samples 2
    run "${n}_t1" "$s" --threads 1;;
  esac
done
if [ "$mode" = check ] && [ ! -e "$ref/orbit_0_passes.exr" ]; then
  echo "skip  EXR: the references were made by a binary without EXR"
elif "$bin" --help | grep -q -- --passes; then
  ext=exr
  for s in "$work/orbit_0.txt" "$here/scenes/edge.txt"; do
    [ -e "$s" ] || continue
    n=$(basename "$s" .txt)
    run "${n}_passes" "$s" --passes all
    run "${n}_passes_t1" "$s" --passes all --threads 1 --exr-depth float
    run "${n}_passes_s2" "$s" --passes all --samples 2 --exr-depth float
  done
elif [ "$mode" = check ]; then
  # The references have EXR renders that this binary cannot make: not the same bytes.
  echo "DIFF  EXR: the references have EXR renders but $bin has no --passes"; fail=1
fi
exit $fail
