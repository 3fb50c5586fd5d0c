#!/usr/bin/python3
"""Runs the example commands of README.md and docs/*.md, as a reader would.

Every ```sh block is one bash script, run from a scratch directory that
holds copies of the repository's scenes/, tests/, sdf_shaders/, tools/ and
docs/ (copies, so that an example that writes next to its inputs, or a
tool that rewrites a page, never touches the tree), with `marchstudio` on
PATH being --bin and `build/marchstudio` pointing at it too; renders are
pinned to Mesa llvmpipe, and CI is unset (a developer's shell). A block
fails when it exits non-zero or runs longer than --timeout seconds (then
it is killed with everything it started).

A block that cannot run here says why on the line before its fence:
    <!-- docs-test: skip (a Slurm cluster and /shared) -->
A skip without a reason fails. docs/testing.md is left to
tools/testing-doc.py, which also checks its outputs. The README's set-up
commands install packages and build: they are what CI itself runs, so
they are skipped here.

Usage: /usr/bin/python3 tools/docs-examples.py --bin build/marchstudio [--list] [FILE...]
ctest: docs_examples (label docs).
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
FENCE = re.compile(r'^([ \t]*)```sh[ \t]*\n(.*?)^\1```[ \t]*$', re.S | re.M)
SKIP = re.compile(r'<!--\s*docs-test:\s*skip\s*(.*?)-->\s*$')
OWN_CHECKER = {'docs/testing.md'}  # tools/testing-doc.py


def blocks(path):
    text = open(path, encoding='utf-8').read()
    for m in FENCE.finditer(text):
        line = text.count('\n', 0, m.start()) + 1
        before = text[:m.start()].rstrip('\n').rsplit('\n', 1)[-1]
        skip = SKIP.search(before)
        indent = m.group(1)
        body = '\n'.join(l[len(indent):] if l.startswith(indent) else l for l in m.group(2).split('\n'))
        yield line, body, skip.group(1).strip() if skip else None


def scratch(bin_path):
    work = tempfile.mkdtemp(prefix='docs-examples-')
    for d in ('scenes', 'tests', 'sdf_shaders', 'tools', 'docs'):
        shutil.copytree(os.path.join(ROOT, d), os.path.join(work, d), symlinks=True)
    os.mkdir(os.path.join(work, 'build'))
    os.symlink(os.path.abspath(bin_path), os.path.join(work, 'build', 'marchstudio'))
    tools = os.path.join(work, '.bin')
    os.mkdir(tools)
    os.symlink(os.path.abspath(bin_path), os.path.join(tools, 'marchstudio'))
    env = dict(os.environ)
    env['PATH'] = tools + os.pathsep + env.get('PATH', '')
    env.pop('CI', None)
    env['LIBGL_ALWAYS_SOFTWARE'] = '1'
    env['MARCH_SHADER_DIR'] = os.path.join(work, 'sdf_shaders')
    mesa = '/usr/share/glvnd/egl_vendor.d/50_mesa.json'
    if os.path.exists(mesa):
        env['__EGL_VENDOR_LIBRARY_FILENAMES'] = mesa
    return work, env


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'marchstudio'))
    ap.add_argument('--timeout', type=float, default=120)
    ap.add_argument('--list', action='store_true', help='list the blocks and whether they run')
    ap.add_argument('files', nargs='*')
    a = ap.parse_args()
    files = a.files or ['README.md'] + sorted('docs/' + f for f in os.listdir(os.path.join(ROOT, 'docs'))
                                               if f.endswith('.md'))
    failed, ran, skipped = [], 0, 0
    t_all = time.monotonic()
    for rel in files:
        if rel in OWN_CHECKER:
            continue
        for line, body, skip in blocks(os.path.join(ROOT, rel)):
            where = '%s:%d' % (rel, line)
            if skip == '' or skip == '()':
                failed.append(where)  # a skip must say why
                print('FAILED %s: a docs-test skip without a reason in parentheses' % where)
                continue
            if skip or rel == 'README.md':
                skipped += 1
                print('skip   %s %s' % (where, skip or '(set-up commands: CI runs them)'), flush=True)
                continue
            if a.list:
                print('run    %s' % where)
                continue
            work, env = scratch(a.bin)
            t0 = time.monotonic()
            # Its own session, so that a timeout ends the whole block (bash and
            # every marchstudio it started), not only bash.
            p = subprocess.Popen(['bash', '-e', '-o', 'pipefail', '-c', body], cwd=work, env=env,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 stdin=subprocess.DEVNULL, start_new_session=True)
            try:
                out, _ = p.communicate(timeout=a.timeout)
                rc = p.returncode
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                out, _ = p.communicate()
                rc = 'timeout after %g s' % a.timeout
            dt = time.monotonic() - t0
            shutil.rmtree(work, ignore_errors=True)
            ran += 1
            print('%-6s %s (%.1f s)' % ('ok' if rc == 0 else 'FAILED', where, dt), flush=True)
            if rc != 0:
                failed.append(where)
                print('  exit %s; the block:\n%s\n  its output:\n%s' % (rc, body.rstrip(), out.rstrip()[-3000:]))
    if not a.list:
        print('docs-examples: %d ran, %d skipped, %d failed, %.0f s' % (ran, skipped, len(failed),
                                                                        time.monotonic() - t_all))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
