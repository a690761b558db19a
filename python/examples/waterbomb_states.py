#!/usr/bin/env python3
"""Stable states of the bistable n = 4 waterbomb base (seed 004) with springs at rest at 60 deg.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/waterbomb_states.py
"""
import math

import rigidfold


def main():
    r = rigidfold.waterbomb_bistability(n=4, theta0=math.radians(60))
    for e in r["equilibria"]:
        print(f"{e['kind']:>28}: theta {math.degrees(e['theta']):8.3f} deg, energy {e['energy']:.6f}, "
              f"closure residual {e['closure_residual']:.1e} rad, stable {e['stable']}")
    print(f"{len(r['stable_states'])} stable states")


if __name__ == "__main__":
    main()
