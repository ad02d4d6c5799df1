#!/usr/bin/env python3
"""Writes the seeds of fuzz/corpus/mesh_from_scene/: scenes in the byte layout documented at the top
of fuzz/mesh_from_scene.cpp, each reversed (FuzzedDataProvider takes its integers from the end).
Usage: fuzz/mesh_from_scene_seeds.py fuzz/corpus/mesh_from_scene"""
import os
import sys

NAN = 0      # float code: NaN
IDENTITY = [0]
NORMAL_PNG = [1, 3]  # material: a normal texture named texture_names[3] ("normal.png")
QUAD_P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
QUAD_UV = [(0, 0), (1, 0), (1, 1), (0, 1)]
TWO_TRIANGLES = [(0, [0, 1, 2]), (0, [0, 2, 3])]  # (size code, indices); size code 0: a triangle


def grid(*values):
    """Float codes of values on the grid k/4 - 2, k = 0..16."""
    codes = []
    for v in values:
        k = round((v + 2) * 4)
        assert 0 <= k <= 16 and k / 4 - 2 == v
        codes.append(32 + k)
    return codes


def quad(attributes=2 | 4, positions=None, faces=TWO_TRIANGLES, material=0):
    """A unit quad; attributes as the harness reads them (bit 0 none, 1 normals, 2 UVs, 4 tangents, 5 bitangents)."""
    codes = [attributes, 4]
    if not attributes & 1:
        codes += positions or sum((grid(*p) for p in QUAD_P), [])
    if attributes & 2:
        codes += grid(0, 0, 1) * 4
    if attributes & 4:
        codes += sum((grid(*uv) for uv in QUAD_UV), [])
    if attributes & 16:
        codes += grid(1, 0, 0) * 4
    if attributes & 32:
        codes += grid(0, 1, 0) * 4
    codes.append(len(faces))
    for size, indices in faces:
        codes += [size] + indices
    return codes + [material]


def node(transform, meshes, parent=None):
    return ([] if parent is None else [parent]) + transform + [len(meshes)] + meshes


def scene(flags, meshes, materials, textures, nodes):
    codes = [flags, len(meshes)] + sum(meshes, []) + [len(materials)] + sum(materials, [])
    return codes + [len(textures)] + sum(textures, []) + [len(nodes) - 1] + sum(nodes, [])


# 33 extra nodes in a binary tree over 64 meshes, every transform code in turn.
TRANSFORMS = [IDENTITY, IDENTITY, [2, 1], [3], [4] + grid(1, 2, 0.5), [5] + grid(0, 0, 1), [6, 1, 2], [7] + grid(*[1, 0, 0, 0] * 4)]
MANY_NODES = [node(IDENTITY, [0, 1, 2, 3])] + [
    node(TRANSFORMS[i % 8], [(4 + 2 * i) % 64, (5 + 2 * i) % 64], parent=i // 2) for i in range(33)]

SEEDS = {
    'quad-normal-map': scene(0, [quad()], [NORMAL_PNG], [], [node(IDENTITY, [0])]),
    'quad-mirrored-instances': scene(0, [quad()], [NORMAL_PNG], [], [
        node(IDENTITY, []), node([2, 0], [0], 0), node([3], [0], 0), node([5] + grid(2, 0, 0), [0], 1),
        node([6, 1, 2], [0], 2)]),
    'quad-no-normals-no-uvs-box': scene(2, [quad(0, faces=[(3, [0, 1, 2, 3])])], [], [], [node(IDENTITY, [0])]),
    'quad-no-uvs-refused': scene(0, [quad(2)], [], [], [node(IDENTITY, [0])]),
    'quad-flat-sphere-mikk': scene(1 | 4 | 8, [quad(0)], [], [], [node([4] + grid(1, -1, 0.5), [0])]),
    'quad-nan-position': scene(0, [quad(positions=[NAN] * 3 + sum((grid(*p) for p in QUAD_P[1:]), []))], [], [],
                               [node(IDENTITY, [0])]),
    'quad-bad-index': scene(0, [quad(faces=[(0, [0, 1, 2]), (0, [0, 0xff, 5, 3])])], [], [], [node(IDENTITY, [0])]),
    'quad-points-lines-degenerate': scene(0, [quad(faces=[(0, [0, 1, 2]), (0, [0, 0, 3]), (4, [1]), (5, [2, 3]), (6, [])])],
                                          [], [], [node(IDENTITY, [0])]),
    'quad-embedded-png': scene(0, [quad()], [[1, 0]], [[0, 3, 8, 0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]],
                               [node(IDENTITY, [0])]),
    'quad-embedded-raw-bump': scene(0, [quad()], [[2, 1]], [[1, 3, 0, 0, 1, 2, 3, 4], [1, 0, 1, 1] + [128] * 16],
                                    [node(IDENTITY, [0])]),
    'quad-file-tangents': scene(0, [quad(2 | 4 | 16 | 32)], [], [], [node(IDENTITY, [0])]),
    'quad-zero-scale-node': scene(0, [quad()], [], [], [node([4] + grid(0, 1, 1), [0])]),
    'null-mesh-and-material': scene(0, [[0xff], quad(material=1)], [NORMAL_PNG, [0xff, 0]], [],
                                    [node(IDENTITY, [1, 0, 0xff, 3])]),
    'many-meshes': scene(0, [quad(material=i % 6) for i in range(64)], [NORMAL_PNG, [2, 4], [3, 6], [0xff, 0]], [], MANY_NODES),
    'no-root': scene(16, [quad()], [], [], [node(IDENTITY, [0])]),
}

if __name__ == '__main__':
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, codes in SEEDS.items():
        assert all(0 <= c < 256 for c in codes), name
        with open(os.path.join(out, name), 'wb') as f:
            f.write(bytes(reversed(codes)))
