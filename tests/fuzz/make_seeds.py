#!/usr/bin/env python3
"""Writes the hand-made seeds of tests/data/fuzz-corpus: small meshes (PLY ASCII and binary, OFF,
OBJ, STL, glTF, GLB), PSD drawings, an SVG, the option-parser inputs and the command lines of
cli-process. The other seeds come
from the commands listed in tests/data/fuzz-corpus/README.md (oiiotool for PNG/JPEG/TIFF/EXR,
Assimp's exporter for FBX, `celform` for projects).
Usage: tests/fuzz/make_seeds.py [CORPUS_DIR]   (default: tests/data/fuzz-corpus)"""
import base64
import json
import os
import struct
import sys

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "data", "fuzz-corpus")

# A unit cube: 8 corners, 6 quads (counter-clockwise from outside).
V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
Q = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
T = [t for q in Q for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def write(kind, name, data):
    os.makedirs(os.path.join(out, kind), exist_ok=True)
    with open(os.path.join(out, kind, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# --- PLY ---
def ply_header(fmt, extra_vertex=(), face_list="uchar int", more=""):
    props = "".join(f"property {t} {n}\n" for t, n in [("float", "x"), ("float", "y"), ("float", "z"), *extra_vertex])
    return (f"ply\nformat {fmt} 1.0\ncomment made by make_seeds.py\nelement vertex {len(V)}\n{props}"
            f"element face {len(Q)}\nproperty list {face_list} vertex_indices\n{more}end_header\n")


write("ply", "cube_ascii.ply", ply_header("ascii", [("uchar", "red"), ("uchar", "green"), ("uchar", "blue")])
      + "".join(f"{x} {y} {z} 200 100 50\n" for x, y, z in V) + "".join(f"4 {' '.join(map(str, q))}\n" for q in Q))
write("ply", "tris_ascii.ply", ply_header("ascii", [("float", "nx"), ("float", "ny"), ("float", "nz")],
                                         "uint8 int32").replace(f"face {len(Q)}", f"face {len(T)}")
      + "".join(f"{x} {y} {z} 0 0 1\n" for x, y, z in V) + "".join(f"3 {a} {b} {c}\n" for a, b, c in T))
for endian, tag in (("<", "binary_little_endian"), (">", "binary_big_endian")):
    body = b"".join(struct.pack(endian + "3f", *v) for v in V)
    body += b"".join(struct.pack(endian + "B4i", 4, *q) for q in Q)
    write("ply", f"cube_{tag}.ply", ply_header(tag).encode() + body)
# Doubles, ushort list counts and an extra element after the faces.
body = b"".join(struct.pack("<3d", *v) for v in V) + b"".join(struct.pack("<H3I", 3, *t) for t in T)
body += struct.pack("<2i", 0, 1)
write("ply", "tris_double_edges.ply",
      ply_header("binary_little_endian", face_list="ushort uint", more="element edge 1\nproperty int v1\nproperty int v2\n")
      .replace("float x\nproperty float y\nproperty float z", "double x\nproperty double y\nproperty double z")
      .replace(f"face {len(Q)}", f"face {len(T)}").encode() + body)

# --- OFF ---
write("off", "cube.off", f"OFF\n# a cube\n{len(V)} {len(Q)} 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in V)
      + "".join(f"4 {' '.join(map(str, q))}\n" for q in Q))
write("off", "tris_colour.off", f"COFF\n{len(V)} {len(T)} 18\n" + "".join(f"{x}.0 {y}e0 {z} 255 0 0 255\n" for x, y, z in V)
      + "".join(f"3 {a} {b} {c} 0.5 0.5 0.5\n" for a, b, c in T))
write("off", "one_line.off", "OFF 4 1 0 0 0 0 1 0 0 0 1 0 0 0 1 3 0 1 2\n")

# --- OBJ ---
obj = ["# a cube", "mtllib cube.mtl", "o cube", "g sides"]
obj += [f"v {x} {y} {z}" for x, y, z in V]
obj += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 0 1", "usemtl red", "s 1"]
obj += ["f " + " ".join(f"{i + 1}/{k + 1}/1" for k, i in enumerate(q)) for q in Q[:3]]
obj += ["usemtl blue"] + ["f " + " ".join(f"{i - 8}/{k - 4}" for k, i in enumerate(q)) for q in Q[3:]]
write("obj", "cube.obj", "\n".join(obj) + "\n")
write("obj", "tris.obj", "".join(f"v {x} {y} {z}\n" for x, y, z in V) + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in T))
write("obj", "cube.mtl_as_obj.obj", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\nmap_Kd tex.png\n" + "\n".join(obj) + "\n")

# --- STL ---
def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


stl = ["solid cube"]
for t in T:
    a, b, c = (V[i] for i in t)
    stl += [f"  facet normal {' '.join(map(str, normal(a, b, c)))}", "    outer loop"]
    stl += [f"      vertex {x} {y} {z}" for x, y, z in (a, b, c)] + ["    endloop", "  endfacet"]
write("stl", "cube_ascii.stl", "\n".join(stl + ["endsolid cube"]) + "\n")
body = b"binary STL seed".ljust(80, b" ") + struct.pack("<I", len(T))
for t in T:
    a, b, c = (V[i] for i in t)
    body += struct.pack("<12fH", *normal(a, b, c), *a, *b, *c, 0)
write("stl", "cube_binary.stl", body)

# --- glTF / GLB: the cube as two meshes under a node hierarchy, with two materials ---
positions = b"".join(struct.pack("<3f", *v) for v in V)
indices = b"".join(struct.pack("<3H", *t) for t in T)
buffer = positions + indices


def gltf(uri):
    return {
        "asset": {"version": "2.0", "generator": "make_seeds.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"children": [1, 2], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1]},
                  {"mesh": 0, "translation": [0, 1, 0], "rotation": [0, 0, 0, 1], "scale": [1, 2, 1]},
                  {"mesh": 1}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "material": 1, "mode": 4}]}],
        "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
                      {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1]}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5123, "count": 18, "type": "SCALAR"},
            {"bufferView": 1, "byteOffset": 36, "componentType": 5123, "count": 18, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices), "target": 34963}],
        "buffers": [{"byteLength": len(buffer), **({"uri": uri} if uri else {})}],
    }


