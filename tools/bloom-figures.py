#!/usr/bin/python3
"""Regenerates docs/post.md's measured figures and images.

Times tests/data/bloom/orbs.toml (the docs' demo: the seed scene with
three glowing orbs and [post.bloom]) at 1280x720 with `bench --json`
(--frames 10 after 2 warm-up frames; its wall-clock median per frame, the
draw waited for): without bloom (--disable bloom), with bloom at scale 0.3
(the scene's) and at scale 1.0 (--set post.bloom.scale=1.0), each --runs
times, in turn. The bloom passes' cost is the median with bloom minus the
median without. The images are `render`'s. The PSNR between
the 0.3 and 1.0 images is `marchstudio compare`'s. GL_RENDERER is
`bench --json`'s. Writes docs/images/post/orbs_plain.png and orbs_bloom.png
(640x360) and the block between the bloom-figures markers in docs/post.md.

Usage: /usr/bin/python3 tools/bloom-figures.py [--bin build/marchstudio] [--runs 5]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
SCENE = os.path.join(ROOT, 'tests', 'data', 'bloom', 'orbs.toml')
DOC = os.path.join(ROOT, 'docs', 'post.md')
BEGIN, END = '<!-- bloom-figures:begin -->', '<!-- bloom-figures:end -->'


def run(args):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode not in (0, 1):
        sys.exit('failed: %s\n%s' % (' '.join(args), r.stderr))
    return r


def frame_ms(binary, extra):
    r = run([binary, 'bench', SCENE, '--size', '1280x720', '--frames', '10', '--warmup', '2', '--json'] + extra)
    return json.loads(r.stdout)['frame_ms']['wall']['median']


def machine(binary):
    r = run([binary, 'bench', SCENE, '--size', '64x36', '--frames', '1', '--warmup', '0', '--json'])
    gl = json.loads(r.stdout)['machine']['gl_renderer']
    distro = 'Linux'
    if os.path.exists('/etc/os-release'):
        info = dict(l.rstrip('\n').split('=', 1) for l in open('/etc/os-release') if '=' in l)
        distro = info.get('PRETTY_NAME', distro).strip('"')
    return '%s, %d cores, %s' % (distro, os.cpu_count(), gl)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'marchstudio'))
    ap.add_argument('--runs', type=int, default=5)
    a = ap.parse_args()
    binary = os.path.abspath(a.bin)
    tmp = tempfile.mkdtemp(prefix='bloom-figures-')
    cases = {'none': ['--disable', 'bloom'], '0.3': [], '1.0': ['--set', 'post.bloom.scale=1.0']}
    times = {k: [] for k in cases}
    for _ in range(a.runs):  # interleaved, so a slow moment of the machine hits every case
        for k, extra in cases.items():
            times[k].append(frame_ms(binary, extra))
    med = {k: statistics.median(v) for k, v in times.items()}
    for k, extra in cases.items():
        run([binary, 'render', SCENE, '-o', os.path.join(tmp, k + '.png'), '--size', '1280x720'] + extra)
    cmp = run([binary, 'compare', os.path.join(tmp, '1.0.png'), os.path.join(tmp, '0.3.png')])
    psnr = re.search(r'psnr\s+([0-9.]+|inf) dB', cmp.stdout).group(1)
    images = os.path.join(ROOT, 'docs', 'images', 'post')
    os.makedirs(images, exist_ok=True)
    for name, extra in (('orbs_plain.png', ['--disable', 'bloom']), ('orbs_bloom.png', [])):
        run([binary, 'render', SCENE, '-o', os.path.join(images, name), '--size', '640x360'] + extra)

    rows = ['| frame at 1280x720 | median frame (`bench`, wall) | bloom adds |', '|---|---|---|',
            '| no bloom (`--disable bloom`) | %.0f ms | - |' % med['none']]
    for k in ('0.3', '1.0'):
        w, h = max(1, round(1280 * float(k))), max(1, round(720 * float(k)))
        rows.append('| bloom, scale %s (targets %dx%d) | %.0f ms | +%.0f ms |' % (k, w, h, med[k], med[k] - med['none']))
    block = '\n'.join([
        BEGIN,
        'Measured by `/usr/bin/python3 tools/bloom-figures.py` (`bench --json` wall medians, the median of %d runs '
        'each, interleaved) on %s:' %
        (a.runs, machine(binary)),
        '',
        *rows,
        '',
        'The image at scale 0.3 against the one at scale 1.0 (`marchstudio compare`): PSNR %s dB.' % psnr,
        END,
    ])
    text = open(DOC, encoding='utf-8').read()
    i, j = text.index(BEGIN), text.index(END) + len(END)
    open(DOC, 'w', encoding='utf-8').write(text[:i] + block + text[j:])
    print(block)


if __name__ == '__main__':
    main()
