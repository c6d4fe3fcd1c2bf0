# Sourced by the script tests that `./asr test` runs (the README walkthrough, the demo): each
# starts its run with setsid, in a session of its own, so that whatever the run leaves behind
# (a master, nodes, even in process groups of their own) can be found by the session's id
# without touching anything else here.
# await_session PID START TIMEOUT_S LOG LABEL: waits for the run PID (started at START, in
# seconds since the epoch) for up to TIMEOUT_S seconds, stopping its session when it takes
# longer; then stops what the run left running in its session. Notes both in LOG. Sets
# session_status (the run's exit code), session_seconds (its duration) and session_leftovers
# (what still runs after the run ended, one "pid command" per line; empty if nothing does).
await_session() {
  local pid="$1" start="$2" timeout_s="$3" log="$4" label="$5"
  while kill -0 "$pid" 2>/dev/null && [ $(($(date +%s) - start)) -lt "$timeout_s" ]; do
    sleep 1
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "$label: still running after $timeout_s s, stopped" >>"$log"
    stop_session "$pid"
  fi
  # Reaped first: until then the finished run is a zombie still in its session, and its
  # session would never look empty.
  wait "$pid"
  session_status=$?
  session_seconds=$(($(date +%s) - start))
  session_leftovers="$(running_in_session "$pid")"
  if [ -n "$session_leftovers" ]; then
    printf '%s: left running after the run ended, stopped:\n%s\n' "$label" "$session_leftovers" >>"$log"
    stop_session "$pid"
  fi
}

# SIGINT to every process of session $1, then SIGKILL to what is left running after 10 s
# (a zombie, such as the run itself before it is reaped, is not running).
stop_session() {
  pkill -INT -s "$1" || return 0
  for _ in $(seq 10); do
    [ -n "$(running_in_session "$1")" ] || return 0
    sleep 1
  done
  pkill -KILL -s "$1" || true
}

# The processes of session $1 that still run ("pid command" per line): a zombie (the run itself
# before it is reaped, a child its parent is about to reap) has ended already.
running_in_session() {
  ps -o pid=,stat=,args= -s "$1" | awk '$2 !~ /^Z/ { $2 = ""; print }'
}
