# Sourced by the cluster checks: daemons started in the background and
# stopped by their process ids, newest first, from a trap.
#   daemon_pids+=($!)      after starting each one
#   trap stop_daemons EXIT
#   port=$(free_port)      a free TCP port on 127.0.0.1
daemon_pids=()

stop_daemons() {  # the newest first: a worker without its scheduler lingers; children too
  local i pid children
  for ((i = ${#daemon_pids[@]} - 1; i >= 0; i--)); do
    pid=${daemon_pids[i]}
    children=$(pgrep -P "$pid" || true)
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" $children 2>/dev/null || true
  done
}

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
