#!/usr/bin/python3
"""Writes the structured validation beam of validation.md §2 (0.1 x 0.02 x 0.02 m, Kuhn 6-tet
split of nx x ny x nz cells, the same split as src/mesh/box_mesh.cpp) as gmsh 2.2 ASCII.

Used for the bundled scenarios until `mrsim mesh` (issue 3) builds unstructured levels.
Deterministic: the same arguments always give the same file.

    /usr/bin/python3 scripts/make_beam_mesh.py 20 4 4 scenarios/meshes/beam_20x4x4.msh
"""
import sys


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    nx, ny, nz = (int(a) for a in sys.argv[1:4])
    size = (0.1, 0.02, 0.02)
    pid = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    pts = [(size[0] * i / nx, size[1] * j / ny, size[2] * k / nz)
           for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)]
    paths = [(1, 3), (1, 5), (2, 3), (2, 6), (4, 5), (4, 6)]
    tets = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                v = [pid(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)) for c in range(8)]
                for a, b in paths:
                    t = [v[0], v[a], v[b], v[7]]
                    p = [pts[x] for x in t]
                    e = [[p[m][d] - p[0][d] for d in range(3)] for m in (1, 2, 3)]
                    det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1])
                           - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
                           + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
                    if det < 0:
                        t[2], t[3] = t[3], t[2]
                    tets.append(t)
    with open(sys.argv[4], "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(pts))
        for n, p in enumerate(pts):
            f.write("%d %.17g %.17g %.17g\n" % (n + 1, *p))
        f.write("$EndNodes\n$Elements\n%d\n" % len(tets))
        for n, t in enumerate(tets):
            f.write("%d 4 2 1 1 %d %d %d %d\n" % (n + 1, *(x + 1 for x in t)))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
