#!/usr/bin/env node
// Validates glTF files with Khronos' glTF Validator (the npm package gltf-validator, installed by
// scripts/install-gltf-tools.sh; NODE_PATH names its node_modules: scripts/gltf-tools/location.sh).
// Prints one line per file, "FILE: E errors, W warnings, I infos, H hints", then each error and
// warning as "  SEVERITY CODE POINTER: message". Exit status 0 when no file has an error or a warning, 1
// otherwise, 2 when a file cannot be read or validated.
// Usage: NODE_PATH=DIR/node_modules node scripts/gltf-tools/validate.js FILE.glb|FILE.gltf...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const kSeverities = ['error', 'warning', 'info', 'hint'];

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    writeTimestamp: false,
    // External buffers and images, relative to the file (as every glTF reader resolves them).
    externalResourceFunction: (uri) =>
      fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints`);
  for (const m of issues.messages)
    if (m.severity <= 1)
      console.log(`  ${kSeverities[m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
  return issues.numErrors + issues.numWarnings === 0;
}

(async () => {
  const files = process.argv.slice(2);
  if (files.length === 0) {
    console.error('usage: validate.js FILE...');
    process.exit(2);
  }
  let clean = true;
  for (const file of files) {
    try {
      clean = (await validate(file)) && clean;
    } catch (e) {
      console.error(`${file}: cannot validate: ${e}`);
      process.exit(2);
    }
  }
  process.exit(clean ? 0 : 1);
})();
