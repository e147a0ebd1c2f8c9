// Validates a .gltf or .glb file with the Khronos glTF Validator (npm package gltf-validator):
//   node validate_gltf.mjs FILE [PACKAGE_PREFIX]
// PACKAGE_PREFIX is the directory holding node_modules/gltf-validator (npm install --prefix);
// without it, Node's usual lookup. Prints the counts and every error and warning, one a line, and
// exits 1 when the report has errors, 2 when the validator cannot run.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const [file, prefix] = process.argv.slice(2);
if (!file) {
    console.error('usage: node validate_gltf.mjs FILE [PACKAGE_PREFIX]');
    process.exit(2);
}

let validator;
try {
    const base = prefix ? path.join(path.resolve(prefix), 'package.json') : import.meta.url;
    validator = createRequire(base)('gltf-validator');
} catch (e) {
    console.error(`validate_gltf: cannot load gltf-validator: ${e.message}`);
    process.exit(2);
}

const severities = ['error', 'warning', 'info', 'hint'];
try {
    const bytes = new Uint8Array(await readFile(file));
    // No externalResourceFunction: Celform's files embed their buffer (data URI or GLB chunk).
    const report = await validator.validateBytes(bytes, { uri: path.basename(file), maxIssues: 0 });
    const issues = report.issues;
    console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings} infos ${issues.numInfos}`);
    for (const m of issues.messages)
        if (m.severity <= 1)
            console.log(`${severities[m.severity]} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
    process.exit(issues.numErrors > 0 ? 1 : 0);
} catch (e) {
    console.error(`validate_gltf: ${file}: ${e.message ?? e}`);
    process.exit(2);
}
