#!/usr/bin/env node
'use strict';
// engine_server: one of Havok, Jolt, Rapier and PhysX (src/engines/names.js) behind a pipe,
// for the C++ adapter peers/engines/NodeEngine.cpp, which starts it as
//   node --no-concurrent-recompilation engine_server.js ENGINE default|best
// and speaks doc/engine-protocol.md: one JSON message a line on stdin, one
// JSON reply a line on stdout for those that take one. Diagnostics go to
// stderr, which the C++ side leaves to its own.
//   node engine_server.js --info ENGINE   prints {"name", "version", "precision"} and ends.
// Started again with node's --no-concurrent-recompilation where it lacks it:
// src/safe_exit.js says why (Node can hang at exit in these WASM builds).
const { readLines } = require('./src/line_reader');
const { Session } = require('./src/session');

// The longest message line read: a build message carries the whole world,
// which a world file holds in at most 64 MiB (utils/world/FormatRanges.h);
// written compactly it takes no more, and twice that leaves room.
const MAX_LINE_BYTES = 128 * 1024 * 1024;

const NAMES = require('./src/engines/names');
const ENGINES = Object.fromEntries(NAMES.map((name) => [name, `./src/engines/${name}`]));
// An engine's name is one of ENGINES' own keys: a name such as '__proto__'
// or 'toString', which every object inherits, is not one.
const isEngine = (name) => typeof name === 'string' && Object.prototype.hasOwnProperty.call(ENGINES, name);

// The reader of stdout gone (the C++ side ended, `| head`): end quietly, as
// a program whose reader left, instead of an 'EPIPE' traceback.
process.stdout.on('error', (error) => {
  if (error.code === 'EPIPE') process.exit(0);
  throw error;
});

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
  // Stdin closed (quit, or the program gone): end now, without waiting on
  // the WebAssembly runtime's background work.
  readLines(process.stdin, MAX_LINE_BYTES, {
    line: (line) => {
      const reply = session.line(line);
      if (reply !== null) process.stdout.write(`${reply}\n`);
      if (session.quit) process.exit(0);
    },
    // No reply can be matched to a message never read: the server ends, and
    // the program says the engine failed.
    tooLong: (bytes) => fail(`a message line of over ${bytes} bytes; the protocol's lines are at most ${MAX_LINE_BYTES}`),
    end: () => process.exit(0),
  });
}

function main(argv) {
  if (argv[0] === '--info') {
    if (!isEngine(argv[1])) fail(`--info: unknown engine '${argv[1]}' (${NAMES.join(', ')})`);
    info(argv[1]);
    return;
  }
  const [name, setting] = argv;
  if (!isEngine(name) || !['default', 'best'].includes(setting))
    fail(`usage: engine_server.js ${NAMES.join('|')} default|best, or --info ENGINE`);
  serve(name, setting);
}

if (!require('./src/safe_exit').restartedWithSafeExit(__filename)) main(process.argv.slice(2));
