// validate_gltf.js: runs the Khronos glTF validator (npm's gltf-validator) on .glb files and fails
// on any error. usage: NODE_PATH=DIR/node_modules node validate_gltf.js FILE.glb...
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function main() {
  let failed = 0;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      externalResourceFunction: () => Promise.reject(new Error('no external resources')),
    });
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const m of issues.messages.slice(0, 10))
      if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code}: ${m.message} (${m.pointer || ''})`);
    if (issues.numErrors > 0) failed++;
  }
  process.exit(failed ? 1 : 0);
}
main().catch((e) => { console.error(e); process.exit(2); });
