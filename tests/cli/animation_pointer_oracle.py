#!/usr/bin/env python3
"""KHR_animation_pointer values against the glTF specification's interpolation
(Appendix C), computed here independently of Sherpa: for tests/data/animation_pointer/
pointer.gltf (tools/animation_pointer/make_pointer.py) at chosen times, every animated
property `sherpa-cli info --time T --json` reports must equal the spec's value; the
refused channels must be warnings naming their channel's JSON pointer; a render at two
times must show the animated base colour and the node visibility. The same for
extensions.gltf (the ratified material extensions' pointers; its animation's
extras.valid_channels says how many channels come before the refused ones), whose frames
at two times must equal those of the file with the spec's values baked in as static
properties (the GPU records themselves: animation_pointer_tests).
Usage: animation_pointer_oracle.py SHERPA_CLI FILE OUT_DIR"""
import base64
import json
import os
import struct
import subprocess
import sys

cli, path, out_dir = sys.argv[1:4]
doc = json.load(open(path))
blob = base64.b64decode(doc['buffers'][0]['uri'].split(',', 1)[1])
WIDTH = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4}


def floats(index):
    a = doc['accessors'][index]
    v = doc['bufferViews'][a['bufferView']]
    n = a['count'] * WIDTH[a['type']]
    return list(struct.unpack_from('<%df' % n, blob, v['byteOffset'] + a.get('byteOffset', 0)))


def sample(s, t, width, step=False):
    """glTF 2.0 Appendix C: STEP, LINEAR, CUBICSPLINE (Hermite, tangents times the key
    interval); clamped to the first and last key."""
    times, values = floats(s['input']), floats(s['output'])
    cubic = s.get('interpolation', 'LINEAR') == 'CUBICSPLINE'
    key = lambda k: values[(3 * k + 1) * width:(3 * k + 2) * width] if cubic else values[k * width:(k + 1) * width]
    if t <= times[0]:
        return key(0)
    if t >= times[-1]:
        return key(len(times) - 1)
    k = max(i for i in range(len(times)) if times[i] <= t)
    t0, t1 = times[k], times[k + 1]
    u, d = (t - t0) / (t1 - t0), t1 - t0
    a, b = key(k), key(k + 1)
    mode = 'STEP' if step else s.get('interpolation', 'LINEAR')
    if mode == 'STEP':
        return a
    if mode == 'LINEAR':
        return [x + (y - x) * u for x, y in zip(a, b)]
    out_t = values[(3 * k + 2) * width:(3 * k + 3) * width]
    in_t = values[(3 * (k + 1)) * width:(3 * (k + 1) + 1) * width]
    u2, u3 = u * u, u * u * u
    return [(2 * u3 - 3 * u2 + 1) * p0 + d * (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
            d * (u3 - u2) * m1 for p0, m0, p1, m1 in zip(a, out_t, b, in_t)]


anim = doc['animations'][0]
VALID = anim.get('extras', {}).get('valid_channels', 16)
expected_pointers = {}
failures = []
for c, ch in enumerate(anim['channels']):
    p = ch['target'].get('extensions', {}).get('KHR_animation_pointer', {}).get('pointer')
    if c < VALID and not p.endswith('/translation'):
        expected_pointers[p] = c


def info(*args):
    r = subprocess.run([cli, 'info', path, '--json', *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'info {args} failed ({r.returncode}): {r.stderr}')
    return json.loads(r.stdout)


worst = 0.0
for t in [-1.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.3, 1.5, 1.75, 1.99, 2.5]:
    j = info('--time', repr(t))
    got = {p['pointer']: p['value'] for p in j['animated_properties']}
    if set(got) != set(expected_pointers):
        failures.append(f't={t}: animated pointers {sorted(got)} != {sorted(expected_pointers)}')
        continue
    for pointer, c in expected_pointers.items():
        s = anim['samplers'][anim['channels'][c]['sampler']]
        width = WIDTH[doc['accessors'][s['output']]['type']]
        want = sample(s, t, width, step=pointer.endswith('/visible'))
        for g, w in zip(got[pointer], want):
            worst = max(worst, abs(g - w))
            if abs(g - w) > 1e-5 * max(1.0, abs(w)):
                failures.append(f't={t} {pointer}: sherpa {got[pointer]} spec {want}')
                break
print(f'animated properties: {len(expected_pointers)} pointers at 11 times, worst |diff| {worst:.3g}')

# The refused channels: skipped with a warning naming the channel's JSON pointer.
r = subprocess.run([cli, 'validate', path, '--json'], capture_output=True, text=True)
report = json.loads(r.stdout)
messages = (report['files'][0] if 'files' in report else report)['issues']['messages']
pointers = {m.get('pointer') for m in messages}
for c in range(VALID, len(anim['channels'])):
    if f'/animations/0/channels/{c}' not in pointers and \
       not any(str(p).startswith(f'/animations/0/channels/{c}/') for p in pointers):
        failures.append(f'channel {c} ({anim["channels"][c]["target"]}) was not warned about')
for c in range(VALID):
    if any(str(p) == f'/animations/0/channels/{c}' for p in pointers):
        failures.append(f'valid channel {c} was warned about')

def decode(png):
    """The PNG's rows of bytes and bytes per pixel (8-bit RGB or RGBA)."""
    import zlib
    data = open(png, 'rb').read()
    w, h, depth, ctype = struct.unpack('>IIBB', data[16:26])
    idat, at = b'', 8
    while at < len(data):
        n, kind = struct.unpack('>I4s', data[at:at + 8])
        if kind == b'IDAT':
            idat += data[at + 8:at + 8 + n]
        at += 12 + n
    raw = zlib.decompress(idat)
    bpp = {2: 3, 6: 4}[ctype]
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for r in range(h):
        f, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return rows, bpp


def pixel(png, x, y):
    rows, bpp = decode(png)
    return tuple(rows[y][x * bpp:x * bpp + 3])



def render_file(gltf, png, *args):
    r = subprocess.run([cli, 'render', gltf, '-o', png, '--width', '160', '--height', '120',
                        '--camera', 'eye=0,0,4:target=0,0,0:fov=45', '--validation', *args],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'render {gltf} {args} failed: {r.stderr}')
    return png


def set_pointer(target, pointer, value):
    """Writes `value` at JSON pointer `pointer` of `target` (scalars unwrapped)."""
    keys = [int(k) if k.isdigit() else k for k in pointer.strip('/').split('/')]
    for k in keys[:-1]:
        target = target[k]
    target[keys[-1]] = value[0] if len(value) == 1 else value


if 'valid_channels' in anim.get('extras', {}):
    # The animated frame against the same file with the spec's values at that time
    # written in as static properties (no animation): the importer's static path, not
    # the animation's, puts them on the GPU. Same lit image within one 8-bit step.
    import copy
    for t in (0.5, 1.5):
        baked = copy.deepcopy(doc)
        for pointer, c in expected_pointers.items():
            s_ = anim['samplers'][anim['channels'][c]['sampler']]
            set_pointer(baked, pointer, sample(s_, t, WIDTH[doc['accessors'][s_['output']]['type']]))
        del baked['animations']
        baked['extensionsUsed'].remove('KHR_animation_pointer')
        baked_path = os.path.join(out_dir, f'extensions_baked_t{t}.gltf')
        json.dump(baked, open(baked_path, 'w'))
        animated = render_file(path, os.path.join(out_dir, f'extensions_t{t}.png'), '--time', str(t))
        static = render_file(baked_path, os.path.join(out_dir, f'extensions_baked_t{t}.png'))
        (ra, bpp), (rb, _) = decode(animated), decode(static)
        worst = max(abs(x - y) for la, lb in zip(ra, rb) for x, y in zip(la, lb))
        differ = sum(1 for la, lb in zip(ra, rb) for i in range(0, len(la), bpp)
                     if la[i:i + 3] != lb[i:i + 3])
        print(f'render t={t}: animated vs baked: {differ} pixels differ, largest step {worst}')
        if worst > 1:
            failures.append(f'render t={t}: animated and baked frames differ by {worst} steps')
    # The animated frames must differ from each other: the values reach the image.
    a05, a15 = (decode(os.path.join(out_dir, f'extensions_t{t}.png'))[0] for t in (0.5, 1.5))
    moved = sum(1 for la, lb in zip(a05, a15) for x, y in zip(la, lb) if abs(x - y) > 8)
    print(f'frames at 0.5 s and 1.5 s: {moved} channel values differ by more than 8 steps')
    if moved < 100:
        failures.append('the frames at 0.5 s and 1.5 s barely differ')

if 'valid_channels' in anim.get('extras', {}):  # extensions.gltf: done
    for f in failures:
        print('FAIL', f)
    sys.exit(1 if failures else 0)


# The frame: the unlit sphere (x = -1.1) shows the animated base colour, the sphere at
# the origin blinks (hidden between 1 and 1.5 s).
def render(t):
    png = os.path.join(out_dir, f'pointer_t{t}.png')
    r = subprocess.run([cli, 'render', path, '-o', png, '--time', str(t), '--width', '160',
                        '--height', '120', '--camera', 'eye=0,0,5:target=0,0,0:fov=45',
                        '--environment', 'none', '--sun', 'off', '--background', '1,0,1',
                        '--tone-map', 'linear', '--validation'], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'render --time {t} failed: {r.stderr}')
    return png


def srgb(c):
    c = min(max(c, 0.0), 1.0)
    return round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055))


