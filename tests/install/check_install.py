#!/usr/bin/python3
"""`cmake --install` gives a tree that runs anywhere: installed to one prefix,
moved to another, and run from a third directory with nothing set, it
passes installed_tree.check_tree."""
import argparse
import os
import shutil
import tempfile

from installed_tree import check_tree, clean_env, run


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cmake', required=True)
    ap.add_argument('--build', required=True)
    ap.add_argument('--source', required=True)
    a = ap.parse_args()
    env = clean_env()
    with tempfile.TemporaryDirectory() as tmp:
        first = os.path.join(tmp, 'first')
        run([a.cmake, '--install', a.build, '--prefix', first], tmp, env)
        # Moved whole: nothing may depend on the prefix it was installed to.
        prefix = os.path.join(tmp, 'moved')
        shutil.move(first, prefix)
        cwd = os.path.join(tmp, 'elsewhere')
        os.mkdir(cwd)
        check_tree(prefix, a.source, cwd, env)
    print('check_install: ok')


if __name__ == '__main__':
    main()
