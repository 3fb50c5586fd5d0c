"""docs/python.md: every ```python block runs (in a scratch directory with
the tree's scenes/), and its table is python/doc_table.py's output."""
import importlib.util
import os
import re
import subprocess
import sys

import pytest

import marchstudio

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), '..', '..'))
PAGE = os.path.join(ROOT, 'docs', 'python.md')


def blocks():
    text = open(PAGE, encoding='utf-8').read()
    for m in re.finditer(r'^```python\n(.*?)^```$', text, re.S | re.M):
        yield text.count('\n', 0, m.start()) + 1, m.group(1)


@pytest.mark.parametrize('line, code', list(blocks()), ids=lambda x: str(x) if isinstance(x, int) else '')
def test_example_runs(line, code, tmp_path):
    os.symlink(os.path.join(ROOT, 'scenes'), tmp_path / 'scenes')
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(marchstudio.__file__)))
    r = subprocess.run([sys.executable, '-c', code], cwd=tmp_path, env=env, capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, f"docs/python.md:{line}: {r.stderr}"
    assert r.stdout.strip(), f"docs/python.md:{line}: printed nothing"


def test_table_is_generated():
    spec = importlib.util.spec_from_file_location('doc_table', os.path.join(ROOT, 'python', 'doc_table.py'))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert mod.table() in open(PAGE, encoding='utf-8').read()
