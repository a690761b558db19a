"""rigidfold.network and rigidfold.metamaterial return the very dicts `rigidfold network --json`
and `rigidfold metamaterial --json` print (one serialiser, report/): compared with the CLI on
the bundled networks and on metamaterial cases of each kind. Keys named "seconds" (wall time)
are left out; everything else must be equal."""
import glob
import json
import os
import subprocess

import pytest

import rigidfold
from conftest import SOURCE_DIR, cli_path

NETWORKS = sorted(glob.glob(os.path.join(SOURCE_DIR, "data", "network", "*.json")))
# The networks whose assembly is a crease pattern (four flat 4R vertices around a flat panel, mobile).
CREASE_PATTERN_NETWORKS = ["a4_R3R13R12.json", "a4_R4R10R16.json", "a4_R4R9R12.json", "eq2-34.json"]


def without_seconds(value):
    if isinstance(value, dict):
        return {k: without_seconds(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_seconds(v) for v in value]
    return value


def cli_failure(*args):
    """Exit status and error line of a CLI run expected to fail."""
    r = subprocess.run([cli_path(), *args], capture_output=True, text=True)
    assert r.returncode != 0, args
    return r.returncode, r.stderr.strip()


def test_every_bundled_network_is_found():
    assert len(NETWORKS) >= 10
    assert all(os.path.basename(p) in map(os.path.basename, NETWORKS) for p in CREASE_PATTERN_NETWORKS)


@pytest.mark.parametrize("path", NETWORKS, ids=os.path.basename)
def test_network_equals_cli_json(cli, path):
    assert rigidfold.network(path) == cli("network", path)


@pytest.mark.parametrize("path", NETWORKS, ids=os.path.basename)
def test_network_trace_equals_cli_json(cli, path):
    expected = None
    try:
        expected = cli("network", path, "--trace", "6")
    except subprocess.CalledProcessError as e:
        assert e.returncode == 3  # no configuration to trace from (eq2-34_perturbed): NoAnswerError
    if expected is None:
        with pytest.raises(rigidfold.NoAnswerError):
            rigidfold.network(path, trace_steps=6)
        return
    got = rigidfold.network(path, trace_steps=6)
    assert "trace" in got
    assert got == expected


@pytest.mark.parametrize("name", CREASE_PATTERN_NETWORKS)
def test_network_crease_pattern_equals_cli_json_and_file(cli, tmp_path, name):
    path = os.path.join(SOURCE_DIR, "data", "network", name)
    out = str(tmp_path / "assembly.fold")
    expected = cli("network", path, "--out", out)
    with open(out) as f:
        cli_fold = f.read()
    os.remove(out)
    assert rigidfold.network(path, out=out) == expected
    with open(out) as f:
        assert f.read() == cli_fold
    assert expected["crease_pattern"]["file"] == out


def test_network_bad_input_names_the_place(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"linkages": [{"name": "A", "twists_deg": [40, "x", 130, 100],
                                             "joints": ["a1", "a2", "a3", "a4"]}]}))
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.network(bad)  # os.PathLike, as the CLI's argument
    assert "linkages[0].twists_deg[1]" in str(e.value)
    status, line = cli_failure("network", str(bad))
    assert status == 2 and line == "rigidfold: error: " + str(e.value)

    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.network(NETWORKS[0], trace_steps=20000)
    assert e.value.place == "trace_steps"
    # A network that is not an assembly of four 4R linkages has no crease pattern: refused as the
    # CLI refuses it (the place is in the network file), nothing written.
    single = os.path.join(SOURCE_DIR, "data", "network", "fig2-1_base.json")
    out = tmp_path / "none.fold"
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.network(single, out=out)
    assert e.value.place == single + ": linkages"
    assert not out.exists()
    status, line = cli_failure("network", single, "--out", str(out))
    assert status == 2 and line == "rigidfold: error: " + str(e.value)


def metamaterial_flags(unit=None, **keywords):
    """The CLI's flags for rigidfold.metamaterial's arguments: each keyword is its flag."""
    flags = ["metamaterial"] + (["--unit", unit] if unit else [])
    for key, value in keywords.items():
        flag = "--" + key.replace("_", "-")
        flags += [flag] if value is True else [flag, str(value)]
    return flags


METAMATERIAL_CASES = [
    dict(unit="square-twist", samples=31),
    dict(unit="element1", samples=31),
    dict(unit="element2", samples=31, alpha_deg=70, beta_deg=70),
    dict(unit="element3", alpha_deg=50, beta_deg=80, l=2, samples=50),
    dict(unit="square-twist", alpha_deg=120, b=1.5, samples=41, cross_check=True, cross_check_steps=12),
    dict(stacked=2, layers=2, stacked_steps=8),
    dict(stacked=4, layers=2, stacked_steps=8, alpha_deg=55),
]


@pytest.mark.parametrize("case", METAMATERIAL_CASES, ids=lambda c: " ".join(metamaterial_flags(**c)[1:]))
def test_metamaterial_equals_cli_json(cli, case):
    expected = cli(*metamaterial_flags(**case))
    got = rigidfold.metamaterial(**case)
    assert without_seconds(got) == without_seconds(expected)
    assert ("cross_check" in got) == bool(case.get("cross_check"))


def test_metamaterial_plot_writes_the_cli_files(cli, tmp_path):
    case = dict(unit="element1", samples=9)
    expected = cli(*metamaterial_flags(**case, plot=tmp_path / "cli"))
    assert rigidfold.metamaterial(**case, plot=tmp_path / "py") == expected
    for name in ("metamaterial.csv", "dimensions.svg", "poisson.svg"):
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text(), name


@pytest.mark.parametrize("keywords, place, message", [
    (dict(unit="square-twist", alpha_deg=80), "alpha_deg", "80.000000 is outside (90, 180) degrees"),
    (dict(unit="element1", a=2), "a", "applies to unit=square-twist, not to the elements"),
    (dict(stacked=1, samples=5), "samples", "does not apply to stacked"),
    (dict(unit="square-twist", stacked=1), "unit", "give either unit or stacked, not both"),
    (dict(), "unit", "is required (or stacked=1..4)"),
    (dict(unit="P"), "unit", None),
])
def test_metamaterial_bad_input_names_the_keyword(tmp_path, keywords, place, message):
    plot = tmp_path / "plot"
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.metamaterial(**keywords, plot=plot)
    assert e.value.place == place
    assert str(e.value).startswith(place + ": ")
    if message:
        assert str(e.value) == place + ": " + message
    assert not plot.exists()
    # The CLI refuses the same request naming the flag (its message names flags where Python names keywords).
    status, line = cli_failure(*metamaterial_flags(**keywords, plot=plot))
    assert status == 2 and line.startswith("rigidfold: error: --" + place.replace("_", "-") + ": "), line