# The sphere centres at 160x120, fov 45 at distance 5: x = 80 + 1.1 / (5 tan 22.5) * 60.
dx = round(1.1 / (5 * 0.41421356) * 60)
for t, hidden in ((0.5, False), (1.25, True)):
    png = render(t)
    base = sample(anim['samplers'][0], t, 4)
    want = tuple(srgb(c) for c in base[:3])
    got = pixel(png, 80 - dx, 60)
    if max(abs(g - w) for g, w in zip(got, want)) > 3:
        failures.append(f'render t={t}: unlit sphere {got}, spec base colour {want}')
    centre = pixel(png, 80, 60)
    if (centre == (255, 0, 255)) != hidden:
        failures.append(f'render t={t}: the blinking sphere {"shows" if not hidden else "is hidden"}'
                        f' but centre pixel is {centre}')
    # The lit sphere moves up (/nodes/1/translation) and its alpha 0.5 meets the
    # animated alphaCutoff (0.2 -> 0.8 over 2 s): shown at 0.5 s, masked away at 1.25 s.
    lit_y = sample(anim['samplers'][15], t, 3)[1]
    cutoff = sample(anim['samplers'][4], t, 1)[0]
    lit = pixel(png, 80 + dx, round(60 - lit_y / (5 * 0.41421356) * 60))
    if (lit == (255, 0, 255)) != (0.5 < cutoff):
        failures.append(f'render t={t}: lit sphere pixel {lit} with alphaCutoff {cutoff:.3f}')
    print(f'render t={t}: unlit sphere {got} (spec {want}), centre {centre}, lit sphere {lit} '
          f'(alphaCutoff {cutoff:.3f})')

for f in failures:
    print('FAIL', f)
sys.exit(1 if failures else 0)
