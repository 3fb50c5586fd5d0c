#!/usr/bin/python3
"""Measures docs/viewer.md's figures and writes them between its markers.

- viewer-reload: the reload latency of three kinds of save. A save of the
  scene TOML that changes only the camera (a per-frame uniform) needs no
  recompile: the shader text is the same, so the viewer's program cache
  has it. A light's intensity is folded into the shader as a constant
  (docs/viewer.md#folding), so its save is new shader text, as is a save of
  the map GLSL with a new constant: assembled, compiled and linked again on
  the compile worker; Mesa's disk shader cache starts empty
  (MESA_SHADER_CACHE_DIR), as for an edit never compiled before.
  For each window size and kind, SAVES saves by rename(); per save the
  in-viewer `ms` and `compile_ms` of its `reload ok` log line and the
  wall time from the rename until that line is in the log.
- watch-log: what `render --watch` prints for a start, one save and Ctrl+C.
- images/viewer/panel.png: the window with its panel under Xvfb, on
  tests/data/bounds/ball.toml, whose map has a ranged uniform (`uRadius`).
- images/viewer/debug_N_<name>.png: the seed scene's window in each debug
  view, 480x270, without the panel (the overlay and its legend show).

- reload-split: for each scene in scenes/, where the first build's time
  goes, from the `reload ok 0` line: `assemble_ms` (ours: reading,
  preprocessing, assembly), `gl_ms` (the driver's compile and link, on the
  compile worker), `warm_ms` (the worker's warm-up draws: llvmpipe
  JIT-compiles the shader there) and `first_draw_ms` (the UI thread's first
  frame, waited for), against a warm frame (the median `frame_ms` of the
  last second). Mesa's disk cache starts empty; each scene runs a second
  time with MESA_SHADER_CACHE_DISABLE=true, where the warm-up cannot reach
  the UI thread: that run's first_draw_ms is the JIT as it was before.

- frame-vs-render: for each scene in scenes/ at 1280x720, one sample per
  pixel: the viewer's frame time (the median `frame_ms` of its last
  second, `--accumulate 1`, paused, no panel: folded, and the one-pass
  frame where `program fused=1`) against `render`'s (`bench --spp 1`,
  the median wall time of its timed frames: the same folded, one-pass
  program `render` draws).

Needs xvfb-run. Usage: /usr/bin/python3 tools/viewer-figures.py [--images|--split|--frames] [path/to/marchstudio]
(--images: only the pictures; --split: only the reload split; --frames: only frame-vs-render)
"""
import datetime
import os
import platform
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

from doc_markers import put  # tools/doc_markers.py: this directory is on sys.path

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
ARGS = [a for a in sys.argv[1:] if a not in ('--images', '--split', '--frames')]
FRAMES_ONLY = '--frames' in sys.argv[1:]
IMAGES_ONLY = '--images' in sys.argv[1:]
SPLIT_ONLY = '--split' in sys.argv[1:]
SPLIT = re.compile(r'compile_ms=([\d.]+) assemble_ms=([\d.]+) gl_ms=([\d.]+) first_draw_ms=([\d.]+) warm_ms=([\d.]+)')
BIN = os.path.abspath(ARGS[0] if ARGS else os.path.join(ROOT, 'build', 'marchstudio'))
DEBUG_VIEWS = ['steps', 'normals', 'depth', 'ao', 'shadow', 'material']
SIZES = ['160x90', '320x180', '640x360', '1280x720']
SAVES = 4
ENV = dict(os.environ, LIBGL_ALWAYS_SOFTWARE='1', MARCH_SHADER_DIR=os.path.join(ROOT, 'sdf_shaders'))
RELOAD = re.compile(r'^reload ok (\d+) frames=(\d+) iterations=\d+ ms=([\d.]+) compile_ms=([\d.]+)(.*)$')


def replace(path, text):
    tmp = path + '.new'
    open(tmp, 'w').write(text)
    os.rename(tmp, path)  # as vim or VS Code save


def wait_line(log, n, deadline=60):
    t_end = time.monotonic() + deadline
    while time.monotonic() < t_end:
        for line in open(log).read().splitlines() if os.path.exists(log) else []:
            if re.match(r'^reload (ok|failed) %d ' % n, line):
                return line
        time.sleep(0.002)
    raise SystemExit('viewer-figures: no reload %d line in %s' % (n, log))


