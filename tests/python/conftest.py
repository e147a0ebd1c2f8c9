"""Fixtures of the celform module's tests: the module, the built `celform` program to compare
with, the bundled samples, and the shared meshes (tests needing them skip when ../shared is absent).

Run by ctest (label python) with PYTHONPATH set to the built module; by hand:
    PYTHONPATH=build/release/python /usr/bin/python3 -m pytest tests/python
"""
import os
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

SOURCE = Path(os.environ.get("CELFORM_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SAMPLES = SOURCE / "resources" / "samples"


@pytest.fixture(scope="session")
def celform():
    import celform as module
    return module


@pytest.fixture(scope="session")
def cli():
    """The `celform` program of the same build."""
    path = os.environ.get("CELFORM_CLI") or str(SOURCE / "build" / "release" / "app" / "celform")
    if not os.access(path, os.X_OK):
        pytest.skip(f"the celform program is not built at {path}")
    return path


@pytest.fixture(scope="session")
def samples():
    return SAMPLES


@pytest.fixture(scope="session")
def shared_data():
    path = Path(os.environ.get("CELFORM_SHARED_DATA_DIR") or SOURCE.parent / "shared" / "data")
    if not (path / "meshes").is_dir():
        pytest.skip(f"the shared meshes and drawings are absent ({path})")
    return path


@pytest.fixture
def plain(tmp_path):
    """A copy of the sample with the model and its drawings, nothing else."""
    target = tmp_path / "plain.celform"
    target.write_bytes((SAMPLES / "elephant-plain.celform").read_bytes())
    return target


@pytest.fixture
def showcase(tmp_path):
    """A copy of the showcase sample: two keys, a turntable, subdivision 2."""
    target = tmp_path / "elephant.celform"
    target.write_bytes((SAMPLES / "elephant.celform").read_bytes())
    return target


def run_cli(cli, *args, check=True):
    """Runs `celform ARGS...`; returns the completed process (text output)."""
    result = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"celform {' '.join(map(str, args))}: {result.returncode}\n{result.stderr}")
    return result


def read_png(path):
    """An 8-bit RGB or RGBA, non-interlaced PNG as an H x W x C uint8 array (what the renderer writes)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and interlace == 0 and colour in (2, 6)
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    out = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 0xFF
        out[y] = cur
        prev = cur
    return out.astype(np.uint8).reshape(height, width, channels)
