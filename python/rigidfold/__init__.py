"""rigidfold: exact kinematics of rigid origami (Python bindings of the C++ kernel).

Set-up from the project root, after building: ``PYTHONPATH=build/python /usr/bin/python3``.

Units and signs are the kernel's: fold angles and sector angles in radians, FOLD sign
(valley > 0, mountain < 0, 0 flat); lengths in the pattern file's units. Dict keys ending in
``_deg`` (in the objects ``check`` returns, which are the CLI's JSON) are degrees.

Patterns:   load (.fold, .svg, .opx), parse_fold, save, svg_text, dxf_text, CreasePattern (.vertices, .edges, .assignments, .faces,
            .fold_angles), bundled_examples, miura_ori, miura_fold_angles, square_twist,
            waterbomb_base, corrugated_unit
Analysis:   check, trace, enumerate_assignments, assignment_branches
Sweeps:     rigidfold.sweep (many tasks on Dask distributed: python3 -m rigidfold.sweep SPEC.json --out R.jsonl)
Any pattern: repair (least vertex move to rigid foldability), add_creases (fewest added face
            diagonals), nearest_closed_state (closed state nearest to target angles)
Vertex:     flat_fold_angles, flat_fold_multipliers, miura_vertex
Closure:    ClosureSystem, closure_jacobian
Energy:     stable_states (crease springs on any pattern, no symmetry imposed)
Thick:      ThickVertex, thick_bennett_vertex, thick_myard_vertex, thick_diamond_vertex,
            thick_waterbomb_vertex (seed 003 ch. 4)
Design:     waterbomb_bistability, string_pattern, string_forward, design_string_from_curve,
            sorce_vertex, sorce_circular_vertex (seed 002 rolling joints),
            square_twist_unit, square_twist_height_stationary_points (seed 003 metamaterial)
Commands:   network, metamaterial (the dicts `rigidfold network --json` and
            `rigidfold metamaterial --json` print, without "provenance")
Version:    __version__ (the CLI's provenance "rigidfold_version"), __commit__
Errors:     InputError (a ValueError; the message names the file and the place in it, e.place
            the place alone), NoAnswerError (a RuntimeError; e.residual)
Figures:    rigidfold.plot (matplotlib)
"""

from rigidfold._core import (
    __commit__,
    __version__,
    add_creases,
    bundled_examples,
    check,
    ClosureSystem,
    corrugated_unit,
    CreasePattern,
    design_string_from_curve,
    dxf_text,
    assignment_branches,
    enumerate_assignments,
    flat_fold_angles,
    flat_fold_multipliers,
    InputError,
    load,
    metamaterial,
    miura_fold_angles,
    miura_ori,
    miura_vertex,
    nearest_closed_state,
    network,
    NoAnswerError,
    parse_fold,
    repair,
    save,
    sorce_circular_vertex,
    sorce_vertex,
    square_twist,
    square_twist_height_stationary_points,
    square_twist_unit,
    stable_states,
    string_forward,
    string_pattern,
    svg_text,
    thick_bennett_vertex,
    thick_diamond_vertex,
    thick_myard_vertex,
    thick_waterbomb_vertex,
    ThickVertex,
    trace,
    waterbomb_base,
    waterbomb_bistability,
)


def closure_jacobian(pattern, fold_angles, fixed=()):
    """Residual and exact Jacobian of the pattern's loop-closure system at per-edge fold angles.

    fold_angles: (E,) radians, FOLD sign (entries of edges that are not free creases are ignored).
    fixed: [(edge, radians)] creases held at a value (they are then not unknowns).
    Returns (residual (rows,) radians, jacobian scipy.sparse.csc_matrix (rows, unknowns),
    free_edges: the edge of each Jacobian column). Needs scipy.
    """
    system = ClosureSystem(pattern, list(fixed))
    x = system.unknowns_from_edges(fold_angles)
    residual, jacobian = system.evaluate(x)
    return residual, jacobian, system.free_edges


def __getattr__(name):
    # rigidfold.sweep (a callable module) is imported on first use: it needs Dask only then, and
    # `python3 -m rigidfold.sweep` must find it not yet imported.
    if name == "sweep":
        import importlib
        return importlib.import_module("rigidfold.sweep")
    raise AttributeError(f"module 'rigidfold' has no attribute {name!r}")


__all__ = [
    "ClosureSystem",
    "CreasePattern",
    "InputError",
    "NoAnswerError",
    "assignment_branches",
    "bundled_examples",
    "check",
    "closure_jacobian",
    "corrugated_unit",
    "design_string_from_curve",
    "enumerate_assignments",
    "flat_fold_angles",
    "flat_fold_multipliers",
    "load",
    "metamaterial",
    "miura_fold_angles",
    "miura_ori",
    "miura_vertex",
    "network",
    "parse_fold",
    "save",
    "square_twist",
    "string_forward",
    "string_pattern",
    "trace",
    "waterbomb_base",
    "waterbomb_bistability",
]
