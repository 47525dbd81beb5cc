// Checks MaterialX documents with MaterialX itself (1.39, compiled to WebAssembly: the npm package
// @needle-tools/materialx). For every file: it must parse; Document.validate() must pass with the
// standard libraries as data library; every node must resolve to a node definition of the standard
// libraries and every input must be one that definition declares, with its type; and for every
// material, shader generation (GLSL, MaterialX's colour management targeting lin_rec709)
// must produce vertex and pixel code with nothing logged (MaterialX logs "Unsupported color space
// transform" and similar problems to stderr). Usage: node materialx.mjs FILE.mtlx...
// Prints one line per file; exit status 1 if any check fails.
import fs from 'fs';
import path from 'path';
import { createRequire } from 'module';
import { fileURLToPath, pathToFileURL } from 'url';

const here = path.dirname(fileURLToPath(import.meta.url));
const bin = path.join(here, 'node_modules/@needle-tools/materialx/bin');
if (!fs.existsSync(bin)) {
  console.error(`materialx.mjs: ${bin} is missing: run scripts/setup.sh (npm ci in tests/validators)`);
  process.exit(1);
}
// The Emscripten module expects CommonJS globals under Node.
globalThis.require = createRequire(import.meta.url);
globalThis.__dirname = bin;
globalThis.__filename = path.join(bin, 'JsMaterialXGenShader.js');
const { default: factory } = await import(pathToFileURL(globalThis.__filename).href);
const logged = [];
const mx = await factory({
  // The package ships the preloaded standard libraries as JsMaterialXGenShader.data.txt.
  locateFile: (p) => path.join(bin, p.endsWith('.data') ? 'JsMaterialXGenShader.data.txt' : p),
  print: (s) => logged.push(s),
  printErr: (s) => logged.push(s),
});

const generators = [['GLSL', mx.GlslShaderGenerator.create()]].map(
  ([name, gen]) => {
    const context = new mx.GenContext(gen);
    const stdlib = mx.loadStandardLibraries(context);
    return { name, gen, context, stdlib };
  });
const stdlib = generators[0].stdlib;
if (logged.length) {
  console.error(`materialx.mjs: loading the standard libraries logged: ${logged.join(' | ')}`);
  process.exit(1);
}

function nodeProblems(doc) {
  const problems = [];
  for (const node of doc.getNodes()) {
    const def = node.getNodeDef();
    if (!def || !stdlib.getNodeDef(def.getName())) {
      problems.push(`node ${node.getName()} (${node.getCategory()}) has no standard node definition`);
      continue;
    }
    for (const input of node.getInputs()) {
      const declared = def.getActiveInput(input.getName());
      if (!declared) problems.push(`${node.getName()}: input ${input.getName()} is not declared by ${def.getName()}`);
      else if (declared.getType() !== input.getType())
        problems.push(`${node.getName()}: input ${input.getName()} is ${input.getType()}, not ${declared.getType()}`);
    }
  }
  return problems;
}

function generationProblems(doc) {
  const problems = [];
  const materials = doc.getMaterialNodes();
  if (materials.length === 0) problems.push('no material');
  for (const material of materials)
    for (const { name, gen, context } of generators) {
      logged.length = 0;
      let shader;
      try {
        shader = gen.generate(material.getName(), material, context);
      } catch (e) {
        problems.push(`${name} ${material.getName()}: ${typeof e === 'number' ? mx.getExceptionMessage(e) : e}`);
        continue;
      }
      if (!shader.getSourceCode('pixel') || !shader.getSourceCode('vertex'))
        problems.push(`${name} ${material.getName()}: empty shader stage`);
      for (const line of logged) problems.push(`${name} ${material.getName()}: ${line}`);
    }
  return { materials: materials.length, problems };
}

let failed = false;
for (const file of process.argv.slice(2)) {
  const doc = mx.createDocument();
  let problems = [];
  let materials = 0;
  try {
    await mx.readFromXmlString(doc, fs.readFileSync(file, 'utf8'));
    doc.setDataLibrary(stdlib);
    const message = { message: '' };
    if (!doc.validate(message)) problems.push(`validate(): ${message.message.trim()}`);
    problems.push(...nodeProblems(doc));
    const gen = generationProblems(doc);
    materials = gen.materials;
    problems.push(...gen.problems);
  } catch (e) {
    problems.push(`cannot read: ${typeof e === 'number' ? mx.getExceptionMessage(e) : e}`);
  }
  const space = doc.getColorSpace() || '(none)';
  if (problems.length) {
    failed = true;
    console.log(`FAIL ${file}: colorspace ${space}, ${materials} materials, ${problems.length} problems`);
    for (const p of problems.slice(0, 20)) console.log(`  ${p}`);
  } else {
    console.log(`ok   ${file}: MaterialX ${mx.getVersionString()}, colorspace ${space}, ${materials} materials ` +
                `validate, resolve to standard definitions and generate GLSL with nothing logged`);
  }
}
process.exit(failed ? 1 : 0);
