#!/usr/bin/env node
'use strict';
// Records what a web peer's scene model reads after every step, so that the
// C++ measurement rules (peers/Measurements.cpp, through peers/replay_lab)
// and the JavaScript ones (src/measurements.js, through replay.js) can be
// run on the very same trajectory (peers/check_parity.py compares them).
//
// Usage: record.js ENGINE SCENE SETTING STEP SECONDS [VELOCITY] > FILE
// The file: "key value" lines (scene, step, seconds, mass, velocity), a line
// "rows", then one line per reading, the first before any step; numbers in
// JavaScript's shortest round-trip form, so both readers get the same doubles.
const { scene } = require('../src/constants');

const PARITY_PLATES = 10;  // test5: enough to stack, few enough to record

const ROWS = {
  test2: (m) => [...m.centreOfMass(), m.kineticEnergy()],
  test8: (m) => [...m.centreOfMass(), m.kineticEnergy()],
  test9: (m) => m.centre(),
  test4: (m) => [...m.bigCentre(), m.bigTiltDegrees(), m.deepestPenetration()],
  test10: (m) => [...m.cubeCentre(), m.cubeVelocityX()],
  test1: (m) => Array.from({ length: m.count }, (_, i) => [...m.centre(i), m.speed(i)]).flat(),
  test5: () => [],  // recorded by recordPlates
  test3: (m) => [...Array.from({ length: m.count }, (_, i) => m.tiltDegrees(i)), m.activeBodies()],
  test6: (m) => [...m.bigCentre(), m.bigTiltDegrees(), m.smallSink()],
  test7: (m) => [m.jointError(), m.pivotAngularSpeed(), ...m.pivotCentre(), ...m.testCubeCentre()],
};

async function main([engineName, sceneName, setting, stepText, secondsText, velocityText]) {
  if (!ROWS[sceneName] || !['havok', 'jolt', 'rapier'].includes(engineName)) {
    process.stderr.write('usage: record.js havok|jolt|rapier test1|test2|test3|test4|test5|test6|test7|test8|test9|test10 SETTING STEP SECONDS [VELOCITY]\n');
    return 2;
  }
  const engine = require(`../src/${engineName}`);
  const lib = await engine.load();
  const options = { scene: sceneName, step: Number(stepText), seconds: Number(secondsText), setting, ccd: false };
  const velocity = Number(velocityText || 300);
  let model, mass = 0, steps = Math.round(options.seconds / options.step);
  if (sceneName === 'test2' || sceneName === 'test8') {
    model = engine.pendulum(lib, sceneName === 'test2' ? scene.test2.BOB_MASS : scene.test8.HEAVY_BOB_MASS, options);
    mass = model.mass();
  } else if (sceneName === 'test9') {
    model = engine.ball(lib, options);
  } else if (sceneName === 'test1') {
    model = engine.balls(lib, options);
  } else if (sceneName === 'test3') {
    model = engine.dominoes(lib, options);
  } else if (sceneName === 'test6') {
    model = engine.axisSystem(lib, options);
  } else if (sceneName === 'test7') {
    model = engine.hangingPair(lib, options);
  } else if (sceneName === 'test4') {
    mass = scene.test4.DEFAULT_BIG_MASS;
    model = engine.stack(lib, mass, options);
  } else {
    const t = scene.test10;
    model = engine.launch(lib, velocity, options);
    // As many steps as test10's rule can take for one launch, and two more.
    steps = Math.ceil(((t.WALL_FAR_FACE + t.CUBE_HALF_SIZE - t.LAUNCH_X) / velocity + t.SETTLE_SECONDS) / options.step) + 2;
  }
  if (sceneName === 'test5') return recordPlates(engine, lib, options);
  const lines = [`scene ${sceneName}`, `step ${options.step}`, `seconds ${options.seconds}`, `mass ${mass}`,
    `velocity ${velocity}`, `count ${model.count || 0}`, `bounce_velocity ${model.bounceVelocity ?? 0}`,
    `sleeps ${model.sleeps ? 1 : 0}`, 'rows', ROWS[sceneName](model).join(' ')];
  for (let i = 0; i < steps; ++i) {
    model.step();
    lines.push(ROWS[sceneName](model).join(' '));
  }
  process.stdout.write(lines.join('\n') + '\n');
  return 0;
}

// test5: the plates are dropped by the rule itself, so the rule runs here and
// the readings are taken after every step (before that step's drop); a row
// is the plate count, then x, y, z, speed and yaw of each plate.
function recordPlates(engine, lib, options) {
  const { measurePlates } = require('../src/measurements');
  const { Metrics } = require('../src/metrics');
  const run = { ...options, plates: PARITY_PLATES, spawnInterval: scene.test5.DEFAULT_SPAWN_INTERVAL };
  const real = engine.plateStack(lib, run);
  const row = () => [real.count(), ...Array.from({ length: real.count() },
    (_, i) => [...real.plateCentre(i), real.plateSpeed(i), real.plateYawDegrees(i)]).flat()];
  const rows = [row()];
  measurePlates({ ...real, step: () => { real.step(); rows.push(row()); } }, run, new Metrics());
  const lines = [`scene test5`, `step ${run.step}`, `seconds ${run.seconds}`, 'mass 0', 'velocity 0', 'count 0',
    'bounce_velocity 0', 'sleeps 0', `plates ${run.plates}`, `spawn_interval ${run.spawnInterval}`, 'rows',
    ...rows.map((r) => r.join(' '))];
  process.stdout.write(lines.join('\n') + '\n');
  return 0;
}

if (!require('../src/safe_exit').restartedWithSafeExit(__filename)) {
  main(process.argv.slice(2)).then((status) => { process.exitCode = status; });
}
