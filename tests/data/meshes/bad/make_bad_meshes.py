#!/usr/bin/env python3
"""Writes the small bad Gmsh meshes of this folder (and ../cube_tets.msh, the good base).

Each file breaks one rule; tests/io/test_mesh_check_bad.cpp expects its specific message.
Base mesh: the unit cube split into six tetrahedra along its 000-111 diagonal (Kuhn split),
all twelve boundary triangles in physical surface "wall", the cells in physical volume "fluid".
Run: python3 make_bad_meshes.py  (from this folder)
"""
import itertools
import os

HERE = os.path.dirname(os.path.abspath(__file__))
NODES = [(i, j, k) for k in (0, 1) for j in (0, 1) for i in (0, 1)]  # tags 1..8


def det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def volume(nodes, tet):
    p = [nodes[t - 1] for t in tet]
    return det(*[[p[i][d] - p[0][d] for d in range(3)] for i in (1, 2, 3)]) / 6


def kuhn_tets():
    tets = []
    for perm in itertools.permutations(range(3)):
        p = [0, 0, 0]
        path = [tuple(p)]
        for axis in perm:
            p[axis] = 1
            path.append(tuple(p))
        tet = [NODES.index(q) + 1 for q in path]
        if volume(NODES, tet) < 0:
            tet[1], tet[2] = tet[2], tet[1]
        tets.append(tet)
    return tets


def tet_faces(tet):
    a, b, c, d = tet
    return [(a, c, b), (a, b, d), (a, d, c), (b, c, d)]


def boundary_triangles(tets):
    count = {}
    for t in tets:
        for f in tet_faces(t):
            key = tuple(sorted(f))
            count.setdefault(key, []).append(f)
    return [fs[0] for fs in count.values() if len(fs) == 1], \
           [fs[0] for fs in count.values() if len(fs) == 2]


def write22(name, nodes, elements, names, cut=None):
    """elements: (gmsh type, physical tag, elementary tag, node tags)."""
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(names))]
    lines += [f'{d} {t} "{n}"' for (d, t, n) in names]
    lines += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    lines += [f"{i + 1} {x:.17g} {y:.17g} {z:.17g}" for i, (x, y, z) in enumerate(nodes)]
    lines += ["$EndNodes", "$Elements", str(len(elements))]
    lines += [" ".join(map(str, [i + 1, typ, 2, phys, ent, *tags]))
              for i, (typ, phys, ent, tags) in enumerate(elements)]
    lines += ["$EndElements"]
    text = "\n".join(lines) + "\n"
    if cut is not None:
        text = text[:cut(text)]
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


def write41(name, nodes, tets, triangles, node_tags=None):
    """Format 4.1 ASCII: one volume entity ("fluid") holding every node, one surface ("wall")."""
    n, nt, nf = len(nodes), len(tets), len(triangles)
    node_tags = node_tags or [i + 1 for i in range(n)]
    lines = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$PhysicalNames", "2",
             '2 1 "wall"', '3 2 "fluid"', "$EndPhysicalNames", "$Entities", "0 0 1 1",
             "1 0 0 0 1 1 1 1 1 0", "1 0 0 0 1 1 1 1 2 1 1", "$EndEntities",
             "$Nodes", f"1 {n} 1 {max(node_tags)}", f"3 1 0 {n}"]
    lines += [str(t) for t in node_tags]
    lines += [f"{x:.17g} {y:.17g} {z:.17g}" for (x, y, z) in nodes]
    lines += ["$EndNodes", "$Elements", f"2 {nt + nf} 1 {nt + nf}", f"3 1 4 {nt}"]
    lines += [" ".join(map(str, [i + 1, *t])) for i, t in enumerate(tets)]
    lines += [f"2 1 2 {nf}"]
    lines += [" ".join(map(str, [nt + i + 1, *f])) for i, f in enumerate(triangles)]
    lines += ["$EndElements"]
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(lines) + "\n")


def edit(name, replacements):
    """Replaces text in a written file (each `old` must occur)."""
    path = os.path.join(HERE, name)
    with open(path) as f:
        text = f.read()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    with open(path, "w") as f:
        f.write(text)


NAMES = [(2, 1, "wall"), (3, 2, "fluid")]
TETS = kuhn_tets()
BOUNDARY, INTERIOR = boundary_triangles(TETS)


def cube(tets=TETS, boundary=BOUNDARY, extra=()):
    return [(4, 2, 1, t) for t in tets] + [(2, 1, 2, f) for f in boundary] + list(extra)


