# Sourced by the make_corpus.sh scripts. A corpus is a folder whose manifest.txt
# starts with "# corpus vN". The manifest is written to manifest.txt.tmp and moved into
# place last, so a run cut short leaves no stamp and the next run starts over.

corpus_is_current() { # dir version label: true (and says so) when dir holds corpus vN
  local stamp="$1/manifest.txt"
  [ -f "$stamp" ] && head -n1 "$stamp" | grep -qx "# corpus v$2" || return 1
  echo "$3 corpus v$2 cached in $1"
}

corpus_start() { # dir version description: empties dir and opens its manifest
  rm -rf "$1"
  mkdir -p "$1"
  printf '# corpus v%s\n# %s\n' "$2" "$3" >"$1/manifest.txt.tmp"
}

corpus_add() { # dir line: one manifest line per file made
  echo "$2" >>"$1/manifest.txt.tmp"
}

corpus_finish() { # dir version label
  mv "$1/manifest.txt.tmp" "$1/manifest.txt"
  echo "$3 corpus v$2 written to $1"
}

run_logged() { # log what command...: runs the command into log; on failure prints
  # the log's tail under "what failed:" and ends the script
  local log="$1" what="$2"
  shift 2
  "$@" >"$log" 2>&1 || {
    echo "$what failed:"
    tail -n 5 "$log"
    exit 1
  } >&2
}
