#!/usr/bin/env python3
"""Whole-process times of short marchstudio runs, and a 640x360 seed still
against the sum of its own phases (render -v), written into
docs/performance.md between the start-up markers (docs/performance.md#start-up).

    /usr/bin/python3 tools/start-up-figures.py [--bin build/marchstudio]
        [--old OTHER_BINARY] [--runs 15] [--print]

--old times a second binary the same way, run for run in turn with this one
(A B A B ...), so both see the same load: e.g. a build of an earlier commit.
--print prints the table instead of writing the page.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from doc_markers import put  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PHASES = re.compile(r'context ([\d.]+) ms, compile ([\d.]+) ms, render ([\d.]+) ms, write ([\d.]+) ms')


def cases(out):
    seed = os.path.join(ROOT, 'scenes', 'seed.toml')
    still = ['render', seed, '--size', '640x360', '-v', '-o']
    return [('`--version`', ['--version']),
            ('`--help`', ['--help']),
            ('seed 640x360 still, PNG', still + [os.path.join(out, 's.png')]),
            ('seed 640x360 still, EXR', still + [os.path.join(out, 's.exr')]),
            ('seed 640x360 still, TIFF (OpenImageIO)', still + [os.path.join(out, 's.tif')])]


def run_once(binary, args):
    t0 = time.perf_counter()
    p = subprocess.run([binary] + args, capture_output=True, text=True)
    wall = (time.perf_counter() - t0) * 1e3
    if p.returncode != 0:
        sys.exit('start-up-figures: %s %s failed: %s' % (binary, ' '.join(args), p.stderr.strip()))
    m = PHASES.search(p.stderr)
    return wall, (sum(float(x) for x in m.groups()) if m else None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'marchstudio'))
    ap.add_argument('--old', help='a second binary to time in turn with --bin')
    ap.add_argument('--runs', type=int, default=15)
    ap.add_argument('--print', action='store_true')
    a = ap.parse_args()
    binaries = [a.bin] + ([a.old] if a.old else [])
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for label, args in cases(out):
            walls = {b: [] for b in binaries}
            phases = []
            for b in binaries:
                run_once(b, args)  # warm-up: Mesa's shader cache, the page cache
            for _ in range(a.runs):
                for b in binaries:
                    wall, ph = run_once(b, args)
                    walls[b].append(wall)
                    if b == a.bin and ph is not None:
                        phases.append(ph)
            new = statistics.median(walls[a.bin])
            cells = ['%.0f ms' % new]
            if a.old:
                cells.append('%.0f ms' % statistics.median(walls[a.old]))
            if phases:
                ph = statistics.median(phases)
                cells += ['%.0f ms' % ph, '%.2f' % (new / ph)]
            else:
                cells += ['', '']
            rows.append('| %s | %s |' % (label, ' | '.join(cells)))
    renderer = subprocess.run([a.bin, 'render', os.path.join(ROOT, 'scenes', 'seed.toml'), '--size', '8x8', '-v',
                               '-o', os.devnull + '.png'], capture_output=True, text=True).stderr
    m = re.search(r'GL_RENDERER (.*?), GL_VERSION', renderer)
    head = ['| run | whole process' + (' | earlier binary' if a.old else '') + ' | sum of -v phases | ratio |',
            '|---|---' + ('|---' if a.old else '') + '|---|---|']
    lines = ['Medians of %d runs each%s, %s, GL_RENDERER `%s`:' % (
        a.runs, ', in turn with the earlier binary' if a.old else '', time.strftime('%Y-%m-%d'),
        m.group(1) if m else 'unknown'), ''] + head + rows
    if a.print:
        print('\n'.join(lines))
    else:
        put(os.path.join(ROOT, 'docs', 'performance.md'), 'start-up', lines)


if __name__ == '__main__':
    main()
