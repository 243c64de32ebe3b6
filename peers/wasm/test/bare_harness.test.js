'use strict';
// The bare harness (bench/bare.js) is the floor the adapters' engine step
// is measured against, so it must build the same world as the adapter:
// after the same steps its bodies stand where the Rapier adapter's do. And
// what it cannot build it refuses, naming it, with status 2.
//   node --test peers/wasm/test/bare_harness.test.js
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');
const { Session } = require('../src/session');
const rapier = require('../src/engines/rapier');

const BARE = path.join(__dirname, '..', 'bench', 'bare.js');
const WORLDS = path.join(__dirname, '..', '..', '..', 'doc', 'worlds');
const STEPS = 500;
// Both run Rapier in float32 from the same start; the adapter builds the
// world by another path (its own inertia frame, material rules), so the
// poses agree to float32 rounding carried over the steps, not bit for bit.
const POSE_TOLERANCE = 1e-4;

function bare(...args) {
  return spawnSync(process.execPath, [BARE, ...args], { encoding: 'utf8' });
}

async function adapterPoses(world) {
  const s = new Session(rapier.make(await rapier.load({}), 'default'));
  s.line(JSON.stringify({ op: 'build', world }));
  let reply;
  for (let i = 0; i < STEPS; ++i) reply = s.line('{"op":"step","count":1}');
  return JSON.parse(reply).states.map((state) => state.slice(0, 7));
}

for (const name of ['projectile', 'hinged_chain']) {
  test(`${name}: the bare harness's bodies end where the Rapier adapter's do`, async () => {
    const file = path.join(WORLDS, `${name}.json`);
    const run = bare('rapier', file, '--steps', String(STEPS), '--repeats', '1', '--warmup', '0', '--states');
    assert.strictEqual(run.status, 0, run.stderr);
    const mine = JSON.parse(run.stdout).states;
    const theirs = await adapterPoses(JSON.parse(fs.readFileSync(file, 'utf8')));
    assert.strictEqual(mine.length, theirs.length);
    mine.forEach((pose, b) => pose.forEach((x, k) => {
      // q and -q are one orientation.
      const sign = Math.sign(pose[3] || 1) === Math.sign(theirs[b][3] || 1) || k < 3 ? 1 : -1;
      assert.ok(Math.abs(x - sign * theirs[b][k]) < POSE_TOLERANCE,
        `body ${b} coordinate ${k}: bare ${x}, adapter ${theirs[b][k]}`);
    }));
  });
}

test('what the harness cannot build is refused, named, with status 2', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'bare-'));
  try {
    const world = JSON.parse(fs.readFileSync(path.join(WORLDS, 'projectile.json'), 'utf8'));
    world.geoms[1].shape = 'capsule';
    world.geoms[1].length = 0.2;
    const file = path.join(dir, 'capsule.json');
    fs.writeFileSync(file, JSON.stringify(world));
    const run = bare('jolt', file);
    assert.strictEqual(run.status, 2);
    assert.match(run.stderr, /geoms\[1\]: shape 'capsule'/);
    assert.strictEqual(run.stdout, '');
    const engine = bare('bullet', file);
    assert.strictEqual(engine.status, 2);
    assert.match(engine.stderr, /engine 'bullet'/);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
