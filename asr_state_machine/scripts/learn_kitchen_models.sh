#!/usr/bin/env bash
# Learns the kitchen's scene models (gedeck, Brot_Regal, Muesli_Regal, star topologies) from the
# recordings, each without the set that places it in config/worlds/kitchen.yaml, into
# OUT/kitchen_models.sqlite (default OUT: out/kitchen in the repository).
# Usage: asr_state_machine/scripts/learn_kitchen_models.sh [OUT [--recordings DIR]]
# (after `./asr build`; the tool is devel/lib/asr_state_machine/learn_kitchen_models).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OUT="${1:-$ROOT/out/kitchen}"
shift || true
TOOL="$ROOT/devel/lib/asr_state_machine/learn_kitchen_models"
if [ ! -x "$TOOL" ]; then
  echo "learn_kitchen_models.sh: $TOOL is not built; run ./asr build first" >&2
  exit 1
fi
mkdir -p "$OUT"
rm -f "$OUT/kitchen_models.sqlite"
"$TOOL" --model "$OUT/kitchen_models.sqlite" "$@"
