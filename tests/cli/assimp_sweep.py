#!/usr/bin/env python3
"""Every model file of Debian's assimp-testmodels through gsdot3 (issue 54).

usage: assimp_sweep.py GSDOT3 WORKDIR [--shard I/N] [--models DIR]

For each file (sorted; shard I of N takes every N-th from the I-th, 0-based): `gsdot3 mesh-info FILE`
describes it (a file with no triangle to draw too), or refuses it with one line `gsdot3: error: ...`
only when assimp cannot read it; then `gsdot3 render --mesh FILE` (64x48, two-pass) renders it or
refuses it with one line ("no triangles" for the files with nothing to draw). No reason may be a
missing UV set. Images, shaders, text and buffers beside the models are not tried. Prints one line per
file and a summary table; exit 0 when nothing failed, 1 otherwise, 77 (skipped) without the models.
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import time

AUXILIARY = {'png', 'jpg', 'jpeg', 'tga', 'bmp', 'dds', 'pcx', 'txt', 'md', 'mtl', 'glsl', 'vert', 'frag',
             'bin', 'material', 'skin'}
NOT_READ = ('cannot read the mesh', 'the reader crashed', 'the reader stopped', 'the reader ran out of memory',
            'the reader used more than', 'the reader did not finish')
NO_UVS = re.compile(r'texture coordinates|no UVs|uv-projection', re.IGNORECASE)


def error_lines(stderr):
    return [l for l in stderr.splitlines() if l.startswith('gsdot3: error: ')]


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stderr


def sweep_one(gsdot3, work, index, path):
    """(category, reason, failure or None) for one file."""
    code, err = run([gsdot3, 'mesh-info', path])
    errors = error_lines(err)
    if code != 0:
        why = errors[-1][len('gsdot3: error: '):] if errors else err.strip()[-200:]
        if code == 2 and len(errors) == 1 and any(s in why for s in NOT_READ):
            return 'not read by assimp', why, None
        return 'failed', why, f'mesh-info refused a file assimp reads (exit {code}): {why}'
    out = os.path.join(work, f'r{index}')
    code, err = run([gsdot3, 'render', '--mesh', path, '--size', '64x48', '--method', 'two-pass', '--out', out])
    shutil.rmtree(out, ignore_errors=True)
    errors = error_lines(err)
    if code == 0:
        return 'rendered', '', None
    why = errors[-1][len('gsdot3: error: '):] if errors else err.strip()[-200:]
    if code != 2 or len(errors) != 1:
        return 'failed', why, f'render exit {code} with {len(errors)} error line(s): {why}'
    if NO_UVS.search(why):
        return 'failed', why, f'refused for missing UVs: {why}'
    if 'no triangles' in why:  # mesh-info described it: nothing to draw (points, lines, NaN positions)
        return 'no triangles', why, None
    return 'refused', why, None


def main():
    args = sys.argv[1:]
    shard, count, models = 0, 1, '/usr/share/assimp/models'
    if '--shard' in args:
        i = args.index('--shard')
        shard, count = (int(x) for x in args[i + 1].split('/'))
        del args[i:i + 2]
    if '--models' in args:
        i = args.index('--models')
        models = args[i + 1]
        del args[i:i + 2]
    gsdot3, work = args
    if not os.path.isdir(models):
        print(f'{models}: not there (Debian package assimp-testmodels); skipped')
        return 77
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(models) for f in fs)
    files = [f for f in files if f.rsplit('.', 1)[-1].lower() not in AUXILIARY][shard::count]
    os.makedirs(work, exist_ok=True)
    t0 = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        results = list(pool.map(lambda a: sweep_one(gsdot3, work, *a), enumerate(files)))
    failures = []
    counts = {}
    for path, (category, why, failure) in zip(files, results):
        rel = os.path.relpath(path, models)
        counts[category] = counts.get(category, 0) + 1
        print(f'{category:18} {rel}' + (f': {why}' if why else ''))
        if failure:
            failures.append(f'{rel}: {failure}')
    print(f'\nshard {shard}/{count}: {len(files)} files in {time.monotonic() - t0:.0f} s')
    for category in ('rendered', 'refused', 'no triangles', 'not read by assimp', 'failed'):
        print(f'  {category:18} {counts.get(category, 0)}')
    for f in failures:
        print(f'FAIL {f}')
    print(f'{len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
