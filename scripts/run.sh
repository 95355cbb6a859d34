#!/usr/bin/env bash
# The main job: sets up (Debian packages), builds, and runs penshaped, printing every stroke and
# the shape it is recognized as. With a tablet attached it reads the tablet (Ctrl-C stops);
# with none — or with a recording given — it replays a recording as if live and stops at
# its end.
#   scripts/run.sh [RECORDING]     default: recordings/generated-shapes.hidrec, made by the
#                                  project (recordings/generate.sh, see recordings/SOURCES.md)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release --target penshaped penshape

bin=build/release
dir=$(mktemp -d)
socket="$dir/penshape.sock"
daemon_pid=
cleanup() {
  [ -n "$daemon_pid" ] && kill -TERM "$daemon_pid" 2>/dev/null && wait "$daemon_pid" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT INT TERM

start_daemon() {  # extra penshaped options
  "$bin/daemon/penshaped" --listen "unix:$socket" "$@" &
  daemon_pid=$!
  for _ in $(seq 100); do [ -S "$socket" ] && return 0; sleep 0.1; done
  echo "run: penshaped did not start" >&2
  exit 1
}

recording=${1:-}
if [ -z "$recording" ]; then
  start_daemon
  sleep 1  # the first scan of hidraw devices
  if "$bin/clients/penshape" devices --json --socket "$socket" | grep -q "{"; then
    echo "run: reading the attached tablet(s); draw, Ctrl-C to stop"
    "$bin/clients/penshape" watch --devices --deconstructions --socket "$socket"
    exit 0
  fi
  kill -TERM "$daemon_pid"; wait "$daemon_pid" 2>/dev/null || true; daemon_pid=
  recording=recordings/generated-shapes.hidrec
  echo "run: no tablet attached; replaying $recording as if live"
fi
[ -f "$recording" ] || { echo "run: no such recording: $recording" >&2; exit 2; }
# Watch until the recording has played (its last report time) plus time to recognize.
last=$(grep '^E:' "$recording" | tail -n 1 | awk '{print $2}')
start_daemon --replay "$recording" --replay-delay 1
"$bin/clients/penshape" watch --deconstructions --socket "$socket" --duration "$(awk -v t="$last" 'BEGIN{print int(t) + 4}')"