def main():
    write22("../cube_tets.msh", NODES, cube(), NAMES)
    # File cut in the middle of the element section.
    write22("truncated.msh", NODES, cube(), NAMES, cut=lambda s: s.index("$Elements") + 40)
    # File cut right after a complete node section: no elements at all.
    write22("cut_after_nodes.msh", NODES, cube(), NAMES,
            cut=lambda s: s.index("$EndNodes") + len("$EndNodes\n"))
    # Element type 99 does not exist in Gmsh.
    write22("unknown_element.msh", NODES, cube(extra=[(99, 2, 1, [1, 2, 3, 4])]), NAMES)
    # A 10-node (second-order) tetrahedron with its edge midpoints.
    corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    edges = [(0, 1), (1, 2), (0, 2), (0, 3), (2, 3), (1, 3)]  # Gmsh tet10 edge order
    mids = [tuple((corners[a][d] + corners[b][d]) / 2 for d in range(3)) for a, b in edges]
    write22("second_order_tet.msh", corners + mids, [(11, 2, 1, list(range(1, 11)))], NAMES)
    # Linear cells but a 6-node (second-order) triangle on the boundary; Gmsh 4.8's 2.2 reader
    # drops that triangle silently, so its three mid-edge nodes are what gets reported.
    nodes = NODES + [(0.5, 0, 0), (0.5, 0.5, 0), (0, 0.5, 0)]
    tri = BOUNDARY[0]
    write22("second_order_face.msh", nodes, cube(extra=[(9, 1, 2, list(tri) + [9, 10, 11])]),
            NAMES)
    # One tetrahedron with two nodes swapped: negative volume.
    bad = [list(t) for t in TETS]
    bad[2][1], bad[2][2] = bad[2][2], bad[2][1]
    write22("inverted_tet.msh", NODES, cube(tets=bad), NAMES)
    # A hexahedron squashed to thickness 1e-14.
    flat = [(x, y, 1e-14 * z) for (x, y, z) in NODES]
    hexa = [1, 2, 4, 3, 5, 6, 8, 7]
    quads = [[1, 3, 4, 2], [5, 6, 8, 7], [1, 2, 6, 5], [2, 4, 8, 6], [4, 3, 7, 8], [3, 1, 5, 7]]
    write22("degenerate_hex.msh", flat, [(5, 2, 1, hexa)] + [(3, 1, 2, q) for q in quads], NAMES)
    # The two triangles of the top face z = 1 are in no physical group.
    top = [f for f in BOUNDARY if all(NODES[n - 1][2] == 1 for n in f)]
    write22("missing_group.msh", NODES, cube(boundary=[f for f in BOUNDARY if f not in top]),
            NAMES)
    # A ninth node that no cell uses (format 4.1: the 2.2 reader of Gmsh drops such nodes).
    write41("unused_node.msh", NODES + [(2, 2, 2)], TETS, BOUNDARY)
    # Two unit cubes 2 m apart: a mesh in two pieces.
    far = [(x + 3, y, z) for (x, y, z) in NODES]
    write41("two_pieces.msh", NODES + far, TETS + [[n + 8 for n in t] for t in TETS],
            BOUNDARY + [[n + 8 for n in f] for f in BOUNDARY])
    # Node tag 8 defined twice (the second at (2, 2, 2)): refused, not one silently winning.
    write41("duplicate_node_tag.msh", NODES + [(2, 2, 2)], TETS, BOUNDARY,
            node_tags=list(range(1, 9)) + [8])
    # A third tetrahedron on an interior face: the face is shared by three cells.
    a, b, c = INTERIOR[0]
    apex = len(NODES) + 1
    third = [a, b, c, apex]
    nodes = NODES + [(3, -1, 2)]
    if volume(nodes, third) < 0:
        third = [a, c, b, apex]
    write22("non_manifold.msh", nodes, cube(tets=TETS + [third]), NAMES)
    # A tagged triangle that is not a face of any tetrahedron.
    all_faces = {tuple(sorted(f)) for t in TETS for f in tet_faces(t)}
    stray = next(f for f in itertools.combinations(range(1, 9), 3) if f not in all_faces)
    write22("stray_face.msh", NODES, cube(extra=[(2, 1, 2, list(stray))]), NAMES)
    # An interior face tagged as boundary.
    write22("interior_face.msh", NODES, cube(extra=[(2, 1, 3, list(INTERIOR[0]))]), NAMES)
    # An element that refers to node 42, which the file does not define.
    write22("undefined_node.msh", NODES, cube(extra=[(4, 2, 1, [1, 2, 3, 42])]), NAMES)
    # Headers that claim 1e15 nodes or elements in a file of a few hundred bytes: Gmsh would
    # allocate for all of them (a bare std::bad_alloc); refused from the file's size.
    huge = "1000000000000000"
    write41("huge_node_count.msh", NODES, TETS, BOUNDARY)
    edit("huge_node_count.msh", [("1 8 1 8\n3 1 0 8\n", f"1 {huge} 1 {huge}\n3 1 0 {huge}\n")])
    write22("huge_element_count.msh", NODES, cube(), NAMES)
    edit("huge_element_count.msh", [("$Elements\n18\n", f"$Elements\n{huge}\n")])
    # Not a mesh at all.
    with open(os.path.join(HERE, "not_a_mesh.msh"), "w") as f:
        f.write("solid cube\n  facet normal 0 0 1\nendsolid cube\n")


if __name__ == "__main__":
    main()
