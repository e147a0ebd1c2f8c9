#!/usr/bin/env python3
"""Writes resources/samples/elephant-trunk.glb: the CGAL elephant (CC0) skinned to two joints, its
trunk swinging down and back up over 48 frames at 24 fps. It is an animated character to try
`celform new elephant-trunk.glb` (or File > New from Mesh) on: a glTF 2.0 skin with inverse bind
matrices, per-vertex joints and weights, and a rotation channel sampled at every frame.

Usage: scripts/make-animated-sample.py [path/to/cgal_elephant.off] [out.glb]
Only the Python standard library is used.
"""
import json
import math
import struct
import sys

MESH = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/meshes/cgal_elephant.off"
OUT = sys.argv[2] if len(sys.argv) > 2 else "resources/samples/elephant-trunk.glb"

FRAMES = 48
FPS = 24.0
PIVOT = (0.2, 0.25, 0.12)  # the trunk's root, where it leaves the head
SWING_DEGREES = -70.0  # about +z: the tip goes forward (+x) and down, then back
BLEND_FROM, BLEND_TO = 0.2, 0.34  # heights over which a vertex passes from the body to the trunk


def read_off(path):
    """Vertices and triangles of an OFF file (polygons fanned into triangles)."""
    with open(path) as f:
        words = f.read().split()
    if not words or words[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    triangles = []
    for _ in range(nf):
        k = int(words[at])
        poly = [int(w) for w in words[at + 1:at + 1 + k]]
        at += 1 + k
        for i in range(1, k - 1):
            triangles.append((poly[0], poly[i], poly[i + 1]))
    return vertices, triangles


def trunk_weight(v):
    """Smoothstep of the height between BLEND_FROM and BLEND_TO: 0 on the body, 1 on the trunk."""
    t = min(1.0, max(0.0, (v[1] - BLEND_FROM) / (BLEND_TO - BLEND_FROM)))
    return t * t * (3.0 - 2.0 * t)


def quaternion_z(degrees):
    half = math.radians(degrees) / 2.0
    return (0.0, 0.0, math.sin(half), math.cos(half))  # glTF order: x, y, z, w


def main():
    vertices, triangles = read_off(MESH)
    chunks = bytearray()
    views, accessors = [], []

    def add(data, target=None):
        while len(chunks) % 4:
            chunks.append(0)
        view = {"buffer": 0, "byteOffset": len(chunks), "byteLength": len(data)}
        if target:
            view["target"] = target
        chunks.extend(data)
        views.append(view)
        return len(views) - 1

    def accessor(view, component, count, kind, **extra):
        accessors.append(dict(bufferView=view, componentType=component, count=count, type=kind, **extra))
        return len(accessors) - 1

    FLOAT, USHORT, UINT = 5126, 5123, 5125
    ARRAY, ELEMENTS = 34962, 34963

    positions = b"".join(struct.pack("<3f", *v) for v in vertices)
    mins = [min(v[i] for v in vertices) for i in range(3)]
    maxs = [max(v[i] for v in vertices) for i in range(3)]
    position = accessor(add(positions, ARRAY), FLOAT, len(vertices), "VEC3", min=mins, max=maxs)
    indices = accessor(add(b"".join(struct.pack("<3I", *t) for t in triangles), ELEMENTS), UINT,
                       3 * len(triangles), "SCALAR")
    # Joint 0 is the body (the root), joint 1 the trunk. A vertex on one joint only names it once,
    # and unused influences are joint 0 with weight 0 (the validator's rule).
    influences = []
    for v in vertices:
        w = trunk_weight(v)
        if w <= 0.0:
            influences.append(((0, 0, 0, 0), (1.0, 0.0, 0.0, 0.0)))
        elif w >= 1.0:
            influences.append(((1, 0, 0, 0), (1.0, 0.0, 0.0, 0.0)))
        else:
            influences.append(((0, 1, 0, 0), (1.0 - w, w, 0.0, 0.0)))
    joints = accessor(add(b"".join(struct.pack("<4H", *j) for j, _ in influences), ARRAY), USHORT,
                      len(vertices), "VEC4")
    skin_weights = accessor(add(b"".join(struct.pack("<4f", *w) for _, w in influences), ARRAY), FLOAT,
                            len(vertices), "VEC4")
    # Column-major 4x4: the root at the origin, the trunk joint at the pivot.
    identity = [1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0]
    to_pivot = identity[:12] + [-PIVOT[0], -PIVOT[1], -PIVOT[2], 1.0]
    inverse_binds = accessor(add(struct.pack("<32f", *identity, *to_pivot)), FLOAT, 2, "MAT4")

    times = [f / FPS for f in range(FRAMES)]
    angles = [SWING_DEGREES * 0.5 * (1.0 - math.cos(2.0 * math.pi * f / (FRAMES - 1))) for f in range(FRAMES)]
    time_accessor = accessor(add(struct.pack(f"<{FRAMES}f", *times)), FLOAT, FRAMES, "SCALAR",
                             min=[times[0]], max=[times[-1]])
    rotations = accessor(add(b"".join(struct.pack("<4f", *quaternion_z(a)) for a in angles)), FLOAT, FRAMES,
                         "VEC4")

    doc = {
        "asset": {"version": "2.0", "generator": "Celform scripts/make-animated-sample.py",
                  "copyright": "CGAL elephant, CC0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "elephant", "mesh": 0, "skin": 0},
            {"name": "body", "children": [2]},
            {"name": "trunk", "translation": list(PIVOT)},
        ],
        "meshes": [{"name": "elephant", "primitives": [{
            "attributes": {"POSITION": position, "JOINTS_0": joints, "WEIGHTS_0": skin_weights},
            "indices": indices, "mode": 4}]}],
        "skins": [{"name": "trunk swing", "joints": [1, 2], "skeleton": 1, "inverseBindMatrices": inverse_binds}],
        "animations": [{"name": "swing",
                        "samplers": [{"input": time_accessor, "output": rotations, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]}],
        "buffers": [{"byteLength": 0}],
        "bufferViews": views,
        "accessors": accessors,
    }
    while len(chunks) % 4:
        chunks.append(0)
    doc["buffers"][0]["byteLength"] = len(chunks)
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(chunks))
    glb += struct.pack("<I4s", len(text), b"JSON") + text
    glb += struct.pack("<I4s", len(chunks), b"BIN\0") + bytes(chunks)
    with open(OUT, "wb") as f:
        f.write(glb)
    print(f"wrote {OUT} ({len(vertices)} vertices, {len(triangles)} triangles, {FRAMES} frames at {FPS:g} fps)")


if __name__ == "__main__":
    main()
