#!/usr/bin/env node
'use strict';
// MuJoCo 3 (the npm package mujoco-js, double precision) on a model that
// peers/mujoco_lab writes with --write-model: the same MJCF that Debian's
// MuJoCo 2.2.2 runs there, measured by the same rules (src/measurements.js),
// so the two versions can be set side by side (peers/check_mujoco3.py).
//
// Usage: mujoco3.js MODEL.xml --scene test2|test9 [--seconds S] [--metrics-json FILE]
// Exit 0 done, 1 the model or the engine failed, 2 bad usage (an option twice, a model
// or metrics file refused by src/files.js), 3 non-finite state.
const { performance } = require('perf_hooks');
const { Metrics } = require('./src/metrics');
const m = require('./src/measurements');
const { checkWritable, readBounded, FileRefused } = require('./src/files');

const MAX_MODEL_BYTES = 16 << 20;  // mujoco_lab's models are a few kilobytes

const USAGE = 'usage: mujoco3.js MODEL.xml --scene test2|test9 [--seconds S] [--metrics-json FILE]\n';

function parse(argv) {
  const options = { model: '', scene: '', seconds: -1, metricsJson: '' };
  for (let i = 0; i < argv.length; ++i) {
    const value = argv[i + 1];
    if (argv[i] === '--scene' && !options.scene && ['test2', 'test9'].includes(value)) options.scene = argv[++i];
    else if (argv[i] === '--seconds' && options.seconds < 0 && /^\d+(\.\d*)?$/.test(value || '') && Number(value) > 0) options.seconds = Number(argv[++i]);
    else if (argv[i] === '--metrics-json' && !options.metricsJson && value) options.metricsJson = argv[++i];
    else if (!argv[i].startsWith('-') && !options.model) options.model = argv[i];
    else return null;
  }
  return options.model && options.scene ? options : null;
}

// The scene's readings, as mujoco_lab takes them (body 1 is the pendulum or the ball).
function model(mj, m3, d) {
  const step = () => {
    mj.mj_step(m3, d);
    mj.mj_kinematics(m3, d);  // the new state's positions (mj_step leaves the old ones)
  };
  const axisInertia = d.qM[0];  // one hinge to the world: the body's moment about the axis
  return {
    step,
    centreOfMass: () => [d.xipos[3], d.xipos[4], d.xipos[5]],
    kineticEnergy: () => 0.5 * axisInertia * d.qvel[0] * d.qvel[0],
    mass: () => m3.body_mass[1],
    centre: () => [d.qpos[0], d.qpos[1], d.qpos[2]],
  };
}

async function main(argv) {
  const options = parse(argv);
  if (!options) {
    process.stderr.write(USAGE);
    return 2;
  }
  let modelText;
  try {  // both files checked before the engine loads: a bad one costs no run
    if (options.metricsJson) checkWritable(options.metricsJson);
    modelText = readBounded(options.model, MAX_MODEL_BYTES).toString('utf8');
  } catch (error) {
    if (!(error instanceof FileRefused)) throw error;
    process.stderr.write(`error: ${error.message}\n${USAGE}`);
    return 2;
  }
  const { default: load } = await import('mujoco-js');
  const mj = await load();
  mj.FS.writeFile('/model.xml', modelText);
  const m3 = mj.MjModel.loadFromXML('/model.xml');
  const d = new mj.MjData(m3);
  mj.mj_forward(m3, d);
  const readings = model(mj, m3, d);
  const run = { scene: options.scene, step: m3.opt.timestep, seconds: options.seconds };
  const metrics = new Metrics();
  const wallBefore = performance.now();
  const tally = options.scene === 'test2' ? m.measureEnergy(readings, run, metrics) : m.measureBounces(readings, run, metrics);
  const all = new Metrics();
  all.set('steps', tally.steps);
  all.set('sim_seconds', tally.steps * run.step);
  all.set('wall_seconds', (performance.now() - wallBefore) / 1000);
  all.set('non_finite', tally.finite ? 0 : 1);
  for (const [name, value] of metrics.entries) all.set(name, value);
  process.stdout.write(`mujoco ${mj.mj_versionString()} (mujoco-js) ${options.scene}, step ${run.step} s\n${all.text()}`);
  if (options.metricsJson) all.writeJsonAtomically(options.metricsJson);
  return tally.finite ? 0 : 3;
}

if (!require('./src/safe_exit').restartedWithSafeExit(__filename)) {
  main(process.argv.slice(2)).then((status) => { process.exitCode = status; }, (error) => {
    process.stderr.write(`error: ${error.stack || error}\n`);
    process.exitCode = 1;
  });
}
