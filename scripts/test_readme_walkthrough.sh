#!/usr/bin/env bash
# Runs the README's ROS walkthrough (the first ```sh block after "## With ROS") as written, top
# to bottom in one shell, and writes a JUnit result to $1 (run by `./asr test`).
#
# The only things changed around it: a ROS master port of its own (a `roscore` on PATH that adds
# `-p PORT`, and ROS_MASTER_URI), so that it cannot meet another master on this machine, and ROS
# logs in a temporary folder. It waits for conditions, not for fixed times; the timeout is only
# for a walkthrough that hangs, and is generous (a 2-core machine needs 1-2 minutes).
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RESULT="${1:-$ROOT/build/test_results/readme/walkthrough.xml}"
TIMEOUT_S="${ASR_WALKTHROUGH_TIMEOUT_S:-600}"
mkdir -p "$(dirname "$RESULT")"

# shellcheck source=junit_result.sh
source "$ROOT/scripts/junit_result.sh"
# shellcheck source=await_session.sh
source "$ROOT/scripts/await_session.sh"
# Writes the JUnit result: $1 = passed | failed | skipped, $2 = message.
write_result() { junit_result "$RESULT" readme RosWalkthroughRunsAsWritten "$1" "$2"; }

recordings="${ASR_RECORDINGS_DIR:-$ROOT/../shared/data/asr_recordings}"
if [ ! -f "$recordings/story_1.sqlite" ]; then
  write_result skipped "the recordings are absent ($recordings)"
  echo "readme walkthrough: skipped, the recordings are absent"
  exit 0
fi

work="$(mktemp -d /tmp/asr_walkthrough.XXXXXX)"
trap 'rm -rf "$work"' EXIT
awk '/^## With ROS/ {section = 1} section && /^```sh$/ {block = 1; next}
     block && /^```$/ {exit} block {print}' "$ROOT/README.md" >"$work/walkthrough.sh"
if [ ! -s "$work/walkthrough.sh" ]; then
  write_result failed "no sh block after '## With ROS' in README.md"
  exit 1
fi

port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
mkdir -p "$work/bin"
cat >"$work/bin/roscore" <<ROSCORE
#!/bin/sh
exec /usr/bin/roscore -p $port "\$@"
ROSCORE
chmod +x "$work/bin/roscore"

echo "readme walkthrough: running the README's ROS walkthrough (master on port $port)"
start=$(date +%s)
# In a session of its own (setsid: its id is the walkthrough's pid), so that whatever it leaves
# running after a failure is ended by that id, and nothing else on the machine is touched.
(
  cd "$ROOT" &&
    exec env PATH="$work/bin:/usr/bin:$PATH" ROS_MASTER_URI="http://localhost:$port" \
      ROS_LOG_DIR="$work/log" setsid bash -e "$work/walkthrough.sh"
) >"$work/output.txt" 2>&1 &
await_session $! "$start" "$TIMEOUT_S" "$work/output.txt" "readme walkthrough"
status=$session_status
seconds=$session_seconds
cp "$work/output.txt" "$ROOT/out/walkthrough/output.txt" 2>/dev/null || true

problems=""
[ "$status" -ne 0 ] && problems="exit code $status after $seconds s; "
grep -q "REQUIRED process" "$work/output.txt" && problems+="a 'REQUIRED process has died'; "
grep -qE "scene: \"breakfast\"" "$work/output.txt" || problems+="no breakfast instance; "
if [ -n "$problems" ]; then
  tail -n 40 "$work/output.txt"
  write_result failed "${problems}output in out/walkthrough/output.txt"
  echo "readme walkthrough: FAILED: $problems"
  exit 1
fi
write_result passed ""
echo "readme walkthrough: passed in $seconds s (output in out/walkthrough/output.txt)"
