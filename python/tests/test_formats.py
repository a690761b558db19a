"""svg_text / dxf_text: the texts `rigidfold export` writes; an SVG read back gives the pattern."""
import subprocess

import pytest

import rigidfold
from conftest import bundled, cli_path


@pytest.mark.parametrize("name", ["miura_4x4_alpha60.fold", "square_twist_30_type2m.fold", "miura_12x12_folded.fold"])
def test_svg_text_equals_the_cli_export_and_reads_back(tmp_path, name):
    path = bundled(name)
    pattern = rigidfold.load(path)
    text = rigidfold.svg_text(pattern, source=path)
    out = tmp_path / "p.svg"
    subprocess.run([cli_path(), "export", path, "--svg", str(out)], check=True, capture_output=True)
    assert out.read_text() == text
    back = rigidfold.load(str(out))
    assert len(back.edges) == len(pattern.edges)
    assert sorted(back.assignments) == sorted(pattern.assignments)
    if pattern.coords_2d:  # a 2D pattern's coordinates come back bit for bit (as a set)
        assert sorted(map(tuple, back.vertices[:, :2])) == sorted(map(tuple, pattern.vertices[:, :2]))


def test_dxf_text_has_one_line_per_edge():
    pattern = rigidfold.load(bundled("miura_4x4_alpha60.fold"))
    pairs = rigidfold.dxf_text(pattern).splitlines()
    entities = [pairs[i + 1].strip() for i in range(0, len(pairs) - 1, 2) if pairs[i].strip() == "0"]
    assert entities.count("LINE") == len(pattern.edges)


def test_a_tube_has_no_flat_crease_pattern():
    with pytest.raises(rigidfold.InputError):
        rigidfold.svg_text(rigidfold.load(bundled("miura_tube_6_alpha60.fold")))
