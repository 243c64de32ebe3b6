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

const REPLYING = new Set(['build', 'add', 'step']);  // the messages that take a reply
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

// Non-finite numbers are not JSON: a state with NaN or infinity sends null
// in their place, which the C++ side reads back as NaN.
const finiteOrNull = (x) => (Number.isFinite(x) ? x : null);

function statesOf(engine, count) {
  const states = [];
  for (let i = 0; i < count; ++i) {
    const s = engine.state(i);
    states.push(s ? s.map(finiteOrNull) : null);
  }
  return states;
}

// A body index the program may name: one of the world's.
function bodyIndex(message, session) {
  const i = message.body;
  if (!Number.isInteger(i) || i < 0 || i >= session.bodies) throw new Error(`no body ${JSON.stringify(i)} (the world has ${session.bodies})`);
  return i;
}

// One message; returns the reply or undefined (a message without one).
function handle(engine, message, session) {
  switch (message.op) {
    case 'build':
      engine.build(message.world, message.removed || []);
      session.bodies = (message.world.bodies || []).length;
      return { ok: true, notes: engine.notes.fresh(), states: statesOf(engine, session.bodies) };
    case 'add':
      engine.add(message.world, message.first_body, message.first_geom, message.first_joint);
      session.bodies = (message.world.bodies || []).length;
      return { ok: true, notes: engine.notes.fresh(), states: statesOf(engine, session.bodies) };
    case 'remove':
      engine.remove(bodyIndex(message, session));
      return undefined;
    case 'set_state':
      engine.setState(bodyIndex(message, session), message.state);
      return undefined;
    case 'force':
      engine.applyForce(bodyIndex(message, session), message.force, message.torque);
      return undefined;
    case 'settings':
      engine.changeSettings(message.world);
      return undefined;
    case 'step': {
      const count = message.count === undefined ? 1 : message.count;
      for (let n = 0; n < count; ++n) engine.step();
      return {
        states: statesOf(engine, session.bodies),
        contacts: engine.contactCount(),
        engine_wall_s: engine.wallSeconds(),
        engine_cpu_s: engine.cpuSeconds(),
        notes: engine.notes.fresh(),
      };
    }
    default:
      throw new Error(`unknown op ${JSON.stringify(message.op)}`);
  }
}

async function serve(name, setting) {
  let engine;
  try {
    engine = await require(ENGINES[name]).create(setting);
  } catch (error) {
    // The first reply the C++ side reads says why.
    process.stdout.write(`${JSON.stringify({ error: `cannot load ${name}: ${error.message}; run \`npm ci\` in peers/wasm` })}\n`);
    process.exit(1);
  }
  const session = { bodies: 0 };
  let pending = null;  // an error in a message without a reply, told in the next reply
  const input = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  input.on('line', (line) => {
    if (!line.trim()) return;
    let message;
    try {
      message = JSON.parse(line);
    } catch (error) {
      pending = pending || `a message that is not JSON (${error.message})`;
      message = null;
    }
    if (message && message.op === 'quit') {
      input.close();
      return;
    }
    let reply;
    if (message) {
      try {
        reply = handle(engine, message, session);
      } catch (error) {
        const what = `${message.op}: ${error.message}`;
        if (REPLYING.has(message.op)) reply = { error: what };
        else pending = pending || what;
      }
    }
    if (!(message && REPLYING.has(message.op))) return;
    if (pending) {
      reply = { error: pending };
      pending = null;
    }
    process.stdout.write(`${JSON.stringify(reply)}\n`);
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
