"""Long calls report progress to a callback, which can stop them; celform.run() and the analyses."""
import json

import pytest

from conftest import run_cli


def test_render_progress_and_cancel(celform, showcase, tmp_path):
    doc = celform.open(showcase)
    seen = []
    result = doc.render(frames=(0, 5), size=(32, 32), threads=1, out=tmp_path / "a_#.png",
                        progress=lambda done, total, label: seen.append((done, total)))
    assert not result["cancelled"] and len(result["written"]) == 6
    assert seen[-1] == (6, 6)

    def stop_after_two(done, total, label):
        return done < 2

    result = doc.render(frames=(0, 9), size=(32, 32), threads=1, out=tmp_path / "b_#.png", progress=stop_after_two)
    assert result["cancelled"]
    assert 2 <= len(result["written"]) < 10
    assert len(list(tmp_path.glob("b_*.png"))) == len(result["written"])


def test_progress_exception_propagates(celform, showcase, tmp_path):
    doc = celform.open(showcase)

    class Stop(Exception):
        pass

    def boom(done, total, label):
        raise Stop("from the callback")

    with pytest.raises(Stop):
        doc.export("pc2", tmp_path / "x.pc2", progress=boom)
    assert not (tmp_path / "x.pc2").exists()  # a one-file export leaves nothing when stopped


def test_export_matches_command_line(celform, cli, showcase, tmp_path):
    doc = celform.open(showcase)
    ours = doc.export("pc2", tmp_path / "p.pc2", frames=(0, 9))
    theirs = json.loads(run_cli(cli, "export", showcase, "--format", "pc2", "--frames", "0-9",
                                "--out", tmp_path / "c.pc2", "--json").stdout)
    assert ours["frames"] == theirs["frames"] == 10 and not ours["cancelled"]
    assert (tmp_path / "p.pc2").read_bytes() == (tmp_path / "c.pc2").read_bytes()


def test_analyze_and_optimize_light(celform, cli, showcase, tmp_path):
    copy = tmp_path / "copy.celform"
    copy.write_bytes(showcase.read_bytes())
    doc = celform.open(showcase)
    ours = doc.analyze(size=(160, 120), frame=3)
    theirs = json.loads(run_cli(cli, "analyze", copy, "--size", "160x120", "--frame", 3, "--json").stdout)
    for key in ("segments", "depth_error"):
        assert ours[key] == theirs[key], key
    before = doc.info()["light"]
    report = doc.optimize_light(size=(160, 120), iterations=3, seed=1)
    assert report["light_before"] == before
    # The light moved in the saved project, and the document was opened again from it.
    assert doc.info()["light"] == report["light_after"] and not doc.modified


def test_unsaved_document_cannot_run_file_commands(celform, samples):
    doc = celform.Document()
    with pytest.raises(celform.UsageError):
        doc.analyze()


def test_run_raises_the_command_line_errors(celform, cli, tmp_path):
    with pytest.raises(celform.UsageError) as raised:
        celform.run("render", tmp_path / "x.celform", size="0x0")
    expected = run_cli(cli, "render", tmp_path / "x.celform", "--size", "0x0", check=False)
    assert expected.returncode == 2
    assert "celform: " + str(raised.value) in expected.stderr
    with pytest.raises(celform.IoError) as raised:
        celform.run("info", tmp_path / "x.celform")
    expected = run_cli(cli, "info", tmp_path / "x.celform", check=False)
    assert expected.returncode == 3 and expected.stderr.strip() == "celform: " + str(raised.value)
    with pytest.raises(celform.UsageError):
        celform.run("no-such-command")


def test_ctrl_c_stops_a_long_render(showcase, tmp_path):
    """Ctrl+C (SIGINT) during a render without a callback stops it with KeyboardInterrupt; the
    frames written stay."""
    import os
    import signal
    import subprocess
    import sys
    import time

    script = tmp_path / "long.py"
    script.write_text(
        "import celform, sys\n"
        f"d = celform.open({str(showcase)!r})\n"
        "print('ready', flush=True)\n"
        "try:\n"
        f"    d.render(frames=(0, 47), size=(1280, 720), threads=1, out={str(tmp_path / 'f_####.png')!r})\n"
        "    print('finished')\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted')\n")
    process = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=os.environ,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert process.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    started = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=60)
    assert out.strip() == "interrupted"
    assert time.monotonic() - started < 5.0
    assert 0 <= len(list(tmp_path.glob("f_*.png"))) < 48


def test_edits_wait_for_a_render_on_another_thread(celform, showcase, tmp_path):
    """A render reads the document with the GIL released: an edit from another thread meanwhile
    is refused, and the render's files are those of the document as it was."""
    import threading

    doc = celform.open(showcase)
    started = threading.Event()
    release = threading.Event()

    def wait_inside(done, total, label):
        started.set()
        release.wait(10)

    worker = threading.Thread(target=lambda: doc.render(frames=(0, 1), size=(32, 32), threads=1,
                                                        out=tmp_path / "t_#.png", progress=wait_inside))
    worker.start()
    assert started.wait(30)
    with pytest.raises(RuntimeError):
        doc.set(style="gooch")
    assert doc.info()["key_viewpoints"]  # reading is fine
    release.set()
    worker.join(30)
    doc.set(style="gooch")  # and editing once the render has returned
    assert len(list(tmp_path.glob("t_*.png"))) == 2