write("gltf", "cube.gltf", json.dumps(gltf("data:application/octet-stream;base64," + base64.b64encode(buffer).decode()), indent=1))
doc = json.dumps(gltf(None)).encode()
doc += b" " * (-len(doc) % 4)
binary = buffer + b"\0" * (-len(buffer) % 4)
glb = struct.pack("<I4s", len(doc), b"JSON") + doc + struct.pack("<I4s", len(binary), b"BIN\0") + binary
write("glb", "cube.glb", struct.pack("<4sII", b"glTF", 2, 12 + len(glb)) + glb)

# --- PSD: 8x8 RGB, raw and PackBits (RLE) image data ---
def psd(channels, compression):
    w = h = 8
    head = struct.pack(">4sH6xHIIHH", b"8BPS", 1, channels, h, w, 8, 3)
    planes = [bytes(((x * 32 + c * 80) & 255) for y in range(h) for x in range(w)) for c in range(channels)]
    if compression == 0:
        data = struct.pack(">H", 0) + b"".join(planes)
    else:
        rows, counts = [], []
        for p in planes:
            for y in range(h):
                row = p[y * w:(y + 1) * w]
                packed = bytes([w - 1]) + row  # one literal run
                rows.append(packed)
                counts.append(len(packed))
        data = struct.pack(">H", 1) + b"".join(struct.pack(">H", n) for n in counts) + b"".join(rows)
    return head + struct.pack(">I", 0) + struct.pack(">I", 0) + struct.pack(">I", 0) + data


write("psd", "rgb_raw.psd", psd(3, 0))
write("psd", "rgba_rle.psd", psd(4, 1))

# --- SVG: shapes, a gradient, text, a transform, use/defs ---
write("svg", "shapes.svg", """<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 120 80" width="120" height="80">
 <defs><linearGradient id="g"><stop offset="0" stop-color="#f00"/><stop offset="1" stop-color="blue" stop-opacity="0.5"/></linearGradient>
  <path id="p" d="M10 10 C 20 0, 40 0, 50 10 S 80 20, 90 10 Q 100 30 110 10 A 5 5 0 1 1 60 60 Z"/></defs>
 <rect x="1" y="1" width="118" height="78" rx="4" fill="url(#g)" stroke="black" stroke-width="2" stroke-dasharray="4 2"/>
 <g transform="translate(10,20) rotate(15) scale(0.8)"><circle cx="20" cy="20" r="15" fill="none" stroke="#333"/>
  <ellipse cx="50" cy="20" rx="10" ry="5"/><polyline points="0,0 10,10 20,0"/><polygon points="60,0 70,10 80,0" fill-rule="evenodd"/></g>
 <use xlink:href="#p" x="2" y="2" opacity="0.7"/>
 <text x="10" y="70" font-family="sans-serif" font-size="12">Celform <tspan fill="red">fuzz</tspan></text>
</svg>
""")

