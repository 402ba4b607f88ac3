"""A reader of the Gmsh 2.2 ASCII files parasol writes (IMPR_RESU FORMAT='GMSH'), for the
tests: nodes, elements, and every $NodeData / $ElementData block with its tags.

Debian 12's meshio (5.0.0) cannot read a 2.2 file that has $ElementData: its reader splits
the element data by the length of (type, data) tuples, i.e. in pieces of 2 and fails with
"Incompatible cell data". The tests read such files with this module instead (and .vtu files
with meshio).

read(path) -> dict(nodes=(n, 3) array, elements=[(number, gmsh type, [nodes])],
                   node_data=[Block], element_data=[Block])
Block: name, time, step, components, rows {number: [values]}
"""
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Block:
    name: str
    time: float
    step: int
    components: int
    rows: dict = field(default_factory=dict)


def _data_block(lines, i):
    n_strings = int(lines[i]); i += 1
    name = lines[i].strip('"'); i += n_strings
    n_reals = int(lines[i]); i += 1
    time = float(lines[i]) if n_reals else 0.0; i += n_reals
    n_ints = int(lines[i]); i += 1
    step, components, count = (int(x) for x in lines[i:i + 3]); i += n_ints
    rows = {}
    for line in lines[i:i + count]:
        words = line.split()
        rows[int(words[0])] = [float(w) for w in words[1:]]
    return Block(name, time, step, components, rows), i + count


def read(path):
    with open(path) as f:
        lines = f.read().split("\n")
    out = dict(nodes=None, elements=[], node_data=[], element_data=[])
    i = 0
    while i < len(lines):
        line = lines[i]
        if line == "$Nodes":
            n = int(lines[i + 1])
            out["nodes"] = np.array([[float(w) for w in lines[i + 2 + k].split()[1:4]]
                                     for k in range(n)])
            i += n + 2
        elif line == "$Elements":
            n = int(lines[i + 1])
            for k in range(n):
                w = [int(x) for x in lines[i + 2 + k].split()]
                out["elements"].append((w[0], w[1], w[3 + w[2]:]))
            i += n + 2
        elif line in ("$NodeData", "$ElementData"):
            block, i = _data_block(lines, i + 1)
            out["node_data" if line == "$NodeData" else "element_data"].append(block)
        else:
            i += 1
    return out
