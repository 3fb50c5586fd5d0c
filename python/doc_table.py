#!/usr/bin/python3
"""Prints docs/python.md's table of fogleman/sdf's names, from
tools/coverage_rows.py: each function, the node marchstudio.sdf builds for
it, or that it is refused. tests/python/test_docs.py holds the page to it.

Usage: /usr/bin/python3 python/doc_table.py
"""
import importlib.util
import os

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))


def rows():
    spec = importlib.util.spec_from_file_location('coverage_rows', os.path.join(ROOT, 'tools', 'coverage_rows.py'))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.ROWS


def node_name(node, name):
    """The node a row's example shows for the function itself, not its
    companions (plane() is shown cut from a sphere, a profile extruded)."""
    want = {'plane': 'sdPlane', 'slab': 'sdSlab', 'cylinder': 'sdInfiniteCylinder', 'shell': 'shell'}
    stack = [node]
    while stack:
        n = stack.pop(0)
        kind = n.get('sdf') or n.get('op')
        if name in want and kind != want[name]:
            stack.extend(n.get('children', []))
            continue
        if kind == 'extrude' and n['children'][0].get('sdf', '').startswith('sd2') and name != 'extrude':
            return n['children'][0]['sdf']
        if kind == 'extrude' and name == 'rounded_x':
            return 'round of two ud2Segment'
        return kind
    return '?'


# Rows that are a node's keys, not a node, and refused rows with a way out.
KEYS = {'translate': '`translate` key', 'scale': '`scale` key (uniform)', 'scale (tuple)': '`scale` modifier',
        'rotate': '`rotate` key, radians to degrees', 'orient': '`rotate` key'}
NOTES = {'tetrahedron': 'four `sdPlane` cut by an `sdBox`', 'polygon': 'three points: `sd2Triangle`; 4 to 32: `sd2Polygon`',
         'slab': '`k` refused', 'rounded_rectangle': 'a radius per corner refused',
         'repeat': '`padding` not needed', 'twist': '`k` negated, `axis` z',
         'scale (tuple)': 'a tuple `factor`', 'scale': 'a number `factor`'}


def table():
    lines = ['| fogleman/sdf | marchstudio.sdf builds | notes |', '|---|---|---|']
    for _group, name, sig, node, _notes in rows():
        note = NOTES.get(name, '')
        if node is None:
            lines.append(f'| `{sig}` | NotImplementedError | {note} |'.replace(' |  |', ' | |'))
            continue
        what = KEYS.get(name) or f'`{node_name(node, name)}`'
        if name in ('dodecahedron', 'icosahedron'):
            what += ' turned 90 degrees round z'
        elif name not in KEYS and 'rotate' in node:
            what += ' turned onto z'
        lines.append(f'| `{sig}` | {what} | {note} |')
    return '\n'.join(lines) + '\n'


if __name__ == '__main__':
    print(table(), end='')
