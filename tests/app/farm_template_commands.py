#!/usr/bin/python3
"""The commands a farm would run for one of the templates in scripts/farm (test_cli_farm).

    farm_template_commands.py openjd TEMPLATE.yaml NAME=VALUE...   (job parameters)
    farm_template_commands.py opencue SPEC.xml PLACEHOLDER=VALUE...

Checks the template's syntax and structure with a real parser (PyYAML, ElementTree), expands its
frame chunks as the scheduler would, and prints one JSON array of commands (argument lists),
one per task, in order. Exits 1 with a message on anything malformed.
"""
import json
import re
import shlex
import sys
import xml.etree.ElementTree as ElementTree

import yaml


def fail(message):
    print("farm_template_commands: " + message, file=sys.stderr)
    sys.exit(1)


def frame_range(text):
    m = re.fullmatch(r"\s*(-?\d+)\s*-\s*(-?\d+)\s*", text)
    if not m or int(m.group(1)) > int(m.group(2)):
        fail("not a frame range A-B: %r" % text)
    return int(m.group(1)), int(m.group(2))


def chunks(first, last, size):
    """Contiguous chunks of size frames, the last one shorter, as (start, end)."""
    return [(s, min(last, s + size - 1)) for s in range(first, last + 1, size)]


def openjd(path, values):
    with open(path, encoding="utf-8") as f:
        template = yaml.safe_load(f)
    if template.get("specificationVersion") != "jobtemplate-2023-09":
        fail("specificationVersion is not jobtemplate-2023-09")
    if "TASK_CHUNKING" not in template.get("extensions", []):
        fail("CHUNK[INT] needs the TASK_CHUNKING extension")
    params = {}
    for p in template["parameterDefinitions"]:
        if p["type"] not in ("STRING", "INT", "FLOAT", "PATH"):
            fail("parameter %s has type %s" % (p["name"], p["type"]))
        if p["name"] in params:
            fail("parameter %s twice" % p["name"])
        params[p["name"]] = str(values.get(p["name"], p.get("default", "")))
        if p["name"] not in values and "default" not in p:
            fail("no value for parameter %s" % p["name"])
    unknown = set(values) - set(params)
    if unknown:
        fail("unknown parameters %s" % sorted(unknown))

    def expand(text, task=None):
        def one(m):
            name = m.group(1).strip()
            if name.startswith("Param.") and name[6:] in params:
                return params[name[6:]]
            if task is not None and name.startswith("Task.Param.") and name[11:] in task:
                return task[name[11:]]
            fail("unresolved {{%s}}" % name)
        return re.sub(r"\{\{([^}]*)\}\}", one, str(text))

    commands = []
    for step in template["steps"]:
        definitions = step["parameterSpace"]["taskParameterDefinitions"]
        if len(definitions) != 1 or definitions[0]["type"] != "CHUNK[INT]":
            fail("step %s: one CHUNK[INT] task parameter expected" % step["name"])
        d = definitions[0]
        if d["chunks"]["rangeConstraint"] != "CONTIGUOUS":
            fail("step %s: chunks are not CONTIGUOUS" % step["name"])
        first, last = frame_range(expand(d["range"]))
        size = int(expand(d["chunks"]["defaultTaskCount"]))
        run = step["script"]["actions"]["onRun"]
        for start, end in chunks(first, last, size):
            task = {d["name"]: "%d-%d" % (start, end)}  # CONTIGUOUS: always START-END
            commands.append([expand(run["command"], task)] + [expand(a, task) for a in run.get("args", [])])
    return commands


def opencue(path, values):
    spec = ElementTree.parse(path).getroot()
    if spec.tag != "spec":
        fail("the root is not <spec>")
    order = [e.tag for e in spec]
    for tag in ("show", "shot", "user", "job"):
        if tag not in order:
            fail("<spec> has no <%s>" % tag)
    commands = []
    for layer in spec.iter("layer"):
        tags = [e.tag for e in layer]
        if tags[:3] != ["cmd", "range", "chunk"]:
            fail("a <layer> starts with %s, not cmd, range, chunk" % tags[:3])

        def text(tag):
            t = layer.find(tag).text
            for k, v in values.items():
                t = t.replace(k, v)
            if "CELFORM_" in t:
                fail("placeholder left in <%s>: %s" % (tag, t))
            return t

        first, last = frame_range(text("range"))
        size = int(text("chunk"))
        for start, end in chunks(first, last, size):
            # As the OpenCue versions of its issue 1129: #FRAME_END# of the last chunk past the
            # range; the command must clamp it.
            end = start + size - 1
            cmd = text("cmd").replace("#FRAME_START#", str(start)).replace("#FRAME_END#", str(end))
            commands.append(shlex.split(cmd))
    return commands


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("openjd", "opencue"):
        fail("usage: farm_template_commands.py openjd|opencue TEMPLATE NAME=VALUE...")
    values = dict(a.split("=", 1) for a in sys.argv[3:])
    commands = (openjd if sys.argv[1] == "openjd" else opencue)(sys.argv[2], values)
    print(json.dumps(commands))


main()
