#!/usr/bin/env python3
"""Fills tools/speed/template.md with the tables of the sweeps in
docs/images/speed/ and writes docs/speed-vs-error.md. Placeholders:
{{DATE}} (the newest sweep's file date), {{MACHINE}}, {{TARGETS}} (the
1280x720 targets table) and {{SCENE:<name>}} (a scene's 640x360 section).
Every number on the page comes from the JSON files; the prose is the
template's. Usage: python3 tools/speed/fill.py"""
import datetime
import json
import os
import re

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), '..', '..'))
SPEED = os.path.join(ROOT, 'docs', 'images', 'speed')
SCENES = ['seed', 'stilllife', 'columns']
DESC = {
    'seed': 'the founding sphere on a checker plane',
    'stilllife': 'CSG, a smooth-union blob, a torus and a capsule; two lights; 2 bounces',
    'columns': 'two rows of repeated columns and a mirror orb; a sun and a point light; 2 bounces',
}
# The rows each scene section lists (the CSV has them all).
ROWS = ['textbook', 'fast', 'balanced', 'reference', 'tol=eps1e-4', 'tol=fp0.1', 'tol=fp0.5', 'tol=fp1',
        'steps=32', 'steps=64', 'omega=1.2', 'omega=1.5', 'omega=1.8', 'no-bounds', 'planes-marched', 'marched',
        'maxdist=50', 'shadow=16', 'shadow=classic', 'ao=0', 'ao=3', 'bounces=0', 'bounces=2', 'neps=fixed1e-3',
        'neps=fp1', 'steps=255 tol=fp1 omega=1.5 marched', 'steps=255 tol=fp1 omega=1.5 analytic']


def load(path):
    with open(path) as f:
        return json.load(f)


def rows_of(d):
    return {r['name']: r for r in d['rows']}


def psnr(v):
    return 'inf' if v is None else '%.1f' % v


def exact_cells(r):
    x = r['error']['exact']
    return f"{psnr(x['psnr'])} | {x['depth_mean']:.1e} | {100 * x['misclassified']:.3f}%" if x else '- | - | -'


def targets():
    out = ['| scene | config | CPU ms / frame | GPU-timer ms | speed-up vs textbook (CPU) | primary steps / px | '
           'step-cap pixels | PSNR vs same-spp reference | PSNR vs 16 spp | PSNR vs exact intersection | '
           'exact: depth err mean | exact: hit/miss flips |',
           '|---|---|---|---|---|---|---|---|---|---|---|---|']
    for s in SCENES:
        r = rows_of(load(os.path.join(SPEED, '1280x720', f'{s}.sweep.json')))
        tb = r['textbook']['time_ms']['cpu']
        for n in ['textbook', 'balanced', 'fast', 'reference']:
            x = r[n]
            e = x['error']
            name = '**balanced**' if n == 'balanced' else n
            out.append(f"| {s} | {name} | {x['time_ms']['cpu']:.1f} | {x['time_ms']['gpu']:.1f} | "
                       f"{tb / x['time_ms']['cpu']:.2f}x | {x['cost']['mean_steps']:.2f} | "
                       f"{100 * x['cost']['step_cap_fraction']:.3f}% | {psnr(e['same_spp']['psnr'])} | "
                       f"{psnr(e['supersampled']['psnr'])} | {exact_cells(x)} |")
    return '\n'.join(out)


def scene_section(s):
    d = load(os.path.join(SPEED, f'{s}.sweep.json'))
    r = rows_of(d)
    tb = r['textbook']['time_ms']['cpu']
    exact = d['references']['exact']['status'] == 'available'
    head = ('| config | CPU ms | vs textbook | steps / px | step cap | PSNR | MAE /255 | depth err | flips | PSNR 16 spp |'
            + (' PSNR exact | exact depth err | exact flips |' if exact else ''))
    lines = [head, '|' + '---|' * (head.count('|') - 1)]
    for n in ROWS:
        if n not in r:
            continue
        x = r[n]
        e, ss = x['error']['same_spp'], x['error']['supersampled']
        front = ('A' if x['pareto']['same_spp'] else '') + ('B' if x['pareto']['supersampled'] else '')
        name = '**balanced**' if n == 'balanced' else (n if n in ('textbook', 'fast', 'reference') else f'`{n}`')
        if front:
            name += f' ({front})'
        line = (f"| {name} | {x['time_ms']['cpu']:.1f} | {tb / x['time_ms']['cpu']:.2f}x | {x['cost']['mean_steps']:.2f} | "
                f"{100 * x['cost']['step_cap_fraction']:.3f}% | {psnr(e['psnr'])} | {255 * e['mae']:.3f} | "
                f"{e['depth_mean']:.1e} | {100 * e['misclassified']:.3f}% | {psnr(ss['psnr'])} |")
        if exact:
            line += f' {exact_cells(x)} |'
        lines.append(line)
    return f"""### {s}: {DESC[s]}

```sh
{d['command']}
```

![{s}: frame time against PSNR, Pareto fronts, balanced highlighted](images/speed/{s}.sweep.png)

{len(d['rows'])} rows, all in [{s}.sweep.csv](images/speed/{s}.sweep.csv) and [{s}.sweep.json](images/speed/{s}.sweep.json).
Selected rows (640x360, 1 spp; process CPU ms per frame; A / B: on the same-spp / supersampled Pareto front;
exact reference: {d['references']['exact']['status']}):

{chr(10).join(lines)}
"""


def machine():
    d = load(os.path.join(SPEED, '1280x720', 'seed.sweep.json'))
    m = d['machine']
    return f"`GL_RENDERER` **`{m['gl_renderer']}`**, {m['gl_version']}, backend `{m['backend']}`"


def main():
    with open(os.path.join(os.path.dirname(__file__), 'template.md')) as f:
        text = f.read()
    newest = max(os.path.getmtime(os.path.join(SPEED, sub, f'{s}.sweep.json')) for s in SCENES for sub in ('', '1280x720'))
    text = text.replace('{{DATE}}', datetime.date.fromtimestamp(newest).isoformat())
    text = text.replace('{{MACHINE}}', machine())
    text = text.replace('{{TARGETS}}', targets())
    text = re.sub(r'\{\{SCENE:(\w+)\}\}', lambda m: scene_section(m.group(1)), text)
    left = re.findall(r'\{\{[^}]*\}\}', text)
    if left:
        raise SystemExit(f'fill.py: unfilled placeholders {left}')
    with open(os.path.join(ROOT, 'docs', 'speed-vs-error.md'), 'w') as f:
        f.write(text)
    print('wrote docs/speed-vs-error.md')


if __name__ == '__main__':
    main()
