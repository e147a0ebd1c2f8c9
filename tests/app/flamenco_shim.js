// Runs a Flamenco job compiler (scripts/farm/flamenco-celform-render.js) under Node with a small
// stand-in for Flamenco's `author` API, and prints the commands its tasks would run as one JSON
// array of argument lists (test_cli_farm).
//
//   node flamenco_shim.js COMPILER.js '{"project": ..., "frames": "0-5", ...}'
"use strict";
const fs = require("fs");
const vm = require("vm");

const [compilerPath, settingsJson] = process.argv.slice(2);
const tasks = [];
const author = {
    Task(name, type) {
        const task = {name, type, commands: []};
        task.addCommand = (command) => task.commands.push(command);
        return task;
    },
    Command(type, parameters) {
        return {type, parameters};
    },
};
const sandbox = {author, console, JSON, Math, Number, String};
vm.createContext(sandbox);
vm.runInContext(fs.readFileSync(compilerPath, "utf8") + "\n;this.JOB_TYPE = JOB_TYPE;", sandbox,
    {filename: compilerPath});

// The job's settings: the defaults of JOB_TYPE, then the given ones; required ones must be given.
const given = JSON.parse(settingsJson);
const settings = {};
for (const s of sandbox.JOB_TYPE.settings) {
    if (s.key in given)
        settings[s.key] = given[s.key];
    else if ("default" in s)
        settings[s.key] = s.default;
    else if (s.required)
        throw new Error("required setting " + s.key + " not given");
}
const job = {settings, addTask: (task) => tasks.push(task)};
sandbox.compileJob(job);

const commands = [];
for (const task of tasks)
    for (const command of task.commands) {
        if (command.type !== "exec")
            throw new Error("task " + task.name + ": command type " + command.type + ", not exec");
        commands.push([command.parameters.exe].concat(command.parameters.args));
    }
console.log(JSON.stringify(commands));