# --- option parsers: the first byte picks the parser (fuzz_inputs.cpp, optionParsers()) ---
options = [b"1,2", b"0.5,-1,2e3", b"1,2,3,0.25", b"0.25,1e30", b" 42.5 ", b"-3.5e2", b"17", b"-120", b"-5-30",
           b"640x480", b"on", b"1e3,2,-3", b"0,0,1", b"0.3,1,0", b"directional:1,1,1", b"gooch",
           b"--view\x000,1,0"]
for i, text in enumerate(options):
    write("cli-options", f"parser{i:02d}", bytes([i]) + text)
write("cli-options", "camera", bytes([len(options) - 1]) + b"--eye\x000,0,5\x00--target\x000,0,0\x00--up\x000,1,0")
write("cli-options", "point_light", bytes([14]) + b"point:1,2,3")

# --- command lines run in a child (fuzz_cli_process; tests/fuzz/cli_process.cpp) ---
# Literal ones: "celform", then an argument a line, run in a work folder that holds p.celform (an
# octahedron with the key k1 and the patch "top"), d.celform (the same with the drawing "drawing"
# linked to k1), base.obj, key.obj, drawing.png and text.svg. Each sub-command once, small sizes
# (each seed runs in the replay of every build), and the cases of issue 27 (SVG text without a
# display, a full disk, a NaN camera).
commands = {
    "camera_start_angle_huge": "camera p.celform --turntable 8 --start-angle 1e308",
    "camera_key": "camera p.celform --key 3 --view 0,1,1",
    "new_svg_text": "new base.obj --out out.celform --drawing text.svg",
    "info_json": "info d.celform --json",
    "key_add_svg_text": "key add p.celform --name k2 --from-base --view 1,0,0 --drawing text.svg",
    "key_set": "key set p.celform --key k1 --mesh key.obj --frame 5",
    "brush_mirror": "brush p.celform --key k1 --vertex 0 --radius 1 --drag 0.1,0 --mirror x",
    "eval_out": "eval p.celform --view 0,0,1 --out out.obj",
    "set_look": "set p.celform --sharpness 100 --style gooch --light directional:1,1,1",
    "render_frames": "render p.celform --size 16x16 --frames 0-2 --out out_####.png --skip-existing",
    "highlight_add": "highlight p.celform --add h1 --patch top --op translate:0.1,0",
    "patch_sphere": "patch p.celform --add p2 --sphere 0,0,1,1",
    "analyze_csv": "analyze p.celform --size 16x16 --view 0,0,1 --frames 0-1 --csv out.csv",
    "analyze_csv_full_disk": "analyze p.celform --size 16x16 --frames 0-1 --csv /dev/full",
    "curvature": "curvature p.celform --out out.ply",
    "optimize_light": "optimize-light p.celform --size 16x16 --iterations 2 --dry-run",
    "offsets_auto": "offsets p.celform --auto --size 16x16",
    "outline": "outline d.celform --drawing drawing --out out.svg",
    "fit": "fit d.celform --key k1 --camera --iterations 2",
    "export_pc2": "export p.celform --format pc2 --frames 0-3 --out out.pc2",
    "export_glb": "export p.celform --format glb --out out.glb",
}
for name, line in commands.items():
    write("cli-process", name, "celform\n" + "\n".join(line.split(" ")) + "\n")
# Choices: the first byte picks the sub-command (modulo the table's size), the rest walks its
# synopsis. Zeros give the first synopsis line with no optional part, first alternatives and the
# value 0; the others are a few mixed walks. Few, as libFuzzer runs every seed before it mutates
# (CI gives the target 6 s).
write("cli-process", "choices_zeros", bytes(17))
for i, rest in enumerate([b"\x05\x01\x03\x02\x07\x01\x00\x11", b"\x42\x01\x01\x0c\x02\x06\x09\x01\x21",
                          b"\x10\x02\x00\x01\x1d\x01\x04\x02\x01\x03\x01"]):
    write("cli-process", f"choices_mixed{i}", bytes([3 + 5 * i]) + rest)
