#!/usr/bin/env bash
# Usage: xvfb_exec.sh "XVFB-ARGS" COMMAND [ARGS...]
# Runs COMMAND on a private Xvfb server and exits with its status. The server picks
# its own free display number and reports it (-displayfd), so any number of suites can
# run at once: `xvfb-run -a` guesses a number from the lock files and two of them
# started together can pick the same one, which had CTest run every windowed suite
# one after another.
set -uo pipefail
xvfb_args=$1
shift
dir=$(mktemp -d "${TMPDIR:-/tmp}/sherpa-xvfb.XXXXXX") || exit 1
# shellcheck disable=SC2086 # the server's arguments are one string, split on purpose
Xvfb -displayfd 3 -nolisten tcp $xvfb_args 3>"$dir/display" 2>"$dir/log" &
server=$!
stop() {
  kill "$server" 2>/dev/null
  wait "$server" 2>/dev/null
  rm -rf "$dir"
}
trap 'stop; exit 130' INT TERM
# The number arrives once the server listens; give up if the server exits first.
for _ in $(seq 1 300); do
  [ -s "$dir/display" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
display=$(head -n 1 "$dir/display" 2>/dev/null)
if [ -z "$display" ]; then
  echo "xvfb_exec.sh: Xvfb did not start (args: $xvfb_args):" >&2
  cat "$dir/log" >&2
  stop
  exit 1
fi
DISPLAY=":$display" XAUTHORITY=/dev/null "$@"
status=$?
stop
exit "$status"
