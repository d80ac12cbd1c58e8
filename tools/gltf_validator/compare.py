#!/usr/bin/env python3
"""Sherpa's validator against the Khronos glTF-Validator (npm gltf-validator) on the
same files: precision and recall on the set of (code, JSON pointer) pairs, per
severity, plus the load contract (every file the oracle calls valid loads; every file
it calls invalid loads with the oracle's error codes, or is refused with a reason that
names the unusable part). SHERPA_ codes are Sherpa's own and are not compared.

Usage: compare.py --cli SHERPA_CLI --node-path CACHE/node_modules [--markdown OUT.md]
                  [--check] [--show-misses] PATH...   (files or directories)"""
import argparse, collections, concurrent.futures, json, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
SEVERITIES = ["error", "warning", "info", "hint"]


def files_of(paths):
    out = []
    for p in paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                out += [os.path.join(root, n) for n in names if n.endswith((".gltf", ".glb"))]
        elif p.endswith((".gltf", ".glb")):
            out.append(p)
    return sorted(out)


def oracle(path, node_path):
    env = dict(os.environ, NODE_PATH=node_path)
    r = subprocess.run(["node", os.path.join(HERE, "khronos_validate.js"), path], env=env,
                       capture_output=True, text=True, timeout=300)
    lines = [l for l in r.stdout.splitlines() if l.startswith("{")]
    if not lines:
        return None  # the oracle itself crashed (e.g. stack overflow on deep nesting)
    return json.loads(lines[0])


def oracle_batch(paths, node_path):
    """The oracle over many files in one Node process (its start-up, about a second,
    once): {path: report}. Where the process dies (the oracle's own stack overflow on
    deep nesting), the first file without a report is run alone by oracle() and the
    files after it go on in a new process."""
    env = dict(os.environ, NODE_PATH=node_path)
    out = {}
    while paths:
        r = subprocess.run(["node", os.path.join(HERE, "khronos_validate.js")] + paths, env=env,
                           capture_output=True, text=True, timeout=300 + 30 * len(paths))
        for line in r.stdout.splitlines():
            if line.startswith("{"):
                j = json.loads(line)
                out[j["file"]] = j
        missing = [i for i, p in enumerate(paths) if p not in out]
        if not missing:
            break
        out[paths[missing[0]]] = oracle(paths[missing[0]], node_path)
        paths = paths[missing[0] + 1:]
    return out


