#!/usr/bin/env python3
"""KHR_animation_pointer values against three.js: `sherpa-cli info FILE --time T --json`'s
animated_properties against what three.js' AnimationMixer gives for the same channels
through Needle's GLTFLoader plugin (tools/motion/three_pointer_oracle.mjs, one Node run
for all times), at times before the first key, on keys, between keys and past the last,
on STEP, LINEAR and CUBICSPLINE channels. Each value must agree within 1e-5 relative
(float32 keys and Sherpa's float32 sampling against three's doubles). A pointer the
plugin does not support is listed with the plugin's reason and must be named in the
docs (docs/animation/pointer.md); every pointer Sherpa animates must be either compared
or listed, and every pointer three.js animates must be animated by Sherpa.
Usage: three_pointer_oracle_test.py SHERPA_CLI NODE ORACLE_SCRIPT CACHE FILE DOCS"""
import json
import re
import subprocess
import sys

cli, node, script, cache, path, docs = sys.argv[1:7]
TIMES = [-0.5, 0.0, 0.25, 0.5, 0.8, 1.0, 1.3, 1.5, 1.75, 2.0, 2.6]
TOLERANCE = 1e-5
doc = json.load(open(path))
anim = doc['animations'][0]
failures = []

r = subprocess.run([node, script, cache, path, '0', *map(repr, TIMES)], capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f'three.js oracle failed ({r.returncode}): {r.stderr[-2000:]}')
three = json.loads(r.stdout)
failures += [f'oracle: {e}' for e in three['errors']]
compared, unsupported = three['compared'], three['unsupported']


def interpolation(pointer):
    for ch in anim['channels']:
        if ch['target'].get('extensions', {}).get('KHR_animation_pointer', {}).get('pointer') == pointer:
            return anim['samplers'][ch['sampler']].get('interpolation', 'LINEAR')


def template(pointer):
    """The pointer with its object index as the docs write it (N)."""
    return re.sub(r'^(/materials|/cameras|/nodes|/extensions/KHR_lights_punctual/lights)/\d+/',
                  r'\1/N/', pointer)


worst, worst_at, worst_rel, worst_rel_at = 0.0, None, 0.0, None
for frame, t in zip(three['frames'], TIMES):
    r = subprocess.run([cli, 'info', path, '--json', '--time', repr(t)], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'info --time {t} failed ({r.returncode}): {r.stderr}')
    ours = {p['pointer']: p['value'] for p in json.loads(r.stdout)['animated_properties']}
    for pointer in sorted(set(ours) - set(compared) - set(unsupported)):
        failures.append(f't={t} {pointer}: animated by Sherpa, neither compared nor listed unsupported')
    for pointer, want in frame['values'].items():
        got = ours.get(pointer)
        if got is None or len(got) != len(want):
            failures.append(f't={t} {pointer}: Sherpa {got}, three.js {want}')
            continue
        for g, w in zip(got, want):
            d, scale = abs(g - w), max(1.0, abs(w))
            if d > worst:
                worst, worst_at = d, f'{pointer} at t={t}'
            if d / scale > worst_rel:
                worst_rel, worst_rel_at = d / scale, f'{pointer} at t={t}'
            if d > TOLERANCE * scale:
                failures.append(f't={t} {pointer}: Sherpa {got}, three.js {want}')
                break

by_kind = {}
for pointer in compared:
    by_kind.setdefault(interpolation(pointer), []).append(pointer)
print(f'compared with three.js: {len(compared)} pointers at {len(TIMES)} times ' +
      ', '.join(f'{k} {len(v)}' for k, v in sorted(by_kind.items())) +
      f'; largest |difference| {worst:.3g} ({worst_at}), relative to max(1, |value|) '
      f'{worst_rel:.3g} ({worst_rel_at}); tolerance {TOLERANCE:g} relative')
for kind in ('STEP', 'LINEAR', 'CUBICSPLINE'):
    if not by_kind.get(kind):
        failures.append(f'no {kind} channel was compared')
text = open(docs).read()
print(f'not supported by the three.js plugin ({len(unsupported)}):')
for pointer, why in unsupported.items():
    print(f'  {pointer}: {why}')
    if template(pointer) not in text:
        failures.append(f'{pointer} is not supported by the oracle but not named in {docs}')
for f in failures:
    print('FAIL', f)
sys.exit(1 if failures else 0)
