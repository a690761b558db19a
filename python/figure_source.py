"""Every figure names its input: a small grey line at the foot of the figure
with the files it was drawn from and the rigidfold version that wrote them where known.

Used by the python/plot_*.py scripts: ``stamp_inputs(fig, [path, ...], version=None)`` before
``fig.savefig``. Paths are shown relative to the working directory when below it.
"""
import os


def _shown(path):
    path = os.fspath(path)
    rel = os.path.relpath(path) if os.path.isabs(path) else path
    return path if rel.startswith("..") else rel


def version_of(document):
    """The "rigidfold_version" (and commit) in the provenance of a JSON output the script has
    already loaded (a dict), or None."""
    p = document.get("provenance", {}) if isinstance(document, dict) else {}
    if "rigidfold_version" not in p:
        return None
    return f"rigidfold {p['rigidfold_version']} ({p.get('rigidfold_commit', '?')})"


def stamp_inputs(fig, paths, version=None):
    shown = [_shown(p) for p in paths]
    if len(shown) > 3:  # many trace files: name the first ones and where the rest are
        folders = sorted({os.path.dirname(p) or "." for p in shown[2:]})
        shown = shown[:2] + [f"and {len(paths) - 2} more in {', '.join(folders)}"]
    text = ("" if not version else f"{version}  |  ") + "input: " + ", ".join(shown)
    fig.text(0.005, 0.003, text, fontsize=6, color="0.45", ha="left", va="bottom")
