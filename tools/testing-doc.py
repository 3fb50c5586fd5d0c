#!/usr/bin/python3
"""Runs every example of docs/testing.md and regenerates its figures.

- Every ```sh block runs as one bash script, every ```console block's
  "$ COMMAND" line (continued by a trailing backslash) runs and its output
  replaces the rest of the block: in order, from the repository root, with
  `marchstudio` on PATH being --bin, renders pinned to Mesa llvmpipe, and CI
  unset (a developer's shell; the examples include --update into out/).
- A ```toml (or other) block after <!-- file: PATH --> is PATH's text, less
  its leading comment lines.
- The golden-tolerance table between <!-- tolerances: begin --> and
  <!-- tolerances: end --> is measured with `marchstudio test --json`: each
  scene on EGL and OSMesa, on llvmpipe without SSE and with 128-bit vectors
  (driver noise), and with the smallest changes we must catch.

Usage:
  /usr/bin/python3 tools/testing-doc.py [--bin build/marchstudio]   rewrite the page
  /usr/bin/python3 tools/testing-doc.py --check [--bin ...]         run the examples; fail if
      an example fails or its output differs from the page (timings aside); the table is
      not re-measured (ctest: docs_testing_examples)
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
DOC = os.path.join(ROOT, 'docs', 'testing.md')
FENCE = re.compile(r'^```(sh|console)\n(.*?)^```\n', re.S | re.M)


def environment(bin_path):
    tools = tempfile.mkdtemp(prefix='testing-doc-bin-')
    os.symlink(os.path.abspath(bin_path), os.path.join(tools, 'marchstudio'))
    env = dict(os.environ)
    env['PATH'] = tools + os.pathsep + env.get('PATH', '')
    env.pop('CI', None)
    env['LIBGL_ALWAYS_SOFTWARE'] = '1'
    mesa = '/usr/share/glvnd/egl_vendor.d/50_mesa.json'
    if os.path.exists(mesa):
        env['__EGL_VENDOR_LIBRARY_FILENAMES'] = mesa
    return env, tools


def run(script, env):
    p = subprocess.run(['bash', '-c', script], cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, stdin=subprocess.DEVNULL)
    return p.returncode, p.stdout


def split_console(body):
    """'$ cmd \\\n  more\nout...' -> (command, shown command lines)."""
    lines = body.split('\n')
    if not lines or not lines[0].startswith('$ '):
        sys.exit('testing-doc: a ```console block must start with "$ COMMAND":\n' + body)
    shown = [lines[0]]
    while shown[-1].endswith('\\'):
        shown.append(lines[len(shown)])
    command = '\n'.join(shown)[2:]
    return command, shown


def normalised(text):
    """Timings and dates vary from run to run; nothing else does."""
    text = re.sub(r'\(\d+(\.\d+)? s\)', '(T s)', text)
    text = re.sub(r'\d+\.\d+x (\w+)\'s \(\d+\.\d+ ms vs \d+\.\d+ ms', r"Rx \1's (T ms vs T ms", text)
    text = re.sub(r'(time|timestamp)="[^"]*"', r'\1="T"', text)
    return text


FILE_BLOCK = re.compile(r'<!-- file: (\S+) -->\n```(\w+)\n(.*?)^```\n', re.S | re.M)


def files(doc, check):
    """Blocks after <!-- file: PATH --> show PATH, less its leading comment lines."""
    failures = []

    def fill(m):
        with open(os.path.join(ROOT, m.group(1))) as f:
            lines = f.read().split('\n')
        while lines and lines[0].startswith('#'):
            lines.pop(0)
        body = '\n'.join(lines).strip('\n') + '\n'
        if check and body != m.group(3):
            failures.append(f'the block showing {m.group(1)} differs from the file')
        return f'<!-- file: {m.group(1)} -->\n```{m.group(2)}\n{body}```\n'

    return FILE_BLOCK.sub(fill, doc), failures


def examples(doc, env, check):
    """Runs the blocks in order; returns the page with fresh outputs."""
    out, at, failures = [], 0, []
    shutil.rmtree(os.path.join(ROOT, 'out', 'doc'), ignore_errors=True)
    for m in FENCE.finditer(doc):
        kind, body = m.group(1), m.group(2)
        out.append(doc[at:m.start()])
        at = m.end()
        if kind == 'sh':
            code, text = run(body, env)
            if code != 0:
                failures.append(f'```sh block exited {code}:\n{body}\n{text}')
            out.append(m.group(0))
            continue
        command, shown = split_console(body)
        code, text = run(command, env)
        if code != 0 and 'echo "exit $?"' not in command:
            failures.append(f'$ {command}\nexited {code}:\n{text}')
        block = '```console\n' + '\n'.join(shown) + '\n' + text + ('' if text.endswith('\n') or not text else '\n') + '```\n'
        if check and normalised(block) != normalised(m.group(0)):
            failures.append(f'output of `{command}` differs from the page:\n--- page\n{m.group(0)}--- now\n{block}')
        out.append(block)
    out.append(doc[at:])
    return ''.join(out), failures


SCENES = sorted(f[:-5] for f in os.listdir(os.path.join(ROOT, 'scenes')) if f.endswith('.toml'))
REGRESSIONS = [('time 0.02', 'time = 0.02'), ('no checker filter', 'disable = ["checker-filter"]'),
               ('no AO', 'disable = ["ao"]'), ('no shadows', 'disable = ["shadows"]'),
               ('no reflections', 'disable = ["reflections"]'), ('2 spp', 'spp = 2')]


def measure(env, tmp, cases, extra_env=None, refs=None, update=False):
    """{case name: (psnr or None for inf, max)} from one `marchstudio test --json` run; the
    references are the goldens, or refs/<scene>.png under `refs`."""
    suite = os.path.join(tmp, 'measure.toml')
    with open(suite, 'w') as f:
        for name, scene, backend, keys in cases:
            ref = f'{refs}/{scene}.png' if refs else f'{ROOT}/tests/golden/{scene}.png'
            f.write(f'[[case]]\nname = "{name}"\nscene = "{ROOT}/scenes/{scene}.toml"\nbackend = "{backend}"\n'
                    f'reference = "{ref}"\nsize = [160, 90]\nthreshold = -1000\n{keys}\n')
    e = dict(env)
    e.update(extra_env or {})
    p = subprocess.run(['marchstudio', 'test', suite, '--json'] + (['--update'] if update else []), env=e,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit('testing-doc: measuring failed:\n' + p.stderr)
    return {c['name']: (c['checks'][0]['psnr'], c['checks'][0]['max']) for c in json.loads(p.stdout)['cases']}


def cell(v):
    psnr, mx = v
    return ('inf' if psnr is None else f'{psnr:.2f} dB') + f', max {mx * 255:.0f}/255'


def tolerance_table(env):
    tmp = tempfile.mkdtemp(prefix='testing-doc-')
    noise = [(f'{s}.{b}', s, b, '') for s in SCENES for b in ('egl', 'osmesa')]
    plain = measure(env, tmp, noise)
    nosse = measure(env, tmp, [(f'{s}.egl', s, 'egl', '') for s in SCENES], {'GALLIUM_OVERRIDE_CPU_CAPS': 'nosse'})
    vec128 = measure(env, tmp, [(f'{s}.egl', s, 'egl', '') for s in SCENES], {'LP_NATIVE_VECTOR_WIDTH': '128'})
    # A regression is measured against this machine's own render of the unchanged scene.
    refs = os.path.join(tmp, 'refs')
    measure(env, tmp, [(s, s, 'egl', '') for s in SCENES], refs=refs, update=True)
    regress = measure(env, tmp, [(f'{s}.{i}', s, 'egl', keys) for s in SCENES for i, (_, keys) in enumerate(REGRESSIONS)],
                      refs=refs)
    shutil.rmtree(tmp)
    rows = ['| scene | egl | osmesa | llvmpipe without SSE | 128-bit vectors | subtlest regression (highest PSNR, '
            'against the unchanged render) |',
            '|---|---|---|---|---|---|']
    worst_noise, best_regression, smallest_max = float('inf'), 0.0, 1.0
    for s in SCENES:
        regs = [(regress[f'{s}.{i}'], label) for i, (label, _) in enumerate(REGRESSIONS)
                if regress[f'{s}.{i}'][0] is not None]  # a change that changes nothing is no regression
        top = max(regs, key=lambda r: r[0][0])
        best_regression = max(best_regression, top[0][0])
        smallest_max = min([smallest_max] + [r[0][1] for r in regs])
        for v in (plain[f'{s}.egl'], plain[f'{s}.osmesa'], nosse[f'{s}.egl'], vec128[f'{s}.egl']):
            if v[0] is not None:
                worst_noise = min(worst_noise, v[0])
        rows.append(f'| {s} | {cell(plain[s + ".egl"])} | {cell(plain[s + ".osmesa"])} | {cell(nosse[s + ".egl"])} | '
                    f'{cell(vec128[s + ".egl"])} | {top[1]}: {cell(top[0])} |')
    labels = ', '.join(label for label, _ in REGRESSIONS)
    rows.append('')
    rows.append(f'Regressions tried on every scene: {labels} (a change that leaves a scene\'s pixels '
                f'identical, such as time in a scene without animation, is left out). Driver noise '
                f'scores {worst_noise:.2f} dB at worst; the subtlest regression {best_regression:.2f} dB, and every '
                f'regression moves some pixel by at least {smallest_max * 255:.0f}/255.')
    return '\n'.join(rows) + '\n'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'marchstudio'))
    ap.add_argument('--check', action='store_true')
    a = ap.parse_args()
    env, tools = environment(a.bin)
    try:
        with open(DOC) as f:
            doc = f.read()
        doc, failures = files(doc, a.check)
        page, more = examples(doc, env, a.check)
        failures += more
        if failures:
            sys.exit('testing-doc: ' + '\n\n'.join(failures))
        if a.check:
            print(f'testing-doc: every example of docs/testing.md ran and printed what the page shows')
            return
        begin, end = '<!-- tolerances: begin -->\n', '<!-- tolerances: end -->'
        i, j = page.index(begin) + len(begin), page.index(end)
        page = page[:i] + tolerance_table(env) + page[j:]
        with open(DOC, 'w') as f:
            f.write(page)
        print('testing-doc: docs/testing.md rewritten')
    finally:
        shutil.rmtree(tools, ignore_errors=True)


if __name__ == '__main__':
    main()
