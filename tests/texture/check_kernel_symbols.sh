#!/usr/bin/env bash
# The encoder kernels are compiled once per instruction set. A weak (inline or
# template) symbol defined outside the kernel's own namespace could be shared
# between those copies, and the linker might then run AVX-512 code on a CPU
# without it. Fails if any kernel object defines such a code symbol (shared
# constant data, "u"/"V" symbols such as the BC7 tables, is the same everywhere).
set -euo pipefail
status=0
for obj in "$@"; do
  leaked=$(nm -C --defined-only "$obj" | grep -E ' [Ww] ' | grep -vE 'sherpa::tex::(scalar|avx2|avx512)::' || true)
  if [ -n "$leaked" ]; then
    echo "$obj defines shared weak symbols:"; echo "$leaked"; status=1
  fi
done
[ $status -eq 0 ] && echo "kernel objects: no shared weak symbols ($# files)"
exit $status
