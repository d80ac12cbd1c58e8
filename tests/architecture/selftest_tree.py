"""What the architecture checks' self-tests share: the checker run on a made-up tree.

Each case writes its files into a temporary folder, runs the checker there with
--root, and passes when the exit code is the one wanted and the output holds every
fragment wanted.
"""
import subprocess
import sys
import tempfile
from pathlib import Path


def run_checker(checker, files, args):
    """(exit code, output) of `checker` on a tree of `files` ({relative path: text})."""
    with tempfile.TemporaryDirectory(prefix="sherpa_arch_") as tmp:
        root = Path(tmp)
        for rel, text in files.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        r = subprocess.run([sys.executable, str(checker), "--root", str(root), *args],
                           capture_output=True, text=True, check=False)
        return r.returncode, r.stdout + r.stderr


def run_cases(title, checker, cases):
    """Runs cases [(name, files, args, exit code wanted, fragments)]; 0 when all behave."""
    failures = 0
    for name, files, args, want_rc, fragments in cases:
        rc, out = run_checker(checker, files, args)
        missing = [f for f in fragments if f not in out]
        ok = rc == want_rc and not missing
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {rc} (want {want_rc})")
        if not ok:
            print("  missing: " + "; ".join(missing) + "\n  output:\n    "
                  + out.replace("\n", "\n    "))
    print(f"{title} self-test: {len(cases) - failures} of {len(cases)} cases behave")
    return 1 if failures else 0
