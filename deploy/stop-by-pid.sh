# Sourced by the cluster scripts of deploy/: stop_pid NAME PIDFILE [SECONDS] sends SIGTERM to the
# process of PIDFILE, waits up to SECONDS (default 30) for it to end, then sends SIGKILL; removes PIDFILE.
stop_pid() {
  local pid
  [ -f "$2" ] || return 0
  pid=$(cat "$2")
  if kill "$pid" 2>/dev/null; then
    for _ in $(seq $((${3:-30} * 10))); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    echo "stopped $1 (pid $pid)"
  fi
  rm -f "$2"
}
