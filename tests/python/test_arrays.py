"""The blend and renders as numpy arrays: the same numbers as the command line's files."""
import json

import numpy as np
import pytest

from conftest import read_png, run_cli


def read_obj_vertices(path):
    return np.array([[float(x) for x in line.split()[1:4]] for line in open(path) if line.startswith("v ")])


def test_eval_matches_command_line(celform, cli, showcase, tmp_path):
    doc = celform.open(showcase)
    ev = doc.eval(frame=17)
    theirs = json.loads(run_cli(cli, "eval", showcase, "--frame", 17, "--json", "--out", tmp_path / "c.obj").stdout)
    assert ev.json() == theirs
    assert ev.weights == {k["key"]: k["weight"] for k in theirs["keys"]}
    ev.write(tmp_path / "p.obj")
    assert (tmp_path / "p.obj").read_bytes() == (tmp_path / "c.obj").read_bytes()
    shape = ev.shape
    assert shape.dtype == np.float32 and not shape.flags.owndata and not shape.flags.writeable
    np.testing.assert_allclose(shape, read_obj_vertices(tmp_path / "c.obj"), atol=1e-5)
    # The keys move the model away from its base at this view.
    assert np.abs(shape - ev.base).max() > 1e-4
    del ev, doc
    assert np.isfinite(shape).all()  # the array keeps the evaluation alive


def test_eval_by_view(celform, showcase):
    doc = celform.open(showcase)
    front = doc.eval(view=(1, 0, 0))
    assert front.weights["front"] > 0.5
    np.testing.assert_allclose(np.linalg.norm(front.direction), 1.0)


def test_render_array_matches_png(celform, cli, showcase, tmp_path):
    doc = celform.open(showcase)
    run_cli(cli, "render", showcase, "--frame", 5, "--size", "96x64", "--out", tmp_path / "c.png")
    png = read_png(tmp_path / "c.png")
    ours = doc.render(frame=5, size=(96, 64), srgb8=True)
    assert ours.shape == (64, 96, 4) and ours.dtype == np.uint8
    np.testing.assert_array_equal(ours[..., :png.shape[2]], png)
    linear = doc.render(frame=5, size=(96, 64))
    assert linear.dtype == np.float32 and linear.shape == (64, 96, 4)
    assert linear.flags.owndata is False  # the renderer's own buffer, handed over
    # The model on its background: not one colour.
    assert np.ptp(linear[..., :3].reshape(-1, 3), axis=0).max() > 0.2


def test_render_passes(celform, showcase):
    doc = celform.open(showcase)
    passes = doc.render(frame=0, size=(80, 60), passes=True)
    assert set(passes) == {"beauty", "lines", "tone", "highlights", "depth", "normal", "id"}
    assert passes["normal"].shape == (60, 80, 3) and passes["id"].dtype == np.int32
    on_model = passes["id"] >= 0
    assert on_model.any() and np.isinf(passes["depth"][~on_model]).all()
    lines = doc.render(frame=0, size=(80, 60), pass_="lines")
    np.testing.assert_allclose(lines[..., 0], passes["lines"], atol=1e-6)


def test_render_file_matches_command_line(celform, cli, showcase, tmp_path):
    doc = celform.open(showcase)
    result = doc.render(frames=(0, 9, 3), size=(64, 64), out=tmp_path / "py_##.png", threads=2)
    run_cli(cli, "render", showcase, "--frames", "0-9:3", "--size", "64x64", "--out", tmp_path / "c_##.png")
    assert [w["frame"] for w in result["written"]] == [0, 3, 6, 9]
    for f in (0, 3, 6, 9):
        assert (tmp_path / f"py_{f:02d}.png").read_bytes() == (tmp_path / f"c_{f:02d}.png").read_bytes()


def test_look_settings_change_the_render(celform, showcase):
    doc = celform.open(showcase)
    toon = doc.render(frame=0, size=(64, 64))
    doc.set(style="gooch", light="directional:0,1,0")
    gooch = doc.render(frame=0, size=(64, 64))
    assert np.abs(toon - gooch).max() > 0.05
    doc.undo()
    doc.undo()
    np.testing.assert_array_equal(doc.render(frame=0, size=(64, 64)), toon)


@pytest.mark.parametrize("pass_name", ["lines", "tone", "depth", "normal", "id", "segments", "curvature",
                                       "depth-error"])
def test_pass_arrays_match_command_line(celform, cli, showcase, tmp_path, pass_name):
    """Every pass as an array holds the values of `celform render --pass` (the depth analysis's
    pictures included)."""
    doc = celform.open(showcase)
    run_cli(cli, "render", showcase, "--frame", 3, "--size", "80x48", "--pass", pass_name, "--out", tmp_path / "c.png")
    png = read_png(tmp_path / "c.png")
    ours = doc.render(frame=3, size=(80, 48), pass_=pass_name, srgb8=True)
    np.testing.assert_array_equal(ours[..., :png.shape[2]], png)
