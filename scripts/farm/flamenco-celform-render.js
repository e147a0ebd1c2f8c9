// A Flamenco 3 job type for `celform render` (docs/farm.md): copy this file into the Manager's
// `scripts/` folder. Submitting a "Celform Render" job makes one task per chunk of frames, each
// running celform over its chunk (`--frames A-B`) into one output pattern every worker sees.
//
// Tasks run with --skip-existing, so a task run again keeps the frames already written. Workers
// need no display. The job compiler runs in Flamenco's JavaScript engine (goja); it uses only
// the `author` API and plain ECMAScript.

const JOB_TYPE = {
    label: "Celform Render",
    description: "Renders a Celform project's frames, a chunk of frames a task.",
    settings: [
        {key: "project", type: "string", subtype: "file_path", required: true,
            description: "The project file (.celform), on storage every worker sees."},
        {key: "frames", type: "string", required: true, default: "1-240",
            description: "The frames, A-B inclusive."},
        {key: "chunk_size", type: "int32", default: 10, description: "Frames a task renders."},
        {key: "render_output_path", type: "string", subtype: "file_path", required: true,
            description: "The output pattern; a run of # is the frame number (sh010_####.exr)."},
        {key: "size", type: "string", default: "1920x1080", description: "Image size, WIDTHxHEIGHT."},
        {key: "threads", type: "int32", default: 4, description: "Frames a task renders at once."},
        {key: "celform", type: "string", default: "celform", description: "The celform binary on the workers."},
    ],
};

// "A-B" (negative frames allowed: "-10--1") as [A, B]; throws on anything else.
function parseFrames(text) {
    const m = /^\s*(-?\d+)\s*-\s*(-?\d+)\s*$/.exec(String(text));
    if (!m || Number(m[1]) > Number(m[2]))
        throw "frames must be A-B with A <= B, not " + JSON.stringify(text);
    return [Number(m[1]), Number(m[2])];
}

// The chunks of first-last, chunkSize frames each (the last one shorter), as "A-B" strings.
function celformChunks(first, last, chunkSize) {
    const size = Math.max(1, Math.floor(chunkSize));
    const chunks = [];
    for (let start = first; start <= last; start += size)
        chunks.push(start + "-" + Math.min(last, start + size - 1));
    return chunks;
}

function compileJob(job) {
    const settings = job.settings;
    const range = parseFrames(settings.frames);
    for (const chunk of celformChunks(range[0], range[1], settings.chunk_size)) {
        const task = author.Task("render-" + chunk, "misc");
        task.addCommand(author.Command("exec", {
            exe: settings.celform,
            args: ["render", settings.project, "--frames", chunk, "--out", settings.render_output_path,
                "--size", settings.size, "--threads", String(settings.threads), "--skip-existing"],
        }));
        job.addTask(task);
    }
}
