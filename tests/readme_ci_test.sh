#!/bin/sh
# The README's test command and .ci/run must be the same command.
set -eu
root=$(dirname "$0")/..
cmd=$(grep -v '^#' "$root/.ci/run" | grep -v '^set \|^cd \|^$' | tail -n 1)
grep -qxF "$cmd" "$root/README.md" || { echo "README lacks the CI command: $cmd"; exit 1; }
grep -qxF '.ci/setup && .ci/build && build/cli/sherpa-cli info builtin:default' "$root/README.md" ||
  grep -q 'sherpa-cli info builtin:default\|build/editor/sherpa' "$root/README.md"
echo "README and .ci/run agree"
