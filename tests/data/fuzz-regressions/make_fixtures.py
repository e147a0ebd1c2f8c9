#!/usr/bin/env python3
"""Writes the handcrafted files of tests/data/fuzz-regressions (see README.md there).

Each file is the smallest input that triggered one defect found while hardening the loaders; the
tests load every file of project/ and image/ and expect a one-line refusal naming it, quickly and
without a large allocation. Run from anywhere: python3 make_fixtures.py (it writes beside itself).
"""
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
MAGIC = b"\x89CELF\r\n\x1a"
END_MAGIC = b"CELFEND\n"
INT32_MAX = 2**31 - 1


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png(width, height, bit_depth, colour_type, raw_rows):
    """A PNG whose IHDR states width x height; raw_rows is what its IDAT holds (may be too little)."""
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(raw_rows, 9))
            + png_chunk(b"IEND", b""))


def jpeg(width, height):
    """A greyscale baseline JPEG stating width x height whose scan stops after four bytes.

    Both Huffman tables hold one code of one bit (DC difference 0, end of block), so libjpeg's
    zero padding after the premature end decodes as flat blocks: the whole image is produced."""
    def segment(marker, payload):
        return b"\xff" + bytes([marker]) + struct.pack(">H", len(payload) + 2) + payload
    dqt = segment(0xDB, b"\x00" + b"\x01" * 64)
    sof = segment(0xC0, struct.pack(">BHHB", 8, height, width, 1) + b"\x01\x11\x00")
    one_code = bytes([1] + [0] * 15) + b"\x00"  # one code of length 1, for symbol 0
    dht = segment(0xC4, b"\x00" + one_code + b"\x10" + one_code)
    sos = segment(0xDA, b"\x01\x01\x00\x00\x3f\x00")
    return b"\xff\xd8" + dqt + sof + dht + sos + b"\x00\x00\x00\x00" + b"\xff\xd9"


class Project:
    """A minimal valid project (a tetrahedron), with its manifest open to edits before writing."""

    def __init__(self):
        self.blocks = []  # (name, bytes)
        vertices = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
        faces = struct.pack("<12i", 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3)
        self.add("mesh/vertices", vertices)
        self.add("mesh/faces", faces)
        self.manifest = {
            "format_version": 1,
            "generator": "make_fixtures.py",
            "base_mesh": {"name": "tetrahedron", "vertex_count": 4, "face_count": 4, "vertices": "mesh/vertices",
                          "faces": "mesh/faces", "materials": [], "face_sets": []},
            "drawings": [],
            "keys": [],
            "blend": {"sharpness": 1, "unspecified": "dummy", "time": "natural"},
            "look": {"style": "toon", "light": {"type": "directional", "vector": [0, 0, 1]},
                     "background": [1, 1, 1], "lines": True},
            "next_id": 10,
        }

    def add(self, name, data):
        self.blocks.append((name, data))
        return name

    def write(self, path, manifest_offset=None):
        out = bytearray(MAGIC + struct.pack("<II", 1, 0))
        table = {}
        for name, data in self.blocks:
            out += b"\0" * ((8 - len(out) % 8) % 8)
            table[name] = {"offset": len(out), "size": len(data), "crc32": zlib.crc32(data)}
            out += data
        self.manifest["chunks"] = table
        json_bytes = json.dumps(self.manifest, separators=(",", ":")).encode()
        offset = len(out)
        out += json_bytes
        trailer_offset = offset if manifest_offset is None else manifest_offset
        out += struct.pack("<QQII", trailer_offset, len(json_bytes), zlib.crc32(json_bytes), 0) + END_MAGIC
        with open(path, "wb") as f:
            f.write(out)


def project_fixtures(folder):
    # Defect 1: offset + size wraps past 2^64 to a small number, so the old bounds check passed.
    p = Project()
    p.write(os.path.join(folder, "trailer-offset-wraps-2pow64.celform"), manifest_offset=2**64 - 64)

    # Defect 2: counts far beyond their data blocks, allocated before the block was checked.
    p = Project()
    p.manifest["base_mesh"]["vertex_count"] = INT32_MAX
    p.write(os.path.join(folder, "vertex-count-int32-max.celform"))

    p = Project()
    p.manifest["base_mesh"]["face_count"] = INT32_MAX
    p.write(os.path.join(folder, "face-count-int32-max.celform"))

    p = Project()
    p.manifest["base_mesh"]["uv_count"] = INT32_MAX
    p.manifest["base_mesh"]["uvs"] = p.add("mesh/uvs", struct.pack("<8f", 0, 0, 1, 0, 0, 1, 1, 1))
    p.manifest["base_mesh"]["uv_faces"] = p.add("mesh/uv_faces", struct.pack("<12i", *([0] * 12)))
    p.write(os.path.join(folder, "uv-count-int32-max.celform"))

    p = Project()
    p.manifest["base_mesh"]["face_sets"] = [
        {"name": "patch", "count": INT32_MAX, "faces": p.add("mesh/face_sets/0", struct.pack("<2i", 0, 1))}]
    p.write(os.path.join(folder, "face-set-count-int32-max.celform"))

    p = Project()
    camera = {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "projection": "perspective",
              "fov_y_degrees": 30, "ortho_height": 2}
    p.manifest["keys"] = [{
        "id": 2, "name": "front", "direction": [0, 0, 1], "camera": camera, "drawings": [], "enabled": True,
        "frames": [{"frame": 0, "count": INT32_MAX, "indices": p.add("keys/2/frames/0/indices", struct.pack("<I", 1)),
                    "offsets": p.add("keys/2/frames/0/offsets", struct.pack("<3f", 0, 0, 0.1))}]}]
    p.write(os.path.join(folder, "key-offset-count-int32-max.celform"))

    # Defect 3 inside a project: an embedded drawing whose header states 11585 x 11585 pixels.
    p = Project()
    p.manifest["drawings"] = [{
        "id": 1, "name": "bomb", "format": "png", "image": p.add("drawings/1/image", png_bomb()),
        "camera": camera, "aligned": False, "opacity": 0.5, "frame": 0}]
    p.write(os.path.join(folder, "drawing-png-11585x11585.celform"))


