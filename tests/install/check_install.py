#!/usr/bin/python3
"""`cmake --install` gives a tree that runs anywhere: installed to one prefix,
moved to another, and run from a third directory with nothing set, the
binary finds its GLSL library and its image module inside the tree (its -v
lines name them), renders a PNG and a JPEG (the JPEG needs the module) and
reads the JPEG back (`info`)."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile


def fail(msg):
    print('check_install: ' + msg, file=sys.stderr)
    sys.exit(1)


def run(cmd, cwd, env):
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=240)
    if r.returncode != 0:
        fail('%s: exit %d\n%s%s' % (' '.join(cmd), r.returncode, r.stdout, r.stderr))
    return r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cmake', required=True)
    ap.add_argument('--build', required=True)
    ap.add_argument('--source', required=True)
    a = ap.parse_args()
    env = {k: v for k, v in os.environ.items() if k not in ('MARCH_SHADER_DIR', 'MARCH_IMAGE_MODULE', 'MARCH_VDB_MODULE')}
    with tempfile.TemporaryDirectory() as tmp:
        first = os.path.join(tmp, 'first')
        run([a.cmake, '--install', a.build, '--prefix', first], tmp, env)
        # Moved whole: nothing may depend on the prefix it was installed to.
        prefix = os.path.join(tmp, 'moved')
        shutil.move(first, prefix)
        exe = os.path.join(prefix, 'bin', 'marchstudio')
        module = os.path.join(prefix, 'lib', 'marchstudio', 'marchstudio-oiio.so')
        vdb_module = os.path.join(prefix, 'lib', 'marchstudio', 'marchstudio-vdb.so')  # mesh/'s .vdb writer
        shaders = os.path.join(prefix, 'share', 'marchstudio', 'sdf_shaders')
        for p in (exe, module, vdb_module, os.path.join(shaders, 'main.frag')):
            if not os.path.isfile(p):
                fail('the install has no ' + os.path.relpath(p, prefix))
        if os.listdir(os.path.join(prefix, 'bin')) != ['marchstudio']:
            fail('bin/ holds more than the binary: %s' % os.listdir(os.path.join(prefix, 'bin')))
        cwd = os.path.join(tmp, 'elsewhere')
        os.mkdir(cwd)
        scene = os.path.join(a.source, 'scenes', 'seed.toml')
        for out in ('seed.png', 'seed.jpg'):
            r = run([exe, 'render', scene, '--size', '64x36', '-o', out, '-v'], cwd, env)
            if r.stdout.strip() != out:
                fail('render printed %r, not %r' % (r.stdout, out))
            if 'marchstudio: shader dir %s\n' % shaders not in r.stderr:
                fail('the shaders did not come from the install:\n' + r.stderr)
            if os.path.getsize(os.path.join(cwd, out)) < 100:
                fail(out + ' is empty')
        if 'marchstudio: image module %s\n' % module not in r.stderr:
            fail('the image module did not come from the install:\n' + r.stderr)
        info = run([exe, 'info', 'seed.jpg'], cwd, env)
        if '64x36' not in info.stdout:
            fail('info of the JPEG says:\n' + info.stdout)
    print('check_install: ok')


if __name__ == '__main__':
    main()
