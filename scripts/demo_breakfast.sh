#!/usr/bin/env bash
# `./asr demo breakfast`: generate the suite's own breakfast demonstration, learn ISM trees from a
# star and a complete relation topology, and recognise a correct and a disturbed place setting.
# Usage: scripts/demo_breakfast.sh <folder with the built tools> [output folder]
set -euo pipefail

TOOLS="$1"
OUT="${2:-$(cd "$(dirname "$0")/.." && pwd)/out/demo_breakfast}"
ISM="$TOOLS/ism"
mkdir -p "$OUT"

step() { printf '\n=== %s\n' "$*"; }

step "1. Demonstration: a breakfast setting recorded over time (generated, with sensor noise)"
"$TOOLS/asr_demo_data" --out "$OUT" --force

for topology in star complete; do
  step "2. Learn an ISM tree from the $topology topology"
  rm -f "$OUT/breakfast_$topology.sqlite"
  "$ISM" learn --demo "$OUT/breakfast.sqlite" --scene breakfast --topology "$topology" \
    --model "$OUT/breakfast_$topology.sqlite"
  "$ISM" info --model "$OUT/breakfast_$topology.sqlite" | head -n 2
done

for configuration in correct disturbed; do
  for topology in star complete; do
    step "3. Recognise the $configuration setting with the $topology tree"
    "$ISM" recognize --model "$OUT/breakfast_$topology.sqlite" --scene breakfast \
      --objects "$OUT/breakfast_$configuration.yaml"
  done
done

step "Done. Files are in $OUT; try: ./asr ism recognize --model $OUT/breakfast_complete.sqlite --scene breakfast --objects $OUT/breakfast_disturbed.yaml --json"
