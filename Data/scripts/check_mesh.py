#!/usr/bin/python3
"""Check a triangle mesh stored as PLY (read with VTK's vtkPLYReader).

Usage:
    /usr/bin/python3 check_mesh.py FILE.ply [FILE.ply ...]

Prints, per file: point/triangle counts, unused points, degenerate and
duplicate triangles, interior/boundary/non-manifold edge counts, boundary
loops, non-manifold vertices, whether the orientation is consistent (every
interior edge used once in each direction), the Euler characteristic, and
the signed volume (> 0: outward-facing normals on a closed mesh).

Exit status is 0 when every file has only triangles, consistent orientation
and no non-manifold edges, 1 otherwise. Needs python3-vtk9 (Debian).
Not used at build or test time.
"""

import sys
from collections import defaultdict

import vtk


def read_ply(path):
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPoints() == 0:
        raise RuntimeError(f"{path}: no points read")
    pts = [poly.GetPoint(i) for i in range(poly.GetNumberOfPoints())]
    tris = []
    ids = vtk.vtkIdList()
    polys = poly.GetPolys()
    polys.InitTraversal()
    non_tri = 0
    while polys.GetNextCell(ids):
        if ids.GetNumberOfIds() != 3:
            non_tri += 1
            continue
        tris.append(tuple(ids.GetId(k) for k in range(3)))
    other = (poly.GetNumberOfVerts() + poly.GetNumberOfLines()
             + poly.GetNumberOfStrips())
    return pts, tris, non_tri + other


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def check(path):
    pts, tris, non_tri = read_ply(path)
    n_pts, n_tri = len(pts), len(tris)

    used = set()
    degenerate_idx = degenerate_area = duplicates = 0
    seen = set()
    directed = defaultdict(int)
    min_area, max_area = float("inf"), 0.0
    volume = 0.0
    for a, b, c in tris:
        used.update((a, b, c))
        if a == b or b == c or a == c:
            degenerate_idx += 1
            continue
        n = cross(sub(pts[b], pts[a]), sub(pts[c], pts[a]))
        area = 0.5 * dot(n, n) ** 0.5
        e2 = max(dot(d, d) for d in (sub(pts[b], pts[a]),
                                     sub(pts[c], pts[b]),
                                     sub(pts[a], pts[c])))
        if area <= 1e-12 * e2:
            degenerate_area += 1
        min_area, max_area = min(min_area, area), max(max_area, area)
        volume += dot(pts[a], cross(pts[b], pts[c])) / 6.0
        key = tuple(sorted((a, b, c)))
        if key in seen:
            duplicates += 1
        seen.add(key)
        for u, v in ((a, b), (b, c), (c, a)):
            directed[(u, v)] += 1

    undirected = defaultdict(lambda: [0, 0])
    for (u, v), n in directed.items():
        if u < v:
            undirected[(u, v)][0] += n
        else:
            undirected[(v, u)][1] += n
    interior = boundary = non_manifold = inconsistent = 0
    for f, r in undirected.values():
        if f + r == 1:
            boundary += 1
        elif f + r == 2:
            interior += 1
            if (f, r) != (1, 1):
                inconsistent += 1
        else:
            non_manifold += 1

    # boundary loops: follow directed boundary edges
    bnext = defaultdict(list)
    for (u, v), n in directed.items():
        if n == 1 and (v, u) not in directed:
            bnext[u].append(v)
    loops = 0
    visited = set()
    for start in list(bnext):
        for first in bnext[start]:
            if (start, first) in visited:
                continue
            loops += 1
            u, v = start, first
            while True:
                visited.add((u, v))
                nxt = [w for w in bnext.get(v, []) if (v, w) not in visited]
                if not nxt:
                    break
                u, v = v, nxt[0]

    # non-manifold vertices: the triangles around a vertex must form a
    # single fan (connected through shared edges at that vertex)
    vtris = defaultdict(list)
    for t, (a, b, c) in enumerate(tris):
        if len({a, b, c}) == 3:
            for v in (a, b, c):
                vtris[v].append(t)
    nm_verts = 0
    for v, ts in vtris.items():
        parent = {t: t for t in ts}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        by_other = defaultdict(list)
        for t in ts:
            for w in tris[t]:
                if w != v:
                    by_other[w].append(t)
        for group in by_other.values():
            for t in group[1:]:
                parent[find(t)] = find(group[0])
        if len({find(t) for t in ts}) > 1:
            nm_verts += 1

    consistent = inconsistent == 0 and non_manifold == 0
    ok = consistent and non_tri == 0
    print(f"{path}:")
    print(f"  points: {n_pts} (unused: {n_pts - len(used)})")
    print(f"  triangles: {n_tri} (non-triangle cells: {non_tri})")
    print(f"  edges: {len(undirected)} (interior {interior}, boundary "
          f"{boundary}, non-manifold {non_manifold}); boundary loops: {loops}")
    print(f"  non-manifold vertices: {nm_verts}")
    print(f"  degenerate triangles: {degenerate_idx} repeated index, "
          f"{degenerate_area} ~zero area; duplicates: {duplicates}")
    print(f"  triangle area: min {min_area:.3e}, max {max_area:.3e}")
    print(f"  orientation consistent: {'yes' if consistent else 'NO'} "
          f"({inconsistent} inconsistent interior edges)")
    print(f"  Euler characteristic V-E+F: "
          f"{len(used) - len(undirected) + n_tri}")
    print(f"  signed volume: {volume:.4f}")
    return ok


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    ok = all([check(p) for p in argv[1:]])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
