#!/usr/bin/env bash
# extract_corpus.sh ARCHIVE DIR — Debian libcgal-demo's meshes (data/meshes of
# its data archive) into DIR, once.
set -euo pipefail
archive=$1 dir=$2
[ -f "$archive" ] || { echo "extract_corpus: $archive is missing: apt-get install libcgal-demo (./vgc installs it)" >&2; exit 1; }
if [ -f "$dir/.extracted" ] && [ "$dir/.extracted" -nt "$archive" ]; then exit 0; fi
rm -rf "$dir.tmp" && mkdir -p "$dir.tmp"
tar -xzf "$archive" -C "$dir.tmp" data/meshes
rm -rf "$dir" && mv "$dir.tmp/data/meshes" "$dir" && rm -rf "$dir.tmp"
touch "$dir/.extracted"
echo "extract_corpus: $(ls "$dir" | wc -l) meshes in $dir"
