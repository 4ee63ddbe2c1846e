#!/usr/bin/env bash
# campaign_finds.sh FUZZ_DIFFERENTIAL PLUGIN SEED_FILE WORK_DIR
# (libFuzzer build only) A bounded libFuzzer campaign, 60 s at most, seed 1,
# starting from SEED_FILE alone (the spec's cube: it holds no trigger of the
# seeded faults), against PLUGIN must stop with a fuzz_differential finding
# and save the input.
set -u
bin=$1 plugin=$2 seed=$3 work=$4
rm -rf "$work" && mkdir -p "$work/corpus"
cp "$seed" "$work/corpus/"
start=$(date +%s)
VGC_FUZZ_PLUGIN="$plugin" "$bin" -seed=1 -dict="$(dirname "$0")/../../corpora/fuzz/fuzz_differential.dict" -max_total_time=60 -artifact_prefix="$work/" "$work/corpus" >"$work/log" 2>&1
rc=$?
end=$(date +%s)
grep -m1 '^vgc-fuzz: FINDING' "$work/log"
[ "$rc" -ne 0 ] || { echo "campaign_finds: no finding within 60 s" >&2; exit 1; }
grep -q '^vgc-fuzz: FINDING in fuzz_differential' "$work/log" || { tail -30 "$work/log"; exit 1; }
ls "$work"/crash-* >/dev/null 2>&1 || { echo "campaign_finds: no crash input saved" >&2; exit 1; }
echo "campaign_finds: found in $((end - start)) s"
