// Runs the Khronos glTF validator (npm gltf-validator) on one .glb and prints
// its report as JSON on stdout: what the interop test reads.
//   node validate_gltf.cjs VALIDATOR_DIR FILE.glb
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, file] = process.argv.slice(2);
if (!validatorDir || !file) {
  console.error('usage: node validate_gltf.cjs VALIDATOR_DIR FILE.glb');
  process.exit(2);
}
const validator = require(path.resolve(validatorDir));
validator
  .validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 50,
    externalResourceFunction: () => Promise.reject(new Error('a .glb must not refer to other files')),
  })
  .then((report) => {
    process.stdout.write(JSON.stringify(report));
  })
  .catch((error) => {
    console.error(`validator failed: ${error}`);
    process.exit(1);
  });
