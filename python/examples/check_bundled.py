#!/usr/bin/env python3
"""Checks a bundled crease pattern for rigid foldability and prints the verdict.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/check_bundled.py [PATTERN.fold]

Default pattern: data/bundled/corrugated_p_rigid.fold (seed 003's double-corrugated unit P).
"""
import os
import sys

import rigidfold

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT = os.path.join(HERE, "..", "..", "data", "bundled", "corrugated_p_rigid.fold")


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else DEFAULT
    pattern = rigidfold.load(path)
    print(f"{os.path.basename(path)}: {pattern.num_vertices} vertices, {pattern.num_edges} edges, "
          f"{pattern.num_faces} faces; letters {''.join(pattern.assignments)}")
    for use_assignment in (True, False):
        r = rigidfold.check(pattern, use_assignment=use_assignment, source=path)
        how = "with its M-V assignment" if use_assignment else "ignoring the assignment"
        print(f"  {how}: {r['verdict_class']} (model {r['model']}, DOF {r['dof']}, proof {r['is_proof']})")
        print(f"    {r['reason']}")


if __name__ == "__main__":
    main()
