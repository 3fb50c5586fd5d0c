#!/usr/bin/python3
"""Writes docs/scene-graph.md's table "Coverage against fogleman/sdf" from
the rows in tools/coverage_rows.py, between <!-- coverage:begin --> and
<!-- coverage:end -->, and renders each row's picture into
docs/images/coverage/ (96x96 PNGs) with the marchstudio binary.

A row's node is in fogleman's Z-up coordinates; its picture stands it on
the floor of a graph file rendered on its own (Y up) by turning the root
-90 degrees round x, folded into the root's own transform as a `matrix`.

Usage:
  /usr/bin/python3 tools/coverage.py [--bin build/marchstudio]   write the table, render the pictures
  /usr/bin/python3 tools/coverage.py --table-only                 write the table only
  /usr/bin/python3 tools/coverage.py --check                      fail if the page's table is not
      what the rows give (no rendering; ctest: graph_coverage_table)
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in tools/
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coverage_rows import ROWS  # noqa: E402
from doc_markers import put  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
DOC = os.path.join(ROOT, 'docs', 'scene-graph.md')
PICTURES = os.path.join(ROOT, 'docs', 'images', 'coverage')
MARKER = 'coverage'
SIZE = '96x96'
SPP = '4'


def slug(name):
    return re.sub(r'[^a-z0-9]+', '_', name.lower()).strip('_')


def snippet(node):
    return json.dumps(node, separators=(', ', ': '))


def function_cell(name, signature):
    if signature.split('(')[0] == name:
        return '`%s`' % signature
    return '%s: `%s`' % (name, signature)


def cell(text):
    return text.replace('|', '\\|')  # a table cell's pipe, even in code (GitHub's tables)


def table_lines():
    lines = ['| fogleman/sdf | marchstudio node | how it maps | picture |', '|---|---|---|---|']
    group = None
    for g, name, signature, node, notes in ROWS:
        if g != group:
            lines.append('| **%s** | | | |' % g)
            group = g
        if node is None:
            lines.append('| %s | — | **Left out.** %s | — |' % (function_cell(name, signature), cell(notes)))
        else:
            picture = '![%s](images/coverage/%s.png)' % (name, slug(name))
            lines.append('| %s | `%s` | %s | %s |' % (function_cell(name, signature), snippet(node), cell(notes), picture))
    return lines


def current_table():
    text = open(DOC, encoding='utf-8').read()
    b, e = '<!-- %s:begin -->' % MARKER, '<!-- %s:end -->' % MARKER
    if b not in text or e not in text:
        sys.exit('%s: no %s ... %s markers' % (os.path.relpath(DOC, ROOT), b, e))
    return text[text.index(b) + len(b):text.index(e)].strip('\n').split('\n')


# --- the picture: fogleman's Z-up node stood up in our Y-up scene ---

def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def axis_angle(axis, degrees):
    n = math.sqrt(sum(x * x for x in axis))
    x, y, z = (v / n for v in axis)
    a = math.radians(degrees)
    c, s, m = math.cos(a), math.sin(a), 1 - math.cos(a)
    return [[c + x * x * m, x * y * m - z * s, x * z * m + y * s],
            [x * y * m + z * s, c + y * y * m, y * z * m - x * s],
            [x * z * m - y * s, y * z * m + x * s, c + z * z * m]]


def stood_up(node):
    """The node with Rx(-90) (z onto y) put before its own scale, rotate and
    translate, as one local-to-parent `matrix`."""
    out = {k: v for k, v in node.items() if k not in ('translate', 'rotate', 'scale', 'matrix')}
    s = node.get('scale', 1)
    r = axis_angle(node['rotate'][:3], node['rotate'][3]) if 'rotate' in node else axis_angle([1, 0, 0], 0)
    t = node.get('translate', [0, 0, 0])
    up = axis_angle([1, 0, 0], -90)
    m = mat_mul(up, [[v * s for v in row] for row in r])
    tt = [sum(up[i][k] * t[k] for k in range(3)) for i in range(3)]
    out['matrix'] = [round(v, 9) for i in range(3) for v in m[i] + [tt[i]]]
    out['material'] = 'shape'
    return out


def render(binary):
    rows = [(name, node) for _, name, _, node, _ in ROWS if node is not None]
    os.makedirs(PICTURES, exist_ok=True)
    work = tempfile.mkdtemp(prefix='.render-', dir=PICTURES)  # beside the pictures: a rename, not a copy
    try:
        inputs = []
        for name, node in rows:
            path = os.path.join(work, slug(name) + '.json')
            with open(path, 'w') as f:
                json.dump({'root': stood_up(node)}, f)
            inputs.append(path)
        print('coverage: rendering %d pictures (%s, %s spp) with %s' % (len(inputs), SIZE, SPP, binary), flush=True)
        t0 = time.monotonic()
        p = subprocess.Popen([binary, 'render', *inputs, '--output-dir', work, '--size', SIZE, '--spp', SPP],
                             stdout=subprocess.PIPE, text=True)
        done = 0
        for line in p.stdout:
            done += 1
            print('  [%d/%d] %s (%.0f s)' % (done, len(inputs), os.path.basename(line.strip()),
                                             time.monotonic() - t0), flush=True)
        if p.wait() != 0:
            sys.exit('coverage: marchstudio render failed (exit %d); no picture replaced' % p.returncode)
        for name, _ in rows:
            os.replace(os.path.join(work, slug(name) + '.png'), os.path.join(PICTURES, slug(name) + '.png'))
        for f in os.listdir(PICTURES):  # a row gone or renamed leaves no picture behind
            if f.endswith('.png') and f[:-4] not in {slug(n) for n, _ in rows}:
                os.remove(os.path.join(PICTURES, f))
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'marchstudio'))
    ap.add_argument('--check', action='store_true', help='compare the page with the rows; write nothing')
    ap.add_argument('--table-only', action='store_true', help='write the table, render nothing')
    a = ap.parse_args()
    lines = table_lines()
    if a.check:
        if current_table() != lines:
            sys.exit('%s: the coverage table is not what tools/coverage_rows.py gives '
                     '(run tools/coverage.py --table-only)' % os.path.relpath(DOC, ROOT))
        print('coverage: the table matches its %d rows' % len(ROWS))
        return
    put(DOC, MARKER, lines)
    print('coverage: wrote %d rows into %s' % (len(ROWS), os.path.relpath(DOC, ROOT)))
    if not a.table_only:
        render(a.bin)


if __name__ == '__main__':
    main()
