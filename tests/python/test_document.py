"""Opening, saving, what a project holds, edits with undo, and errors with the command line's words."""
import json

import numpy as np
import pytest

from conftest import run_cli


def test_info_matches_command_line(celform, cli, showcase):
    doc = celform.open(showcase)
    ours = doc.info()
    theirs = json.loads(run_cli(cli, "info", showcase, "--json").stdout)
    for key in ("format_version", "drawings", "key_viewpoints", "blend", "subdivision", "fps", "frame_range",
                "camera_keys", "light_keys", "current_frame"):
        assert ours[key] == theirs[key], key
    for key in ("vertex_count", "triangle_count", "bounding_box", "centroid"):
        assert ours["base_mesh"][key] == theirs["base_mesh"][key], key
    # And through celform.run, the command line's own code in this process.
    assert celform.run("info", showcase, json=True) == theirs


def test_mesh_arrays_are_views(celform, showcase):
    doc = celform.open(showcase)
    v, f = doc.vertices, doc.faces
    assert v.dtype == np.float32 and v.shape == (doc.info()["base_mesh"]["vertex_count"], 3)
    assert f.dtype == np.int32 and f.shape[1] == 3 and f.max() < v.shape[0]
    assert not v.flags.owndata and not v.flags.writeable
    with pytest.raises(ValueError):
        v[0, 0] = 1.0
    del doc  # the arrays keep the mesh alive
    assert np.isfinite(v).all()


def test_save_open_and_undo(celform, plain, tmp_path):
    doc = celform.open(plain)
    assert doc.keys == [] and not doc.modified
    key = doc.add_key("side", from_base=True, view=(0, 0, 1))
    assert key["name"] == "side" and doc.modified
    doc.set(style="gooch", sharpness=2.5)
    # One undo step per setting, as the command line's `set` makes them.
    assert len(doc.history) == 3
    doc.undo()
    doc.undo()
    assert doc.info()["blend"]["sharpness"] == 1.0 and len(doc.history) == 1
    doc.redo()
    assert doc.info()["blend"]["sharpness"] == 2.5
    out = tmp_path / "copy.celform"
    doc.save(out)
    assert doc.file_path == str(out) and not doc.modified
    again = celform.Document(out)
    assert again.keys == ["side"] and again.info()["blend"]["sharpness"] == 2.5


def test_brush_matches_command_line(celform, cli, showcase, tmp_path):
    copy = tmp_path / "copy.celform"
    copy.write_bytes(showcase.read_bytes())
    theirs = json.loads(run_cli(cli, "brush", copy, "--key", "front", "--vertex", 100, "--radius", 0.2,
                                "--push", "0.02", "--mirror", "auto", "--json").stdout)
    doc = celform.open(showcase)
    ours = doc.brush("front", vertex=100, radius=0.2, push=0.02, mirror="auto")
    assert ours == theirs
    doc.save()
    assert showcase.read_bytes() == copy.read_bytes()


@pytest.mark.parametrize("call, cli_args", [
    (lambda d: d.set(style="bogus"), ["set", "{P}", "--style", "bogus"]),
    (lambda d: d.set(sharpness=0), ["set", "{P}", "--sharpness", "0"]),
    (lambda d: d.render(size=(0, 10)), ["render", "{P}", "--size", "0x10"]),
    (lambda d: d.brush("nope", vertex=1, radius=0.1, push=0.1), ["brush", "{P}", "--key", "nope", "--vertex", "1",
                                                                 "--radius", "0.1", "--push", "0.1"]),
    (lambda d: d.add_key("x", from_base=True, view=(0, 0, 0)), ["key", "add", "{P}", "--name", "x", "--from-base",
                                                               "--view", "0,0,0"]),
    (lambda d: d.export("gltf", "x.pc2"), ["export", "{P}", "--format", "gltf", "--out", "x.pc2"]),
])
def test_errors_carry_command_line_messages(celform, cli, showcase, call, cli_args):
    doc = celform.open(showcase)
    result = run_cli(cli, *[a.replace("{P}", str(showcase)) for a in cli_args], check=False)
    assert result.returncode in (2, 3)
    expected = next(line for line in result.stderr.splitlines() if line.startswith("celform: "))[len("celform: "):]
    error = celform.UsageError if result.returncode == 2 else celform.IoError
    with pytest.raises(error) as raised:
        call(doc)
    assert str(raised.value) == expected
    assert isinstance(raised.value, celform.Error)


def test_missing_project_is_an_io_error(celform, tmp_path):
    with pytest.raises(celform.IoError) as raised:
        celform.open(tmp_path / "none.celform")
    assert isinstance(raised.value, OSError)
    assert "none.celform" in str(raised.value)


def test_new_from_shared_mesh(celform, cli, shared_data, samples, tmp_path):
    mesh = shared_data / "meshes" / "cgal_elephant.off"
    drawing = samples / "drawings" / "elephant-sheet-side.png"
    run_cli(cli, "new", mesh, "--drawing", drawing, "--out", tmp_path / "cli.celform")
    doc = celform.new(mesh, drawings=[drawing])
    doc.save(tmp_path / "py.celform")
    assert (tmp_path / "py.celform").read_bytes() == (tmp_path / "cli.celform").read_bytes()


def test_file_commands_match_command_line(celform, cli, showcase, tmp_path):
    """patch and highlight run the command line's sub-commands on the document's file; keyword
    values such as a list of tuples become repeated options (--sphere X,Y,Z,R --sphere ...)."""
    copy = tmp_path / "copy.celform"
    copy.write_bytes(showcase.read_bytes())
    run_cli(cli, "patch", copy, "--add", "ears", "--sphere", "0.3,0.2,0,0.3", "--sphere", "0.3,0.2,0.1,0.2")
    run_cli(cli, "highlight", copy, "--add", "shine", "--patch", "ears", "--epsilon", "0.1",
            "--op", "rotate:30", "--op", "scale:0.5")
    doc = celform.open(showcase)
    doc.patch(add="ears", sphere=[(0.3, 0.2, 0, 0.3), np.array([0.3, 0.2, 0.1, 0.2])])
    layer = doc.highlight(add="shine", patch="ears", epsilon=0.1, op=["rotate:30", "scale:0.5"])
    assert layer["name"] == "shine" and not doc.modified
    assert showcase.read_bytes() == copy.read_bytes()
    assert [p["name"] for p in doc.patch(list=True)["patches"]] == ["ears"]


def test_any_sub_command_on_the_document(celform, showcase):
    """Document.command runs any sub-command of the table on the document's file, positional
    words before the file (`celform key add P ...`)."""
    doc = celform.open(showcase)
    doc.set(sharpness=3)  # unsaved: saved before the sub-command runs
    made = doc.command("key", "add", name="top", from_base=True, view=(0, 1, 0), json=True)
    assert made["name"] == "top" and doc.keys == ["side", "front", "top"]
    assert doc.info()["blend"]["sharpness"] == 3 and not doc.modified
    assert doc.command("camera", list=True, json=True)["fps"] == doc.info()["fps"]