def png_bomb():
    # 11585 x 11585 RGB is 402 MB of pixels (1.7 GB in the old decoder's float buffer) from 69 bytes.
    return png(11585, 11585, 8, 2, b"\0" * 64)


def tiff(width, height, strip):
    """A little-endian greyscale TIFF stating width x height, uncompressed, in one strip of the bytes given."""
    entries = [(256, 4, width), (257, 4, height), (258, 3, 8), (259, 3, 1), (262, 3, 1), (273, 4, 0),
               (277, 3, 1), (278, 4, height), (279, 4, len(strip))]
    ifd_size = 2 + 12 * len(entries) + 4
    data_offset = 8 + ifd_size
    out = b"II*\0" + struct.pack("<I", 8) + struct.pack("<H", len(entries))
    for tag, kind, value in entries:
        value = data_offset if tag == 273 else value
        packed = struct.pack("<HH", value, 0) if kind == 3 else struct.pack("<I", value)
        out += struct.pack("<HHI", tag, kind, 1) + packed
    return out + struct.pack("<I", 0) + strip


def image_fixtures(folder):
    with open(os.path.join(folder, "png-11585x11585-69-bytes.png"), "wb") as f:
        f.write(png_bomb())
    # A valid 40000 x 1 greyscale line: every pixel is there, but it is wider than kMaxImageSide.
    with open(os.path.join(folder, "png-40000x1-wider-than-limit.png"), "wb") as f:
        f.write(png(40000, 1, 1, 0, b"\0" + b"\xff" * 5000))
    with open(os.path.join(folder, "jpeg-11585x11585-short-scan.jpg"), "wb") as f:
        f.write(jpeg(11585, 11585))
    # A format image_io.cpp reads no header of: OpenImageIO's header is checked in the module.
    with open(os.path.join(folder, "tiff-11585x11585-16-byte-strip.tif"), "wb") as f:
        f.write(tiff(11585, 11585, b"\0" * 16))
    # A plausible size (1000 x 1000) with too little data: libpng printed "libpng error: Not enough
    # image data" on standard error, beside the one-line message.
    with open(os.path.join(folder, "png-1000x1000-libpng-error-line.png"), "wb") as f:
        f.write(png(1000, 1000, 8, 0, b"\0" * 64))


def glb_json_chunk_3_3_gb():
    """91 bytes: a GLB header whose JSON chunk states 3.2e9 bytes. Assimp allocated and zeroed all of
    them (3.3 GB, 12 s) before it found the file too short."""
    body = b'{"asset":{"version":"2.0"}}' + b" " * 44
    return b"glTF" + struct.pack("<II", 2, 12 + 8 + len(body)) + struct.pack("<I", 3200000000) + b"JSON" + body


def gltf_nested_nodes(depth):
    """A glTF scene whose nodes nest depth deep (each the only child of the one before): Assimp walks
    them recursively and overflows the stack (SIGSEGV) near 20,000."""
    nodes = ",".join('{"children":[%d]}' % (i + 1) for i in range(depth - 1)) + ",{}"
    return ('{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[%s]}\n' % nodes).encode()


def dae_comment_in_index_list():
    """A valid one-triangle COLLADA file, but for a comment line inside its <p> index list: Assimp's
    index loop stops advancing at the first character that is not a digit and appends for ever
    (3 GB in 15 s, until memory runs out)."""
    return b"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
<library_geometries><geometry id="g" name="g"><mesh>
<source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>
<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2
// one triangle
</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
</library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def mesh_fixtures(folder):
    # Inputs that crash, exhaust or hang Assimp. importMesh() reads
    # them in a child process (celform/model/io/import_process.h); the parent refuses them in one line.
    # (The other files of mesh/ were written by hand.)
    with open(os.path.join(folder, "glb-91-bytes-json-chunk-3.2-gb.glb"), "wb") as f:
        f.write(glb_json_chunk_3_3_gb())
    with open(os.path.join(folder, "gltf-30000-nested-nodes-stack-overflow.gltf"), "wb") as f:
        f.write(gltf_nested_nodes(30000))
    with open(os.path.join(folder, "dae-comment-in-index-list-endless-loop.dae"), "wb") as f:
        f.write(dae_comment_in_index_list())


def cli_fixtures(folder):
    with open(os.path.join(folder, "tetrahedron.off"), "w") as f:
        f.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")


if __name__ == "__main__":
    project_fixtures(os.path.join(HERE, "project"))
    image_fixtures(os.path.join(HERE, "image"))
    mesh_fixtures(os.path.join(HERE, "mesh"))
    cli_fixtures(os.path.join(HERE, "cli"))
