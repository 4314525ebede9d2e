#!/usr/bin/env bash
# A profile-guided build of `raytrace` and `animate` for render farms (rustc's PGO).
#
#   farm/pgo-build.sh [OUTDIR]        # default: target/pgo of the project
#
# 1. builds both binaries with our crate instrumented (-Cprofile-generate), in OUTDIR/build;
# 2. runs them on a training set: every scene of scenes/ and benches/scenes/, the orbit
#    with adaptive anti-aliasing, and frames of the orbit and bounce animations through
#    `animate` (PNG encoding, tracks, blur);
# 3. merges the profiles with the llvm-profdata of rustc's own LLVM (rustup component
#    llvm-tools) and builds our crate again with -Cprofile-use (the dependencies are
#    built once, plain: the time is in our code);
# 4. renders the training scenes with the plain release binaries (PLAIN_BIN_DIR; default
#    the release folder of $CARGO_TARGET_DIR or target/, built first) and with the new
#    ones, and compares the bytes: if one image differs it stops with status 1 and copies
#    nothing.
# The binaries end in OUTDIR/raytrace and OUTDIR/animate (`ANIMATE=OUTDIR/animate sbatch
# ...`). The profile changes only how the code is laid out, inlined and branched, never
# the arithmetic (Rust neither reassociates nor contracts floating point), so the pixels
# are the plain build's; the orbit costs about 12 % less CPU (docs/performance.md).
# LLVM_PROFDATA names another llvm-profdata (it must read this rustc's LLVM's profiles).
# Status 2: llvm-profdata is missing (nothing is written); 1: the pixels differ; a failed
# build or render stops the script with its own non-zero status.
set -euo pipefail

# Called by cargo as the rustc wrapper: add the PGO flag to our own crates only.
if [ -n "${PGO_BUILD_FLAG:-}" ]; then
  rustc=$1
  shift
  case " $* " in
    *" --crate-name whitted "* | *" --crate-name whitted_cmd "* | *" --crate-name whitted_anim "* | *" --crate-name whitted_cli "* | *" --crate-name raytrace "* | *" --crate-name animate "*)
      exec "$rustc" "$@" "$PGO_BUILD_FLAG" ;;
  esac
  exec "$rustc" "$@"
fi

self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/target/pgo}
case $out in /*) ;; *) out=$PWD/$out ;; esac
cd "$root"

host=$(rustc -vV | sed -n 's/^host: //p')
profdata=${LLVM_PROFDATA:-"$(rustc --print sysroot)/lib/rustlib/$host/bin/llvm-profdata"}
if [ ! -x "$profdata" ]; then
  echo "pgo-build: no llvm-profdata for this rustc ($profdata)" >&2
  echo "pgo-build: install it with: rustup component add llvm-tools" >&2
  exit 2
fi
mkdir -p "$out"

build() { # the flag for our crates
  PGO_BUILD_FLAG=$1 RUSTC_WRAPPER=$self \
    cargo build --release --locked --quiet --bins --target-dir "$out/build"
}
bin="$out/build/release"
scenes=(scenes/*.txt benches/scenes/*.txt)
render() { # bin-dir, out-dir
  mkdir -p "$2"
  for s in "${scenes[@]}"; do
    "$1/raytrace" "$s" -o "$2/$(basename "$s" .txt).raw" --quiet
  done
  # Adaptive anti-aliasing's own code (the lattice, the measure) at its default.
  "$1/raytrace" scenes/orbit.txt -o "$2/orbit-adaptive.raw" --aa adaptive --quiet
}

profiles="$out/profiles"
rm -rf "$profiles" "$out/train" "$out/check" "$out/raytrace" "$out/animate"
echo "pgo-build: 1/4 instrumented build" >&2
cargo clean --release --quiet -p whitted -p whitted-cmd -p whitted-anim -p whitted-cli --target-dir "$out/build"
build "-Cprofile-generate=$profiles"

echo "pgo-build: 2/4 training" >&2
render "$bin" "$out/train"
"$bin/animate" animations/orbit.toml --frames 0,31,62,94,125,156,187,218 \
  -o "$out/train/orbit" --quiet
"$bin/animate" animations/bounce.toml --frames 0-3 -o "$out/train/bounce" --quiet
"$profdata" merge -o "$out/merged.profdata" "$profiles"

echo "pgo-build: 3/4 optimised build" >&2
cargo clean --release --quiet -p whitted -p whitted-cmd -p whitted-anim -p whitted-cli --target-dir "$out/build"
build "-Cprofile-use=$out/merged.profdata"

echo "pgo-build: 4/4 same bytes as the plain release build" >&2
plain=${PLAIN_BIN_DIR:-${CARGO_TARGET_DIR:-target}/release}
[ -n "${PLAIN_BIN_DIR:-}" ] || cargo build --release --locked --quiet --bins
render "$plain" "$out/check/plain"
render "$bin" "$out/check/pgo"
if ! diff -r "$out/check/plain" "$out/check/pgo" >&2; then
  echo "pgo-build: the optimised build draws other pixels than the plain one; not kept" >&2
  exit 1
fi
cp "$bin/raytrace" "$bin/animate" "$out/"
rm -rf "$out/check" "$out/train" "$profiles"
echo "pgo-build: $out/raytrace and $out/animate (${#scenes[@]} scenes, same bytes)" >&2
