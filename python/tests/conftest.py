"""Shared paths for the rigidfold Python tests (run by CTest as Python.Pytest, or by hand:
PYTHONPATH=build/python /usr/bin/python3 -m pytest -q python/tests)."""
import json
import os
import subprocess

import pytest

import rigidfold

SOURCE_DIR = os.environ.get("RIGIDFOLD_SOURCE_DIR") or os.path.abspath(
    os.path.join(os.path.dirname(__file__), "..", ".."))
BUNDLED = os.path.join(SOURCE_DIR, "data", "bundled")
EXAMPLES = os.path.join(SOURCE_DIR, "python", "examples")


def cli_path():
    """The rigidfold CLI of the same build as the module (RIGIDFOLD_CLI, or <build>/app/rigidfold)."""
    path = os.environ.get("RIGIDFOLD_CLI")
    if not path:
        build = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(rigidfold.__file__))))
        path = os.path.join(build, "app", "rigidfold")
    return path


@pytest.fixture
def cli():
    path = cli_path()
    if not os.access(path, os.X_OK):
        pytest.fail(f"the rigidfold CLI is not built at {path} (set RIGIDFOLD_CLI)")

    def run_json(*args):
        """The CLI's JSON without its "provenance" (the version and the command line, which a
        Python call does not have), after checking that the provenance names this command."""
        out = subprocess.run([path, *args, "--json"], check=True, capture_output=True, text=True).stdout
        doc = json.loads(out)
        provenance = doc.pop("provenance")
        assert provenance["rigidfold_version"] == rigidfold.__version__
        assert provenance["arguments"] == [*args, "--json"]
        return doc

    return run_json


def bundled(name):
    return os.path.join(BUNDLED, name)
