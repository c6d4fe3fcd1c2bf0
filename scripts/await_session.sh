# Sourced by the script tests that `./asr test` runs (the README walkthrough, the demo): each
# starts its run with setsid, in a session of its own, so that whatever the run leaves behind
# (a master, nodes) can be ended by the session's id without touching anything else here.
# await_session PID START TIMEOUT_S LOG LABEL: waits for the run PID (started at START, in
# seconds since the epoch) for up to TIMEOUT_S seconds, noting in LOG when it had to stop it;
# then ends what is left of its session (SIGINT, then SIGKILL 10 s later) and sets
# session_status (the run's exit code) and session_seconds (its duration).
await_session() {
  local pid="$1" start="$2" timeout_s="$3" log="$4" label="$5"
  while kill -0 "$pid" 2>/dev/null && [ $(($(date +%s) - start)) -lt "$timeout_s" ]; do
    sleep 1
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "$label: still running after $timeout_s s, stopped" >>"$log"
  fi
  kill -INT -- -"$pid" 2>/dev/null && sleep 10
  kill -KILL -- -"$pid" 2>/dev/null
  wait "$pid"
  session_status=$?
  session_seconds=$(($(date +%s) - start))
}
