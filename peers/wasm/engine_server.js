#!/usr/bin/env node
'use strict';
// engine_server: one of Havok, Jolt and Rapier (src/engines/) behind a pipe,
// for the C++ adapter peers/engines/NodeEngine.cpp, which starts it as
//   node --no-concurrent-recompilation engine_server.js ENGINE default|best
// and speaks doc/engine-protocol.md: one JSON message a line on stdin, one
// JSON reply a line on stdout for those that take one. Diagnostics go to
// stderr, which the C++ side leaves to its own.
//   node engine_server.js --info ENGINE   prints {"name", "version", "precision"} and ends.
// Started again with node's --no-concurrent-recompilation where it lacks it:
// src/safe_exit.js says why (Node can hang at exit in these WASM builds).
const readline = require('readline');
const { Session } = require('./src/session');

const ENGINES = { havok: './src/engines/havok', jolt: './src/engines/jolt', rapier: './src/engines/rapier' };

function fail(message) {
  process.stderr.write(`engine_server: ${message}\n`);
  process.exit(2);
}

function info(name) {
  const fs = require('fs');
  const path = require('path');
  const adapter = require(ENGINES[name]);
  const file = path.join(__dirname, 'node_modules', adapter.packageName, 'package.json');
  const version = JSON.parse(fs.readFileSync(file, 'utf8')).version;
  process.stdout.write(`${JSON.stringify({ name, package: adapter.packageName, version, precision: adapter.precision })}\n`);
}

// The engine's WebAssembly module, its .wasm file read here where the
// build does not inline it.
function loadEngine(adapter) {
  const wasmBinary = adapter.wasmFile ? require('fs').readFileSync(require.resolve(adapter.wasmFile)) : undefined;
  return adapter.load({ wasmBinary });
}

async function serve(name, setting) {
  let session;
  try {
    const adapter = require(ENGINES[name]);
    const module = await loadEngine(adapter);
    session = new Session(adapter.make(module, setting), () => adapter.make(module, setting));
  } catch (error) {
    // The first reply the C++ side reads says why.
    process.stdout.write(`${JSON.stringify({ error: `cannot load ${name}: ${error.message}; run \`npm ci\` in peers/wasm` })}\n`);
    process.exit(1);
  }
  const input = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  input.on('line', (line) => {
    const reply = session.line(line);
    if (reply !== null) process.stdout.write(`${reply}\n`);
    if (session.quit) input.close();
  });
  // Stdin closed (quit, or the program gone): end now, without waiting on
  // the WebAssembly runtime's background work.
  input.on('close', () => process.exit(0));
}

function main(argv) {
  if (argv[0] === '--info') {
    if (!ENGINES[argv[1]]) fail(`--info: unknown engine '${argv[1]}' (havok, jolt or rapier)`);
    info(argv[1]);
    return;
  }
  const [name, setting] = argv;
  if (!ENGINES[name] || !['default', 'best'].includes(setting))
    fail('usage: engine_server.js havok|jolt|rapier default|best, or --info ENGINE');
  serve(name, setting);
}

if (!require('./src/safe_exit').restartedWithSafeExit(__filename)) main(process.argv.slice(2));
