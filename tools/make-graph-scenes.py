#!/usr/bin/env python3
"""Writes generated graph scenes (docs/scene-graph.md):

  molecule.json   N spheres (default 1,000) smoothly blended: a molecule-like blob
  particles.json  N spheres (default 10,000) in a field: a plain union

A count of 0 skips that file. Deterministic (fixed seeds), so the
repository's copy is what this writes:

  tools/make-graph-scenes.py scenes/
  tools/make-graph-scenes.py out/ --molecule 0 --particles 30000   # tools/graph-figures.sh
"""
import argparse
import json
import math
import os
import random


def molecule(n, rng):
    # Atoms grown as a random walk of bonds, so the blob is one connected body.
    atoms = [(0.0, 0.0, 0.0)]
    while len(atoms) < n:
        x, y, z = atoms[rng.randrange(len(atoms))]
        u, v = rng.uniform(-1, 1), rng.uniform(0, 2 * math.pi)
        s = math.sqrt(1 - u * u)
        d = 0.14
        p = (x + d * s * math.cos(v), y + d * u, z + d * s * math.sin(v))
        if max(abs(c) for c in p) < 1.2:
            atoms.append(p)
    kids = []
    for i, (x, y, z) in enumerate(atoms):
        kids.append({"sdf": "sdSphere", "r": round(rng.uniform(0.05, 0.08), 4),
                     "translate": [round(x, 4), round(y + 1.3, 4), round(z, 4)],
                     **({"material": "accent"} if i % 7 == 0 else {})})
    return {"root": {"op": "opSmoothUnion", "k": 0.04, "material": "ball", "children": kids}}


def particles(n, rng):
    kids = []
    for i in range(n):
        x, y, z = rng.uniform(-3, 3), rng.uniform(0.05, 2.5), rng.uniform(-3, 3)
        kids.append({"sdf": "sdSphere", "r": round(rng.uniform(0.02, 0.05), 4),
                     "translate": [round(x, 4), round(y, 4), round(z, 4)],
                     **({"material": "accent"} if i % 5 == 0 else {})})
    return {"root": {"op": "opUnion", "material": "ball", "children": kids}}


def write(path, graph):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(graph, f, separators=(",", ":"))
        f.write("\n")
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--molecule", type=int, default=1000)
    ap.add_argument("--particles", type=int, default=10000)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.molecule:
        write(os.path.join(a.out, "molecule.json"), molecule(a.molecule, random.Random(1)))
    if a.particles:
        write(os.path.join(a.out, "particles.json"), particles(a.particles, random.Random(2)))


if __name__ == "__main__":
    main()