def measure(size, work):
    for f in ('seed.toml', 'seed.glsl'):
        shutil.copy(os.path.join(ROOT, 'scenes', f), work)
    log = os.path.join(work, 'log.txt')
    if os.path.exists(log):
        os.remove(log)
    p = subprocess.Popen(['xvfb-run', '-a', '-s', '-screen 0 1920x1080x24', BIN, 'view', 'seed.toml',
                          '--size', size, '--log', log, '--exit-after', '300'], cwd=work,
                         env=dict(ENV, MESA_SHADER_CACHE_DIR=os.path.join(work, 'mesa-cache')),  # empty: a new edit misses
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    rows = {'camera': [], 'light': [], 'glsl': []}
    try:
        wait_line(log, 0)
        time.sleep(1.0)
        n = 0
        toml = open(os.path.join(work, 'seed.toml')).read()
        glsl = open(os.path.join(work, 'seed.glsl')).read()
        for k in range(SAVES):
            for kind in ('camera', 'light', 'glsl'):
                n += 1
                # TOML edits build on the last one, so that each save changes one value
                if kind == 'camera':  # a uniform value only
                    path, text = 'seed.toml', re.sub(r'position = \[0\.0, 1\.6, [-\d.]+\]',
                                                     'position = [0.0, 1.6, %.2f]' % (-5.0 - 0.05 * (k + 1)), toml)
                    toml = text
                elif kind == 'light':  # a folded value: new shader text
                    path, text = 'seed.toml', re.sub(r'intensity   = [\d.]+', 'intensity   = %.2f' % (2.0 + 0.05 * (k + 1)),
                                                     toml)
                    toml = text
                else:  # new shader text: a radius never compiled before in this session
                    path, text = 'seed.glsl', glsl.replace('1.0), MAT_BALL', '%.4f), MAT_BALL' % (1.0 - 0.001 * (k + 1)))
                t0 = time.monotonic()
                replace(os.path.join(work, path), text)
                line = wait_line(log, n)
                wall = (time.monotonic() - t0) * 1000
                m = RELOAD.match(line)
                if not m:
                    raise SystemExit('viewer-figures: reload %d failed: %s' % (n, line))
                rows[kind].append((int(m.group(2)), float(m.group(3)), float(m.group(4)), wall))
                time.sleep(1.0)
        frame = [float(x) for x in re.findall(r'frame_ms=([\d.]+)', open(log).read())]
    finally:
        os.killpg(p.pid, signal.SIGTERM)
        p.wait()
    return rows, statistics.median(frame) if frame else float('nan')


def span(xs, fmt='%.0f'):
    lo, hi = min(xs), max(xs)
    return (fmt % lo) if fmt % lo == fmt % hi else '%s - %s' % (fmt % lo, fmt % hi)


def watch_log(work):
    for f in ('seed.toml', 'seed.glsl'):
        shutil.copy(os.path.join(ROOT, 'scenes', f), work)
    p = subprocess.Popen([BIN, 'render', '--watch', 'seed.toml', '-o', 'out/seed.png', '--size', '320x180'], cwd=work,
                         env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    time.sleep(4)
    glsl = open(os.path.join(work, 'seed.glsl')).read()
    replace(os.path.join(work, 'seed.glsl'), glsl.replace('1.0), MAT_BALL', '0.9), MAT_BALL'))
    time.sleep(4)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=30)
    return out.rstrip('\n').split('\n'), p.returncode


def panel(work):
    for f in ('ball.toml', 'ball.glsl'):
        shutil.copy(os.path.join(ROOT, 'tests', 'data', 'bounds', f), work)
    window_shot(work, ['ball.toml'], '960x600', os.path.join(ROOT, 'docs', 'images', 'viewer', 'panel.png'))


def window_shot(work, args, size, out):
    shots = os.path.join(work, 'shots')
    shutil.rmtree(shots, ignore_errors=True)
    subprocess.run(['xvfb-run', '-a', '-s', '-screen 0 1920x1080x24', BIN, 'view'] + args +
                   ['--size', size, '--paused', '--shot-frame', '20', '--shot-dir', shots, '--max-frames', '25'],
                   cwd=work, env=ENV, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
    win = [f for f in os.listdir(shots) if '_window_' in f]
    if len(win) != 1:
        raise SystemExit('viewer-figures: expected one window screenshot, found %s' % os.listdir(shots))
    shutil.copy(os.path.join(shots, win[0]), out)


def debug_views(work):
    for f in ('seed.toml', 'seed.glsl'):
        shutil.copy(os.path.join(ROOT, 'scenes', f), work)
    for n, name in enumerate(DEBUG_VIEWS, 1):
        window_shot(work, ['seed.toml', '--no-panel', '--debug-view', str(n)], '480x270',
                    os.path.join(ROOT, 'docs', 'images', 'viewer', 'debug_%d_%s.png' % (n, name)))


TINY = 'void mainImage(out vec4 o, in vec2 f) { o = vec4(f.x / iResolution.x, 0.0, 0.0, 1.0); }\n'


def reload_split(date, cpu, renderer):
    rows = []
    inputs = [os.path.join(ROOT, 'scenes', f) for f in sorted(os.listdir(os.path.join(ROOT, 'scenes'))) if f.endswith('.toml')]
    for path in [None] + inputs:  # None: a one-line shader, the first frame's fixed cost (the UI's, the post pass)
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, 'log.txt')
            if path is None:
                path = os.path.join(work, 'one_line.glsl')
                open(path, 'w').write(TINY)
            toml = os.path.basename(path).rsplit('.', 1)[0] + '.'
            texts = []
            # Twice: with an empty disk shader cache (the warm-up's JIT reaches the UI thread through it),
            # then with none (MESA_SHADER_CACHE_DISABLE: the JIT lands in the first draw, as before the worker).
            for extra in ({}, {'MESA_SHADER_CACHE_DISABLE': 'true'}):
                if os.path.exists(log):
                    os.remove(log)
                subprocess.run(['xvfb-run', '-a', '-s', '-screen 0 1920x1080x24', BIN, 'view',
                                path, '--size', '640x360', '--paused', '--no-panel',
                                '--log', log, '--exit-after', '3.5'],
                               env=dict(ENV, MESA_SHADER_CACHE_DIR=os.path.join(work, 'mesa-cache'), **extra), check=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
                texts.append(open(log).read())
            text = texts[0]
        m = SPLIT.search(re.search(r'^reload ok 0 .*$', text, re.M).group(0))
        uncached = SPLIT.search(re.search(r'^reload ok 0 .*$', texts[1], re.M).group(0))
        frame = [float(x) for x in re.findall(r'frame_ms=([\d.]+)', text)]
        rows.append('| %s | %s | %s | %s | %s | %s | %s | %s |' % (toml[:-1], m.group(2), m.group(3), m.group(5), m.group(4),
                                                                 uncached.group(4), m.group(1),
                                                                 '%.0f' % frame[-1] if frame else '-'))
        print('split %s' % toml, file=sys.stderr)
    return ['Measured by `tools/viewer-figures.py --split` on %s (%d cores), Xvfb, `GL_RENDERER` = `%s`, %s: the'
            % (cpu, os.cpu_count(), renderer, date),
            'first build of each scene at 640x360, paused, Mesa\'s disk shader cache empty. *ours*: reading, preprocessing',
            'and assembly (on the UI thread); *GL*: glCompileShader and glLinkProgram (on the compile worker);',
            '*warm-up*: the worker\'s 8x8 draws, where llvmpipe JIT-compiles the shader; *first draw*: the UI',
            'thread\'s first frame with the program, waited for with glFinish; *no cache*: the same with',
            '`MESA_SHADER_CACHE_DISABLE=true`, where the warm-up cannot reach the UI thread and the first draw',
            'JIT-compiles again, as before the worker; *load to program*: from the',
            'start of the reload to the program adopted; *warm frame*: the median frame time of the last second.',
            '`one_line` is a one-line Shadertoy shader: the fixed cost of any first frame (the panel\'s font',
            'texture and shaders, the post pass).',
            '',
            '| scene | ours (ms) | GL compile + link (ms) | warm-up, JIT (ms) | first draw (ms) | first draw, no cache (ms) | load to program (ms) | warm frame (ms) |',
            '|---|---|---|---|---|---|---|---|'] + rows


def frame_vs_render(date, cpu, renderer):
    rows = []
    for toml in sorted(f for f in os.listdir(os.path.join(ROOT, 'scenes')) if f.endswith('.toml')):
        path = os.path.join(ROOT, 'scenes', toml)
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, 'log.txt')
            subprocess.run(['xvfb-run', '-a', '-s', '-screen 0 1920x1080x24', BIN, 'view', path, '--size', '1280x720',
                            '--accumulate', '1', '--paused', '--no-panel', '--log', log, '--exit-after', '9'],
                           env=ENV, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=180)
            text = open(log).read()
        viewer = [float(x) for x in re.findall(r'^frames \d+ .*frame_ms=([\d.]+)', text, re.M)]
        fused = re.findall(r'^program fused=(\d)', text, re.M)
        bench = subprocess.run([BIN, 'bench', path, '--size', '1280x720', '--spp', '1', '--frames', '5', '--warmup', '1',
                                '--json'], env=ENV, capture_output=True, text=True, check=True, timeout=300).stdout
        render = re.search(r'"wall":\s*\{\s*"min":\s*[\d.]+,\s*"median":\s*([\d.]+)', bench).group(1)
        rows.append('| %s | %s | %.0f | %.0f |' % (toml[:-5], 'yes' if fused and fused[-1] == '1' else 'no',
                                                  viewer[-1] if viewer else float('nan'), float(render)))
        print('frames %s' % toml, file=sys.stderr)
    return ['Measured by `tools/viewer-figures.py --frames` on %s (%d cores), Xvfb, `GL_RENDERER` = `%s`, %s:'
            % (cpu, os.cpu_count(), renderer, date),
            'each scene at 1280x720, one sample per pixel. *viewer*: `view --accumulate 1 --paused --no-panel`, the',
            'median frame time (swap to swap) of its last second; *one pass*: its program is the fused one',
            '(`program fused=1`; bloom scenes keep the post pass, as `render` does); *render*: `bench --spp 1`, the',
            'median wall time of 5 frames, the program `render` draws. Both fold the scene\'s values.',
            '',
            '| scene | one pass | viewer frame (ms) | render frame (ms) |',
            '|---|---|---|---|'] + rows


def machine():
    renderer = subprocess.run([BIN, 'bench', os.path.join(ROOT, 'scenes', 'seed.toml'), '--size', '16x16', '--frames', '1',
                               '--json'], env=ENV, capture_output=True, text=True, check=True).stdout
    renderer = re.search(r'"gl_renderer":\s*"([^"]*)"', renderer).group(1)
    with open('/proc/cpuinfo') as f:
        cpu = next((l.split(':', 1)[1].strip() for l in f if l.startswith('model name')), platform.machine())
    date = datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d')
    return date, cpu, renderer


def images():
    with tempfile.TemporaryDirectory() as work:
        panel(work)
    with tempfile.TemporaryDirectory() as work:
        debug_views(work)
    print('wrote docs/images/viewer/panel.png and debug_*.png', file=sys.stderr)


def main():
    if not shutil.which('xvfb-run'):
        raise SystemExit('viewer-figures: needs xvfb-run')
    if IMAGES_ONLY:
        return images()
    doc = os.path.join(ROOT, 'docs', 'viewer.md')
    date, cpu, renderer = machine()
    if FRAMES_ONLY:
        return put(doc, 'frame-vs-render', frame_vs_render(date, cpu, renderer))
    put(doc, 'reload-split', reload_split(date, cpu, renderer))
    if SPLIT_ONLY:
        return
    put(doc, 'frame-vs-render', frame_vs_render(date, cpu, renderer))
    table = ['Measured by `tools/viewer-figures.py` on %s (%d cores), Xvfb, `GL_RENDERER` = `%s`, %s: the seed'
             % (cpu, os.cpu_count(), renderer, date),
             'scene, spp 1, %d saves of each kind per window size, one second apart. *save to log line*: wall time from'
             % SAVES,
             'the `rename()` until the `reload ok` line is in the log file. Mesa\'s disk shader cache starts empty, so',
             'each new radius or intensity is a real compile, as an edit never made before is.', '',
             '| window | frame time (median) | save | in-viewer `ms` (event to swap) | `compile_ms` | save to log line | frames |',
             '|---|---|---|---|---|---|---|']
    for size in SIZES:
        with tempfile.TemporaryDirectory() as work:
            rows, frame = measure(size, work)
        for kind, label in (('camera', 'TOML, the camera\'s position (no recompile)'),
                            ('light', 'TOML, a light\'s intensity (folded: recompile)'),
                            ('glsl', 'map GLSL, a new radius (recompile)')):
            r = rows[kind]
            table.append('| %s | %.0f ms | %s | %s ms | %s ms | %s ms | %s |' % (
                size, frame, label, span([x[1] for x in r]), span([x[2] for x in r], '%.1f'), span([x[3] for x in r]),
                span([x[0] for x in r], '%d')))
        print('measured %s' % size, file=sys.stderr)
    put(doc, 'viewer-reload', table)
    with tempfile.TemporaryDirectory() as work:
        lines, rc = watch_log(work)
    put(doc, 'watch-log', ['```text', '$ marchstudio render --watch seed.toml -o out/seed.png --size 320x180',
                           '(one save of seed.glsl, then Ctrl+C)'] + lines +
        ['```', 'Exit status %d. Printed by `tools/viewer-figures.py`, %s.' % (rc, date)])
    images()
    print('wrote docs/viewer.md', file=sys.stderr)


if __name__ == '__main__':
    main()
