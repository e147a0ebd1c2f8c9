// Reads a USD file (.usda, .usdc, .usdz) with TinyUSDZ (npm package tinyusdz, its WebAssembly
// build) and reports what it found:
//   node read_usd.mjs FILE [PACKAGE_PREFIX]
// PACKAGE_PREFIX is the directory holding node_modules/tinyusdz (npm install --prefix). Prints
// `errors N meshes M` then, per mesh, its path and counts, and the reader's messages; exits 1 when
// the file does not load, 2 when the reader cannot run.
//
// The package is an Emscripten build for browsers only: its module throws on Node unless the
// process looks like a browser's (Electron's renderer reports process.type "renderer"), and it
// fetches tinyusdz.wasm over HTTP unless handed the bytes (Module.wasmBinary). This shim does
// both; its loader class (TinyUSDZLoader.js, which needs three.js) is not used.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [file, prefix] = process.argv.slice(2);
if (!file) {
    console.error('usage: node read_usd.mjs FILE [PACKAGE_PREFIX]');
    process.exit(2);
}

let native;
try {
    const dir = path.join(path.resolve(prefix ?? '.'), 'node_modules', 'tinyusdz');
    globalThis.window = globalThis;
    process.type = 'renderer';
    const init = (await import(pathToFileURL(path.join(dir, 'tinyusdz.js')).href)).default;
    native = await init({
        wasmBinary: await readFile(path.join(dir, 'tinyusdz.wasm')),
        print: (s) => console.log(`tinyusdz: ${s}`),
        printErr: (s) => console.log(`tinyusdz: ${s}`),
    });
} catch (e) {
    console.error(`read_usd: cannot load tinyusdz: ${e.message ?? e}`);
    process.exit(2);
}

try {
    const usd = new native.TinyUSDZLoaderNative();
    const ok = usd.loadFromBinary(new Uint8Array(await readFile(file)), path.basename(file));
    if (!ok) {
        console.log(`errors 1 meshes 0`);
        console.log(`error ${usd.error()}`);
        process.exit(1);
    }
    const meshes = usd.numMeshes();
    console.log(`errors 0 meshes ${meshes}`);
    for (let i = 0; i < meshes; ++i) {
        const m = usd.getMesh(i);
        console.log(`mesh ${m.absPath} faceVertexIndices ${m.faceVertexIndices?.length ?? 0} ` +
            `points ${m.points?.length ?? 0} normals ${m.normals?.length ?? 0}`);
    }
    const warning = usd.warn ? usd.warn() : '';
    if (warning)
        console.log(`warning ${warning}`);
    process.exit(0);
} catch (e) {
    console.error(`read_usd: ${file}: ${e.message ?? e}`);
    process.exit(2);
}
