'use strict';
// One web peer's whole program: options, the engine loaded, the scene's
// measurement, metrics. Exit status 0 done, 1 the engine or the metrics
// file failed, 2 bad usage or a metrics file that may not be written, 3 the state became non-finite (as the C++ peers).
const fs = require('fs');
const path = require('path');
const { performance } = require('perf_hooks');
const { parseArguments, usage, UsageError } = require('./cli');
const { Metrics } = require('./metrics');
const { checkWritable, FileRefused } = require('./files');
const m = require('./measurements');
const { scene } = require('./constants');
const { measureRebounds } = require('./rebound');
const { measureUpright } = require('./upright');

// The version npm installed (the lockfile's), read from the package's own
// package.json: a package's "exports" may hide that file from require().
function installedVersion(packageName) {
  try {
    const file = path.join(__dirname, '..', 'node_modules', packageName, 'package.json');
    return JSON.parse(fs.readFileSync(file, 'utf8')).version;
  } catch (error) {
    return `(not installed: run \`npm ci\` in peers/wasm)`;
  }
}

function measure(engine, lib, options, metrics) {
  switch (options.scene) {
    case 'test1':
      return measureRebounds(engine.balls(lib, options), options, metrics);
    case 'test6':
      return measureUpright(engine.axisSystem(lib, options), options, metrics);
    case 'test2':
      return m.measureEnergy(engine.pendulum(lib, scene.test2.BOB_MASS, options), options, metrics);
    case 'test8':
      return m.measureElongation(engine.pendulum(lib, options.bobMass || scene.test8.HEAVY_BOB_MASS, options), options, metrics);
    case 'test5':
      return m.measurePlates(engine.plateStack(lib, options), options, metrics);
    case 'test3':
      return m.measureChain(engine.dominoes(lib, options), options, metrics);
    case 'test7':
      return m.measureJoints(engine.hangingPair(lib, options), options, metrics);
    case 'test9':
      return m.measureBounces(engine.ball(lib, options), options, metrics);
    case 'test4': {
      const bigMass = options.bigMass || scene.test4.DEFAULT_BIG_MASS;
      return m.measureHold(engine.stack(lib, bigMass, options), bigMass, options, metrics);
    }
    default:
      return m.measureWall((velocity) => engine.launch(lib, velocity, options), options, metrics);
  }
}

async function runPeer(engine, argv = process.argv.slice(2)) {
  let options;
  try {
    options = parseArguments(argv, engine);
    if (options.scene !== 'test10' && m.stepsFor(options) < 1)
      throw new UsageError(`--seconds: a run of ${m.stepsFor(options)} steps of ${options.step} s measures nothing`);
    // Before the run: a metrics file that cannot be written costs no run.
    if (options.metricsJson && !options.help && !options.version) checkWritable(options.metricsJson);
  } catch (error) {
    if (error instanceof FileRefused) error.message = `--metrics-json: ${error.message}`;
    else if (!(error instanceof UsageError)) throw error;
    process.stderr.write(`error: ${error.message}\nRun with --help for more information.\n`);
    return 2;
  }
  if (options.help) {
    process.stdout.write(usage(engine.name));
    return 0;
  }
  if (options.version) {
    process.stdout.write(`${engine.name} ${engine.packageName} ${installedVersion(engine.packageName)}\n`);
    return 0;
  }
  let lib;
  try {
    lib = await engine.load();
  } catch (error) {
    process.stderr.write(`error: cannot load ${engine.name} (${error.message}); run \`npm ci\` in peers/wasm\n`);
    return 1;
  }
  const metrics = new Metrics();
  const cpuBefore = process.cpuUsage();
  const wallBefore = performance.now();
  const tally = measure(engine, lib, options, metrics);
  const wall = (performance.now() - wallBefore) / 1000;
  const cpuUsed = process.cpuUsage(cpuBefore);
  const all = new Metrics();  // the run's own figures first, as the ODE programs write them
  all.set('steps', tally.steps);
  all.set('sim_seconds', tally.steps * options.step);
  all.set('wall_seconds', wall);
  all.set('cpu_seconds', (cpuUsed.user + cpuUsed.system) / 1e6);
  all.set('non_finite', tally.finite ? 0 : 1);
  for (const [name, value] of metrics.entries) all.set(name, value);
  process.stdout.write(`${engine.name} ${options.scene}, step ${options.step} s, setting ${options.setting}` +
    `${options.ccd ? ' + ccd' : ''}: ${engine.settingText(options)}\n`);
  process.stdout.write(all.text());
  if (options.metricsJson) {
    try {
      all.writeJsonAtomically(options.metricsJson);
    } catch (error) {
      process.stderr.write(`error: ${error.message}\n`);
      return 1;
    }
  }
  return tally.finite ? 0 : 3;
}

// The entry files call this: the status becomes the process's.
function main(engine) {
  runPeer(engine).then((status) => { process.exitCode = status; }, (error) => {
    process.stderr.write(`error: ${error.stack || error}\n`);
    process.exitCode = 1;
  });
}

module.exports = { runPeer, main };
