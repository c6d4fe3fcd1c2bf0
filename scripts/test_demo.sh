#!/usr/bin/env bash
# Runs the main job, scripts/demo.sh (what `./asr demo` runs after the build), as a new user
# would meet it: no models learned yet, into a folder that does not exist yet; and checks what
# it promises: the kitchen searched to found_all_objects, the result, log, bag and picture
# written. Writes a JUnit result to $2 (run by `./asr test`).
# Usage: scripts/test_demo.sh <devel folder> <result file>
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEVEL="$1"
RESULT="$2"
TIMEOUT_S="${ASR_DEMO_TIMEOUT_S:-900}"
# shellcheck source=junit_result.sh
source "$ROOT/scripts/junit_result.sh"
# shellcheck source=await_session.sh
source "$ROOT/scripts/await_session.sh"
write_result() { junit_result "$RESULT" demo KitchenSearchFromAFreshStart "$1" "$2"; }

recordings="${ASR_RECORDINGS_DIR:-$ROOT/../shared/data/asr_recordings}"
if [ ! -f "$recordings/story_1.sqlite" ]; then
  write_result skipped "the recordings are absent ($recordings)"
  echo "demo test: skipped, the recordings are absent"
  exit 0
fi

work="$(mktemp -d /tmp/asr_demo_test.XXXXXX)"
trap 'rm -rf "$work"' EXIT
out="$work/demo"
models="$work/not_yet/kitchen_models.sqlite"
echo "demo test: running scripts/demo.sh into $out"
start=$(date +%s)
# In a session of its own, so that what a hung demo leaves running is ended by its id alone.
ASR_DEMO_MODELS="$models" setsid "$ROOT/scripts/demo.sh" "$DEVEL" "$out" >"$work/output.txt" 2>&1 &
await_session $! "$start" "$TIMEOUT_S" "$work/output.txt" "demo test"
status=$session_status
seconds=$session_seconds

problems=""
[ "$status" -ne 0 ] && problems="exit code $status after $seconds s; "
# The demo starts its own master, recorder and nodes: a user's machine must be left as it was.
[ -n "$session_leftovers" ] && problems+="left running after it ended: $(echo "$session_leftovers" | tr '\n' ';') "
[ -s "$models" ] || problems+="no models learned into $models; "
outcome=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["outcome"])' \
  "$out/result.json" 2>/dev/null)
reason=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["reason"])' \
  "$out/result.json" 2>/dev/null)
[ "$outcome" = "found_all_objects" ] ||
  problems+="outcome '${outcome:-none}'${reason:+ ($reason)}, not found_all_objects; "
for file in search_log.jsonl search.bag search.png; do
  [ -s "$out/$file" ] || problems+="no $file; "
done
grep -q "^outcome: found_all_objects" "$work/output.txt" || problems+="no summary printed; "
# The bag is on the search's simulated time: it spans the simulated seconds the result reports.
bag_span=$(/usr/bin/python3 -c '
import json, sys, rosbag
bag = rosbag.Bag(sys.argv[1])
span = bag.get_end_time() - bag.get_start_time()
print("ok" if abs(span - json.load(open(sys.argv[2]))["sim_seconds"]) < 1.0 else "%.1f s" % span)
' "$out/search.bag" "$out/result.json" 2>&1 | tail -n 1)
[ "$bag_span" = "ok" ] || problems+="the bag does not span the search's simulated time ($bag_span); "
if [ -n "$problems" ]; then
  tail -n 40 "$work/output.txt"
  write_result failed "$problems"
  echo "demo test: FAILED: $problems"
  exit 1
fi
write_result passed ""
echo "demo test: passed in $seconds s"