def sherpa(path, cli):
    r = subprocess.run([cli, "validate", path, "--json"], capture_output=True, text=True, timeout=300)
    try:
        j = json.loads(r.stdout)
    except json.JSONDecodeError:
        return {"crashed": True, "status": r.returncode, "stderr": r.stderr[-400:]}
    j["status"] = r.returncode
    return j


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--node-path", required=True)
    ap.add_argument("--markdown")
    ap.add_argument("--check", action="store_true", help="exit 1 when a goal is missed")
    ap.add_argument("--show-misses", action="store_true")
    ap.add_argument("--error-precision", type=float, default=1.0, help="--check floor (goal 1.0)")
    ap.add_argument("--error-recall", type=float, default=0.95, help="--check floor (goal 0.95)")
    ap.add_argument("--warning-recall", type=float, default=0.90, help="--check floor (goal 0.90)")
    ap.add_argument("--max-contract-violations", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--oracle-cache", help="JSON file keeping the oracle's reports between runs")
    ap.add_argument("paths", nargs="+")
    a = ap.parse_args()
    files = files_of(a.paths)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        cache = {}
        if a.oracle_cache and os.path.exists(a.oracle_cache):
            with open(a.oracle_cache) as c:
                cache = json.load(c)
        todo = [f for f in files if f not in cache]
        # One Node process per worker (round-robin, so large files spread out).
        chunks = [todo[i::a.jobs] for i in range(a.jobs) if todo[i::a.jobs]]
        for reports in pool.map(lambda c: oracle_batch(c, a.node_path), chunks):
            cache.update(reports)
        if a.oracle_cache:
            with open(a.oracle_cache, "w") as c:
                json.dump(cache, c)
        oracles = [cache[f] for f in files]
        ours = list(pool.map(lambda f: sherpa(f, a.cli), files))
    tp, fn, fp = collections.Counter(), collections.Counter(), collections.Counter()
    misses, extras, contract = [], [], []
    valid = invalid = skipped = 0
    for f, o, s in zip(files, oracles, ours):
        if o is None:
            skipped += 1
            continue
        if s.get("crashed"):
            contract.append(f"{f}: sherpa-cli validate crashed (status {s['status']}): {s['stderr']}")
            continue
        want = {(m["code"], m["pointer"]): m["severity"] for m in o["messages"]}
        got = {(m["code"], m.get("pointer", "")): SEVERITIES[m["severity"]]
               for m in s["issues"]["messages"] if not m["code"].startswith("SHERPA_")}
        for pair, sev in want.items():
            if pair in got:
                tp[sev] += 1
            else:
                fn[sev] += 1
                misses.append((sev, pair, os.path.basename(f)))
        for pair, sev in got.items():
            if pair not in want:
                fp[sev] += 1
                extras.append((sev, pair, os.path.basename(f)))
        oracle_errors = {m["code"] for m in o["messages"] if m["severity"] == "error"}
        if not oracle_errors:
            valid += 1
            if not s["loaded"]:
                contract.append(f"{f}: valid for the oracle but not loaded: " +
                                "; ".join(m["message"] for m in s["issues"]["messages"] if m["code"] == "SHERPA_LOAD_REFUSED"))
        else:
            invalid += 1
            our_codes = {m["code"] for m in s["issues"]["messages"]}
            if s["loaded"]:
                missing = oracle_errors - our_codes
                if missing:
                    contract.append(f"{f}: loaded without the oracle's error codes {sorted(missing)}")
            else:
                reasons = [m for m in s["issues"]["messages"] if m["code"] == "SHERPA_LOAD_REFUSED"]
                if not reasons or not (reasons[0].get("pointer") or any(c in reasons[0]["message"] for c in "[.:/")):
                    contract.append(f"{f}: refused without naming the unusable part")
    rows = []
    for sev in SEVERITIES:
        t, n, p = tp[sev], fn[sev], fp[sev]
        recall = t / (t + n) if t + n else 1.0
        precision = t / (t + p) if t + p else 1.0
        rows.append((sev, t, n, p, precision, recall))
    lines = [f"{len(files)} files ({valid} valid and {invalid} invalid for the oracle, {skipped} the oracle could not read)", "",
             "| severity | matched | missed | extra | precision | recall |", "|---|---:|---:|---:|---:|---:|"]
    lines += [f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]:.1%} | {r[5]:.1%} |" for r in rows]
    lines += ["", f"load contract violations: {len(contract)}"] + [f"- {c}" for c in contract]
    text = "\n".join(lines)
    print(text)
    if a.show_misses:
        print("\nmissed (oracle reports, Sherpa does not):")
        for m in sorted(misses): print("  ", m)
        print("\nextra (Sherpa reports, oracle does not):")
        for m in sorted(extras): print("  ", m)
    if a.markdown:
        with open(a.markdown, "w") as out:
            out.write(text + "\n")
    if a.check:
        err, warn = rows[0], rows[1]
        ok = (err[4] >= a.error_precision and err[5] >= a.error_recall and warn[5] >= a.warning_recall
              and len(contract) <= a.max_contract_violations)
        if not ok:
            print(f"FAILED: floors are error precision {a.error_precision:.1%}, error recall "
                  f"{a.error_recall:.1%}, warning recall {a.warning_recall:.1%}, at most "
                  f"{a.max_contract_violations} load contract violations", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
