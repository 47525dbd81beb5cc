// Checks glTF files with the Khronos glTF validator (npm gltf-validator): every file must have 0
// errors and 0 warnings (infos and hints are listed but allowed). Usage: node gltf.mjs FILE.gltf...
// Exit status 1 if any file fails.
import fs from 'fs';
import validator from 'gltf-validator';

let failed = false;
for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), { uri: file, maxIssues: 0 });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  const infos = [...new Set(messages.filter((m) => m.severity >= 2).map((m) => m.code))].join(', ');
  const bad = messages.filter((m) => m.severity < 2);
  if (numErrors || numWarnings) failed = true;
  console.log(`${numErrors || numWarnings ? 'FAIL' : 'ok  '} ${file}: glTF validator ${report.validatorVersion}, ` +
              `${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints` +
              (infos ? ` (${infos})` : ''));
  for (const m of bad.slice(0, 20)) console.log(`  ${m.code} at ${m.pointer}: ${m.message}`);
}
process.exit(failed ? 1 : 0);
