'use strict';
// The protocol's engine side (src/session.js), as the Node.js server and
// the page both use it: replies, errors told in the next reply, quit.
//   node --test peers/wasm/test/
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const path = require('path');
const { Session } = require('../src/session');
const rapier = require('../src/engines/rapier');

// A ball thrown over a plane: the world format's own example.
const WORLD = JSON.parse(fs.readFileSync(path.join(__dirname, '..', '..', '..', 'doc', 'worlds', 'projectile.json'), 'utf8'));
delete WORLD.measures;

async function session() {
  return new Session(rapier.make(await rapier.load({}), 'default'));
}

const send = (s, message) => s.line(JSON.stringify(message));

test('a build and a step answer every body\'s state, 14 numbers', async () => {
  const s = await session();
  const built = JSON.parse(send(s, { op: 'build', world: WORLD, removed: [] }));
  assert.strictEqual(built.ok, true);
  assert.deepStrictEqual(built.states[0].slice(0, 3), [0, 1, 0]);
  const stepped = JSON.parse(send(s, { op: 'step', count: 10 }));
  assert.strictEqual(stepped.states.length, 1);
  assert.strictEqual(stepped.states[0].length, 14);
  // 10 steps of 1 ms at 4 m/s: 4 cm along x, within float32.
  assert.ok(Math.abs(stepped.states[0][0] - 0.04) < 1e-4, `x ${stepped.states[0][0]}`);
  assert.ok(stepped.engine_wall_s > 0 && stepped.engine_cpu_s >= 0);
});

test('a message without a reply that fails is told in the next reply', async () => {
  const s = await session();
  send(s, { op: 'build', world: WORLD, removed: [] });
  assert.strictEqual(send(s, { op: 'remove', body: 7 }), null);
  assert.match(JSON.parse(send(s, { op: 'step' })).error, /^remove: no body 7 \(the world has 1\)/);
  assert.ok(JSON.parse(send(s, { op: 'step' })).states, 'the error is told once');
});

test('a line that is not JSON, and an unknown op, are errors', async () => {
  const s = await session();
  assert.strictEqual(s.line('{not json'), null);
  assert.match(JSON.parse(send(s, { op: 'build', world: WORLD })).error, /^a message that is not JSON/);
  assert.strictEqual(send(s, { op: 'fly' }), null);
  assert.match(JSON.parse(send(s, { op: 'step' })).error, /^fly: unknown op "fly"/);
});

test('a number that is not finite goes as null; quit ends the session', () => {
  // An engine whose body has blown up (a stand-in: JSON cannot carry NaN in).
  const blownUp = {
    notes: { fresh: () => [] },
    build() {},
    step() {},
    state: () => [NaN, Infinity, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1],
    contactCount: () => -1,
    wallSeconds: () => 0,
    cpuSeconds: () => 0,
  };
  const s = new Session(blownUp);
  send(s, { op: 'build', world: { bodies: [{}] } });
  const reply = JSON.parse(send(s, { op: 'step' }));
  assert.deepStrictEqual(reply.states[0].slice(0, 4), [null, null, 0, 1]);
  assert.strictEqual(s.quit, false);
  assert.strictEqual(send(s, { op: 'quit' }), null);
  assert.strictEqual(s.quit, true);
});

for (const name of ['havok', 'jolt', 'rapier']) {
  test(`${name}: reset makes a fresh engine in the same session, and a build after it starts over`, async () => {
    const adapter = require(`../src/engines/${name}`);
    const wasmBinary = adapter.wasmFile ? fs.readFileSync(require.resolve(adapter.wasmFile)) : undefined;
    const module = await adapter.load({ wasmBinary });
    const s = new Session(adapter.make(module, 'default'), () => adapter.make(module, 'default'));
    send(s, { op: 'build', world: WORLD, removed: [] });
    const before = JSON.parse(send(s, { op: 'step', count: 100 })).states[0];
    assert.strictEqual(send(s, { op: 'reset' }), null);
    send(s, { op: 'build', world: WORLD, removed: [] });
    const again = JSON.parse(send(s, { op: 'step', count: 100 }));
    assert.strictEqual(again.error, undefined);
    assert.deepStrictEqual(again.states[0], before, 'the same world built again steps to the same state');
  });
}

test('reset without a way to make an engine is an error told in the next reply', async () => {
  const s = await session();
  send(s, { op: 'build', world: WORLD, removed: [] });
  assert.strictEqual(send(s, { op: 'reset' }), null);
  assert.match(JSON.parse(send(s, { op: 'step' })).error, /^reset: this session cannot make a fresh engine/);
});
