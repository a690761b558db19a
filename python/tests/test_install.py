"""The package installs with pip and as a wheel, offline, into a fresh venv that sees Debian's
numpy (--system-site-packages), and then imports from any directory: the README's Python lines
run there with the installed package, not the build tree's.

Both builds reuse this build's CMake directory (RIGIDFOLD_CMAKE_BUILD_DIR, setup.py): nothing is
compiled again, so what is tested is the packaging (pyproject.toml, setup.py, the module copied
into the wheel), on the very extension the other tests check.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import venv

import pytest

import rigidfold
from conftest import BUNDLED, SOURCE_DIR
from test_readme import readme_snippets

BUILD_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(rigidfold.__file__))))


def run(args, **kw):
    r = subprocess.run(args, capture_output=True, text=True, timeout=600, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, args))}:\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r.stdout


def fresh_venv(where):
    venv.EnvBuilder(system_site_packages=True, with_pip=True).create(where)
    return os.path.join(where, "bin", "python")


def clean_env():
    """This process's environment without the build tree on the path (the sanitizer's preload,
    when this build is instrumented, stays: the installed module is this build's)."""
    env = dict(os.environ, RIGIDFOLD_CMAKE_BUILD_DIR=BUILD_DIR, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    return env


def source_copy(tmp_path):
    """What the package's build reads, in a directory of its own: setuptools writes its build/
    and egg-info beside setup.py, which must not touch the tree the other tests read. (With
    RIGIDFOLD_CMAKE_BUILD_DIR the C++ sources are the build directory's own.)"""
    dest = tmp_path / "src"
    for rel in ("pyproject.toml", "setup.py", "CMakeLists.txt", "docs/python.md", "python/rigidfold"):
        src = os.path.join(SOURCE_DIR, rel)
        os.makedirs(dest / os.path.dirname(rel), exist_ok=True)
        (shutil.copytree if os.path.isdir(src) else shutil.copy2)(src, dest / rel)
    return dest


def check_installed(python, tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir(exist_ok=True)
    code = ("import rigidfold, sys; p = rigidfold.load(sys.argv[1]); "
            "print(rigidfold.__file__); print(rigidfold.__version__, rigidfold.__commit__); "
            "print(rigidfold.check(p)['verdict_class'])")
    pattern = os.path.join(BUNDLED, "corrugated_p_rigid.fold")
    where, version, verdict = run([python, "-c", code, pattern], cwd=elsewhere, env=clean_env()).splitlines()
    assert where.startswith(str(tmp_path)), where
    assert version.split()[0] == rigidfold.__version__
    assert version.split()[1] == rigidfold.__commit__
    assert verdict == rigidfold.check(rigidfold.load(pattern))["verdict_class"]
    for snippet in readme_snippets():
        out = run([python, "-c", "import rigidfold; assert rigidfold.__file__.startswith(" + repr(str(tmp_path)) + "); " + snippet],
                  cwd=SOURCE_DIR, env=clean_env())
        assert out.strip()


def test_pip_install_and_the_wheel_into_a_fresh_venv(tmp_path):
    """`pip install --no-build-isolation .`, then the wheel `python3 -m build --no-isolation` makes,
    installed over it in the same venv (one venv: its creation is most of the time)."""
    src = source_copy(tmp_path)
    python = fresh_venv(str(tmp_path / "venv"))
    run([python, "-m", "pip", "install", "--no-build-isolation", str(src)], cwd=tmp_path, env=clean_env())
    check_installed(python, tmp_path)
    run([python, "-m", "pip", "uninstall", "-y", "rigidfold"], cwd=tmp_path, env=clean_env())
    gone = subprocess.run([python, "-c", "import rigidfold"], cwd=tmp_path / "elsewhere", env=clean_env(),
                          capture_output=True, text=True)
    assert gone.returncode != 0, "rigidfold still importable after pip uninstall"

    pytest.importorskip("build", reason="python3-build (scripts/bootstrap.sh) builds the wheel")
    run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(tmp_path / "dist"), str(src)],
        cwd=tmp_path, env=clean_env())
    wheels = glob.glob(str(tmp_path / "dist" / "rigidfold-*.whl"))
    assert len(wheels) == 1, wheels
    assert re.search(r"rigidfold-" + re.escape(rigidfold.__version__) + r"-cp\d+-cp\d+-linux_x86_64\.whl$", wheels[0]), wheels
    run([python, "-m", "pip", "install", wheels[0]], cwd=tmp_path, env=clean_env())
    check_installed(python, tmp_path)
