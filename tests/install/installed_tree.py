"""What an installed marchstudio tree must do, wherever it lies: the checks
that tests/install/check_install.py (cmake --install) and check_package.py
(the .deb and .tar.gz cpack makes) share."""
import os
import subprocess
import sys

NAME = os.path.basename(sys.argv[0]).rsplit('.', 1)[0]


def fail(msg):
    print('%s: %s' % (NAME, msg), file=sys.stderr)
    sys.exit(1)


def run(cmd, cwd, env, timeout=240):
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    if r.returncode != 0:
        fail('%s: exit %d\n%s%s' % (' '.join(cmd), r.returncode, r.stdout, r.stderr))
    return r


def clean_env():
    """The environment without the variables that would point the binary
    away from its own tree."""
    return {k: v for k, v in os.environ.items()
            if k not in ('MARCH_SHADER_DIR', 'MARCH_IMAGE_MODULE', 'MARCH_VDB_MODULE')}


def check_tree(prefix, source, cwd, env):
    """prefix holds bin/, lib/marchstudio/ and share/marchstudio/: run from
    cwd with nothing set, the binary finds its GLSL library and image module
    inside the tree (its -v lines name them), renders a PNG and a JPEG (the
    JPEG needs the module) and reads the JPEG back (`info`). Returns the
    binary's path."""
    exe = os.path.join(prefix, 'bin', 'marchstudio')
    module = os.path.join(prefix, 'lib', 'marchstudio', 'marchstudio-oiio.so')
    vdb_module = os.path.join(prefix, 'lib', 'marchstudio', 'marchstudio-vdb.so')  # mesh/'s .vdb writer
    shaders = os.path.join(prefix, 'share', 'marchstudio', 'sdf_shaders')
    for p in (exe, module, vdb_module, os.path.join(shaders, 'main.frag')):
        if not os.path.isfile(p):
            fail('the tree has no ' + os.path.relpath(p, prefix))
    if os.listdir(os.path.join(prefix, 'bin')) != ['marchstudio']:
        fail('bin/ holds more than the binary: %s' % os.listdir(os.path.join(prefix, 'bin')))
    scene = os.path.join(source, 'scenes', 'seed.toml')
    for out in ('seed.png', 'seed.jpg'):
        r = run([exe, 'render', scene, '--size', '64x36', '-o', out, '-v'], cwd, env)
        if r.stdout.strip() != out:
            fail('render printed %r, not %r' % (r.stdout, out))
        if 'marchstudio: shader dir %s\n' % shaders not in r.stderr:
            fail('the shaders did not come from the tree:\n' + r.stderr)
        if os.path.getsize(os.path.join(cwd, out)) < 100:
            fail(out + ' is empty')
    if 'marchstudio: image module %s\n' % module not in r.stderr:
        fail('the image module did not come from the tree:\n' + r.stderr)
    info = run([exe, 'info', 'seed.jpg'], cwd, env)
    if '64x36' not in info.stdout:
        fail('info of the JPEG says:\n' + info.stdout)
    return exe
