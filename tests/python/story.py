"""The README's command-line story (scripts/make-sample.sh makes the showcase sample this way),
once as `celform` sub-commands and once as one Python script through the celform module.

Starting from a copy of resources/samples/elephant-plain.celform (the model and its drawings):
two key viewpoints from the model sheet's drawings, Fit to Drawing, a brush stroke, a turntable,
Loop subdivision, four rendered frames, a USD export and the blended mesh at frame 10.
"""
import shutil
import subprocess
from pathlib import Path

SIDE = dict(eye=(0.2476, 0.1357, 2.348), target=(0.001793, 0.012576, 0.01161), up=(0, 1, 0))
FRONT = dict(eye=(2.4115, 0.1436, 0.189), target=(0.067994, 0.020561, -0.016062), up=(0, 1, 0))
OUTPUTS = ["p.celform", "shot_0000.png", "shot_0012.png", "shot_0024.png", "shot_0036.png",
           "shot.usda", "f10.obj"]


def _vec(v):
    return ",".join(repr(x) for x in v)


def run_cli(celform_binary, samples: Path, work: Path):
    """The story as the command line runs it, one process per sub-command."""
    drawings = samples / "drawings"
    shutil.copyfile(samples / "elephant-plain.celform", work / "p.celform")

    def c(*args):
        subprocess.run([str(celform_binary), *map(str, args)], cwd=work, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    for name, cam, drawing in (("side", SIDE, "elephant-sheet-side.png"),
                               ("front", FRONT, "elephant-sheet-front.png")):
        c("key", "add", "p.celform", "--name", name, "--from-base", "--eye", _vec(cam["eye"]),
          "--target", _vec(cam["target"]), "--up", _vec(cam["up"]), "--drawing", drawings / drawing)
    c("fit", "p.celform", "--key", "side", "--camera", "--shape", "--json")
    c("brush", "p.celform", "--key", "side", "--vertex", 691, "--radius", 0.12, "--drag", "0.01,0.01")
    c("camera", "p.celform", "--turntable", 48, "--elevation", 10)
    c("set", "p.celform", "--subdivision", 2)
    c("render", "p.celform", "--frames", "0-47:12", "--size", "240x240", "--out", "shot_####.png")
    c("export", "p.celform", "--format", "usda", "--frames", "0-11", "--out", "shot.usda")
    c("eval", "p.celform", "--frame", 10, "--out", "f10.obj")


def run_python(celform, samples: Path, work: Path):
    """The same story as one Python script (docs/python.md shows it)."""
    drawings = samples / "drawings"
    shutil.copyfile(samples / "elephant-plain.celform", work / "p.celform")
    doc = celform.open(work / "p.celform")
    doc.add_key("side", from_base=True, drawing=drawings / "elephant-sheet-side.png", **SIDE)
    doc.add_key("front", from_base=True, drawing=drawings / "elephant-sheet-front.png", **FRONT)
    doc.save()
    doc.fit(key="side", camera=True, shape=True)   # runs on the saved file, reopens it
    doc.brush("side", vertex=691, radius=0.12, drag=(0.01, 0.01))
    doc.camera(turntable=48, elevation=10)
    doc.set(subdivision=2)
    doc.save()
    doc.render(frames=(0, 47, 12), size=(240, 240), out=work / "shot_####.png")
    doc.export("usda", work / "shot.usda", frames=(0, 11))
    doc.eval(frame=10, out=work / "f10.obj")
    return doc
