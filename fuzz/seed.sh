#!/bin/sh
# Fills the fuzz corpora (fuzz/corpus/, not tracked) from the project's own inputs:
# every scene of scenes/, every manifest of animations/, and the small hand-made seeds
# of fuzz/seeds/. Run from anywhere; existing corpus entries are kept.
set -e
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$here/corpus/scene" "$here/corpus/manifest"
cp "$here"/../scenes/*.txt "$here"/seeds/scene/* "$here/corpus/scene/"
cp "$here"/../animations/*.toml "$here"/seeds/manifest/* "$here/corpus/manifest/"
echo "corpus: $(ls "$here/corpus/scene" | wc -l) scenes, $(ls "$here/corpus/manifest" | wc -l) manifests"
