"""The README's Python one-liners run as documented (the examples in the README work from a
clean clone after the set-up command). Each `PYTHONPATH=build/python /usr/bin/python3 -c "..."`
line is run from the project root with this build's package on the path."""
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

LINE = re.compile(r'^PYTHONPATH=build/python /usr/bin/python3 -c "(.*)"$')


def readme_snippets():
    with open(os.path.join(SOURCE_DIR, "README.md")) as f:
        return [m.group(1) for m in map(LINE.match, f.read().splitlines()) if m]


def test_the_readme_has_python_snippets():
    assert len(readme_snippets()) >= 3


@pytest.mark.parametrize("code", readme_snippets())
def test_readme_snippet_runs(code):
    # PYTHONPATH is this build's python/ (CTest sets it), which may not be build/python.
    r = subprocess.run([sys.executable, "-c", code], cwd=SOURCE_DIR, capture_output=True, text=True,
                       env=dict(os.environ), timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip()
