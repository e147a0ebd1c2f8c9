"""The README's story as one Python script gives the same files, byte for byte, as the command line."""
from pathlib import Path

import story


def test_story_matches_command_line(celform, cli, samples, tmp_path):
    by_cli, by_python = tmp_path / "cli", tmp_path / "python"
    by_cli.mkdir()
    by_python.mkdir()
    story.run_cli(cli, samples, by_cli)
    doc = story.run_python(celform, samples, by_python)
    for name in story.OUTPUTS:
        a, b = (by_cli / name).read_bytes(), (by_python / name).read_bytes()
        assert len(a) > 0, name
        assert a == b, f"{name} differs: {len(a)} bytes from the command line, {len(b)} from Python"
    # The document knows what it did: the story's last edits are its undo steps since the fit
    # reopened the file.
    assert doc.keys == ["side", "front"]
    assert not doc.modified
    assert doc.info()["subdivision"] == 2
