"""Reads the binary PLY that `lungar-bake export` writes (float x y z dx dy dz, mm, LPS; triangles), for the
scripts beside it (plot-motion, ply-shares). Uses Debian's python3-numpy."""
import sys

import numpy as np


def read_export(path, tool):
    """(vertices N x 6 float64: x y z dx dy dz, triangles M x 3 int32); exits with one line naming `tool`, the file
    and what was expected when the file is not a whole export."""
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline()
            if not line:
                sys.exit(f"{tool}: {path}: header: expected 'end_header'")
            header.append(line.decode("ascii", "replace").strip())
            if header[-1] == "end_header":
                break
        if "format binary_little_endian 1.0" not in header:
            sys.exit(f"{tool}: {path}: format: expected binary_little_endian 1.0 (lungar-bake export)")
        count = {h.split()[1]: int(h.split()[2]) for h in header if h.startswith("element ")}
        props = [h.split()[-1] for h in header if h.startswith("property float")]
        if props[:6] != ["x", "y", "z", "dx", "dy", "dz"]:
            sys.exit(f"{tool}: {path}: vertex properties: expected x y z dx dy dz, got {' '.join(props)}")
        nv, nf = count.get("vertex", 0), count.get("face", 0)
        vertices = np.frombuffer(f.read(4 * len(props) * nv), dtype="<f4")
        faces = np.frombuffer(f.read(13 * nf), dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]))
        if vertices.size != len(props) * nv or faces.size != nf or np.any(faces["n"] != 3):
            sys.exit(f"{tool}: {path}: body: expected {nv} vertices and {nf} triangles, the file is cut short")
        return vertices.reshape(nv, len(props))[:, :6].astype(np.float64), faces["i"]
