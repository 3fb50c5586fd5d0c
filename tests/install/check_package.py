#!/usr/bin/python3
"""The packages cpack makes install and run from another folder: the .deb
declares its Debian dependencies (each one a package this machine knows,
the dlopen'd ones among them), and unpacked into a scratch root, like the
.tar.gz unpacked and moved elsewhere, it passes installed_tree.check_tree,
prints its version and runs `marchstudio test` on a suite of another
project's, as that project's CI would."""
import argparse
import glob
import os
import re
import shutil
import tarfile
import tempfile

from installed_tree import check_tree, clean_env, fail, run

# dpkg-shlibdeps finds what is linked; these are dlopen'd, so listed by hand.
DLOPENED = ('libosmesa6', 'libegl-mesa0', 'libgl1-mesa-dri', 'libsndfile1')
# One of each kind that only dpkg-shlibdeps can have found.
LINKED = (r'libc6\b', r'libopenimageio\S*', r'libopenvdb\S*', r'libegl1\b')

SUITE = '''[[case]]
name = "seed"
scene = "scenes/seed.toml"
reference = "refs/seed.png"
size = [32, 18]
'''


def depends(deb, env):
    """The Depends field's package names (every alternative)."""
    field = run(['dpkg-deb', '-f', deb, 'Depends'], None, env).stdout
    names = [re.sub(r'\s*\(.*\)', '', alt).strip()
             for dep in field.split(',') for alt in dep.split('|')]
    return field.strip(), [n for n in names if n]


def check_depends(deb, env):
    field, names = depends(deb, env)
    for want in DLOPENED:
        if want not in names:
            fail('Depends lacks %s: %s' % (want, field))
    for pattern in LINKED:
        if not any(re.fullmatch(pattern, n) for n in names):
            fail('Depends has nothing matching %s (dpkg-shlibdeps): %s' % (pattern, field))
    for n in names:  # a misspelt name would make the package uninstallable
        run(['dpkg-query', '-W', n], None, env)


def check_suite(exe, source, tmp, cwd, env):
    """A project of its own, outside the source tree, tested from cwd."""
    project = os.path.join(tmp, 'project')
    if not os.path.isdir(project):
        os.makedirs(os.path.join(project, 'scenes'))
        for f in ('seed.toml', 'seed.glsl'):
            shutil.copy(os.path.join(source, 'scenes', f), os.path.join(project, 'scenes'))
        with open(os.path.join(project, 'suite.toml'), 'w') as f:
            f.write(SUITE)
        run([exe, 'test', os.path.join(project, 'suite.toml'), '--update', '--force'], cwd, env)
    r = run([exe, 'test', os.path.join(project, 'suite.toml')], cwd, env)
    if '1 case: 1 passed' not in r.stdout:
        fail('test printed:\n' + r.stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cpack', required=True)
    ap.add_argument('--build', required=True)
    ap.add_argument('--source', required=True)
    ap.add_argument('--version', required=True)
    a = ap.parse_args()
    env = clean_env()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'packages')
        run([a.cpack, '--config', os.path.join(a.build, 'CPackConfig.cmake'), '-B', out], tmp, env)
        debs = glob.glob(os.path.join(out, 'marchstudio_%s_*.deb' % a.version))
        tgzs = glob.glob(os.path.join(out, 'marchstudio-%s-*.tar.gz' % a.version))
        if len(debs) != 1 or len(tgzs) != 1:
            fail('cpack made %s' % os.listdir(out))
        check_depends(debs[0], env)

        root = os.path.join(tmp, 'root')
        run(['dpkg-deb', '-x', debs[0], root], tmp, env)
        with tarfile.open(tgzs[0]) as t:
            t.extractall(os.path.join(tmp, 'unpacked'))
        top = os.listdir(os.path.join(tmp, 'unpacked'))
        if len(top) != 1:
            fail('the .tar.gz holds %s, not one folder' % top)
        moved = os.path.join(tmp, 'moved')  # relocatable: moved whole
        shutil.move(os.path.join(tmp, 'unpacked', top[0]), moved)

        for prefix in (os.path.join(root, 'usr'), moved):
            cwd = tempfile.mkdtemp(dir=tmp)
            exe = check_tree(prefix, a.source, cwd, env)
            v = run([exe, '--version'], cwd, env).stdout
            if v.strip() != 'marchstudio ' + a.version:
                fail('--version printed %r' % v)
            check_suite(exe, a.source, tmp, cwd, env)
    print('check_package: ok')


if __name__ == '__main__':
    main()
