"""The Python package's tests (docs/python.md): run by ctest as
`python3 -m pytest tests/python` with PYTHONPATH=build/python and
MARCH_BIN the command-line binary, so a test can hold the package's
output to the CLI's."""
import os
import shutil

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), '..', '..'))


@pytest.fixture(scope='session')
def cli():
    path = os.environ.get('MARCH_BIN') or shutil.which('marchstudio')
    if not path:
        pytest.skip('MARCH_BIN is not set (ctest sets it)')
    return path


@pytest.fixture(scope='session')
def root():
    return ROOT
