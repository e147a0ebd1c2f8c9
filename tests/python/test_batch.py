"""docs/python.md's batch: every project of a folder rendered, as `celform render` renders each."""
from pathlib import Path

from conftest import run_cli


def render_folder(celform, folder: Path, out: Path, size=(96, 54)):
    """Renders frame 0 of every project in folder to out/NAME.png; returns the files written."""
    written = []
    for project in sorted(folder.glob("*.celform")):
        doc = celform.open(project)
        target = out / (project.stem + ".png")
        doc.render(size=size, out=target)
        written.append(target)
    return written


def test_batch_render_matches_command_line(celform, cli, samples, tmp_path):
    (tmp_path / "py").mkdir()
    written = render_folder(celform, samples, tmp_path / "py")
    assert len(written) == len(list(samples.glob("*.celform"))) >= 3
    for image in written:
        project = samples / (image.stem + ".celform")
        run_cli(cli, "render", project, "--size", "96x54", "--out", tmp_path / "cli.png")
        assert image.read_bytes() == (tmp_path / "cli.png").read_bytes(), image.name
