'use strict';
// A force and a torque given through 'force' act for the next step only
// (doc/engine-protocol.md): the step after gives a free body nothing more.
// A torque that outlived its step kept spinning a dragged body after the
// drag was released, and the mouse drag poured energy into it (a
// pendulum on Rapier whirled upright: 25 J became 37,657 J).
//   node --test peers/wasm/test/
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const path = require('path');
const { Session } = require('../src/session');

// The ball of the world format's example, its velocity and gravity taken
// off so that only the force and torque move it, and the plane far below.
function freeBall() {
  const world = JSON.parse(fs.readFileSync(path.join(__dirname, '..', '..', '..', 'doc', 'worlds', 'projectile.json'), 'utf8'));
  delete world.measures;
  world.settings.gravity = [0, 0, 0];
  world.bodies[0].linear_velocity = [0, 0, 0];
  world.bodies[0].position = [0, 100, 0];
  return world;
}

const send = (s, message) => s.line(JSON.stringify(message));
const norm = (v) => Math.hypot(v[0], v[1], v[2]);

for (const name of ['havok', 'jolt', 'rapier']) {
  test(`${name}: a force and a torque act for one step, then no more`, async (t) => {
    let module;
    try {
      module = require(`../src/engines/${name}`);
    } catch (error) {
      t.skip(`${name} is not installed here (${error.message})`);
      return;
    }
    // The .wasm file read here where the package does not inline it (as engine_server.js does).
    const wasmBinary = module.wasmFile ? fs.readFileSync(require.resolve(module.wasmFile)) : undefined;
    const s = new Session(module.make(await module.load({ wasmBinary }), 'default'));
    const world = freeBall();
    assert.strictEqual(JSON.parse(send(s, { op: 'build', world, removed: [] })).ok, true);
    // 1000 N and 1 N m for one 1 ms step on a 1 kg ball with I = 0.004 kg m^2:
    // 1 m/s and 0.25 rad/s (speeds of a drag; Havok lets far smaller ones decay).
    send(s, { op: 'force', body: 0, force: [1000, 0, 0], torque: [0, 0, 1] });
    const first = JSON.parse(send(s, { op: 'step' })).states[0];
    const v1 = first.slice(7, 10), w1 = first.slice(10, 13);
    assert.ok(Math.abs(v1[0] - 1) < 1e-3, `speed after the forced step ${v1}`);
    assert.ok(Math.abs(w1[2] - 0.25) < 2.5e-3, `spin after the forced step ${w1}`);
    // Ten steps with nothing applied: the speeds stay (float32: 1e-6 relative).
    const later = JSON.parse(send(s, { op: 'step', count: 10 })).states[0];
    const v2 = later.slice(7, 10), w2 = later.slice(10, 13);
    assert.ok(norm(v2) <= norm(v1) * (1 + 1e-4), `speed grew without a force: ${v1} -> ${v2}`);
    assert.ok(norm(w2) <= norm(w1) * (1 + 1e-4), `spin grew without a torque: ${w1} -> ${w2}`);
  });
}
