'use strict';
// The command line of the peer programs (peers/PeerMain.cpp's options), for
// the web peers. A bad option, an option given twice, a value out of range,
// NaN, a count not in digits, or a run that would take no step is refused with its reason on stderr and status 2.

const { scene } = require('./constants');

class UsageError extends Error {}

const SCENES = ['test1', 'test2', 'test3', 'test4', 'test5', 'test6', 'test7', 'test8', 'test9', 'test10'];

// name -> {kind: 'number'|'choice'|'text'|'flag', key, min, max, choices, help}
const OPTIONS = {
  '--scene': { kind: 'choice', key: 'scene', choices: SCENES, help: 'the scene, named as the ODE program that measures it' },
  '--step': { kind: 'number', key: 'step', min: 1e-7, max: 0.1,
    help: "simulation step in s (test3: 0.005, its ODE program's, unless given)" },
  '--seconds': { kind: 'number', key: 'seconds', min: 0, max: 86400, exclusiveMin: true,
    help: "simulated seconds (default: the ODE program's run for the scene)" },
  '--setting': { kind: 'choice', key: 'setting', choices: ['default', 'best'],
    help: "default: the engine as a user gets it; best: the engine's most accurate settings for the scene" },
  '--ccd': { kind: 'flag', key: 'ccd', help: "test10: the engine's continuous collision detection" },
  '--velocity': { kind: 'number', key: 'velocity', min: 1e-3, max: 1e7, help: 'test10: launch velocity in m/s' },
  '--find-max-velocity': { kind: 'flag', key: 'findMaxVelocity',
    help: 'test10: scan from 1 m/s (every 1 m/s to 1000, every 0.1% above) for the highest velocity with every launch up to it stopped' },
  '--big-mass': { kind: 'number', key: 'bigMass', min: 1e-3, max: 1e9, help: "test4: mass of the big cube in kg (default: the scene's)" },
  '--bob-mass': { kind: 'number', key: 'bobMass', min: 1e-3, max: 1e9, help: "test8: mass of the bob in kg (default: the scene's)" },
  '--plates': { kind: 'number', key: 'plates', min: 1, max: 100000, integer: true, help: "test5: plates dropped (default: the scene's)" },
  '--spawn-interval': { kind: 'number', key: 'spawnInterval', min: 1e-6, max: 1e4,
    help: "test5: simulated seconds between plates (default: the scene's)" },
  '--metrics-json': { kind: 'text', key: 'metricsJson', help: 'write the metrics to this file as JSON, whole (a new or regular file in an existing folder: anything else is refused before the run)' },
  '--headless': { kind: 'flag', key: 'headless', help: "accepted for the lab's sake; the peers never open a window" },
  '--help': { kind: 'flag', key: 'help', help: 'print this help and exit' },
  '--version': { kind: 'flag', key: 'version', help: 'print the engine and its npm package version, and exit' },
};
const ALIASES = { '-h': '--help' };

function defaults() {
  return { scene: 'test2', step: 0.001, seconds: -1, setting: 'default', ccd: false, velocity: 200,
    findMaxVelocity: false, bigMass: 0, bobMass: 0, plates: 0, spawnInterval: 0, metricsJson: '', headless: false, help: false,
    version: false };
}

function usage(engineName) {
  const lines = [`The thesis's measurement scenes on ${engineName} (WebAssembly, float32), headless, with the ODE programs' metric names (doc/peers.md).`,
    `Usage: ${engineName}_lab [OPTIONS]`, '', 'Options:'];
  const initial = defaults();
  for (const [name, o] of Object.entries(OPTIONS)) {
    const value = o.kind === 'flag' ? '' : o.kind === 'choice' ? ` {${o.choices.join(',')}}` : o.kind === 'number' ? ' NUMBER' : ' FILE';
    const shown = ['scene', 'step', 'setting', 'velocity'].includes(o.key) ? ` (default ${initial[o.key]})` : '';
    lines.push(`  ${(name + value).padEnd(34)} ${o.help}${shown}`);
  }
  return lines.join('\n') + '\n';
}

function parseNumber(name, text, o) {
  // Number() takes '', '0x10' and ' 1 '; a plain decimal is what the C++ peers accept.
  if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(text)) throw new UsageError(`${name}: "${text}" is not a number`);
  // A count is written in digits: 1e3 or 10.0 is refused, as the C++ peers' integer parser refuses it.
  if (o.integer && !/^[+-]?\d+$/.test(text)) throw new UsageError(`${name}: "${text}" is not a whole number`);
  const value = Number(text);
  const low = o.exclusiveMin ? value <= o.min : value < o.min;
  if (!Number.isFinite(value) || low || value > o.max)
    throw new UsageError(`${name}: ${text} is not in ${o.exclusiveMin ? '(' : '['}${o.min} - ${o.max}]`);
  return value;
}

// `argv`: the arguments after the program. Returns the options; throws
// UsageError naming what was wrong. `engine`: {hasContinuousCollision, name}.
function parseArguments(argv, engine) {
  const options = defaults();
  const given = new Set();  // an option given twice is a mistake, not a choice of the last
  for (let i = 0; i < argv.length; ++i) {
    let arg = argv[i], value;
    const equals = arg.startsWith('--') ? arg.indexOf('=') : -1;
    if (equals > 0) {
      value = arg.slice(equals + 1);
      arg = arg.slice(0, equals);
    }
    arg = ALIASES[arg] || arg;
    const o = OPTIONS[arg];
    if (!o) throw new UsageError(arg.startsWith('-') ? `unknown option ${arg}` : `unexpected argument "${arg}"`);
    if (given.has(arg)) throw new UsageError(`${arg} given twice`);
    given.add(arg);
    if (o.kind === 'flag') {
      if (value !== undefined) throw new UsageError(`${arg} takes no value`);
      options[o.key] = true;
      continue;
    }
    if (value === undefined) {
      if (i + 1 >= argv.length) throw new UsageError(`${arg} needs a value`);
      value = argv[++i];
    }
    if (o.kind === 'number') options[o.key] = parseNumber(arg, value, o);
    else if (o.kind === 'choice') {
      if (!o.choices.includes(value)) throw new UsageError(`${arg}: "${value}" is not one of ${o.choices.join(', ')}`);
      options[o.key] = value;
    } else {
      if (value === '') throw new UsageError(`${arg}: empty file name`);
      options[o.key] = value;
    }
  }
  if (options.help || options.version) return options;
  if (options.scene === 'test3' && !argv.some((a) => a === '--step' || a.startsWith('--step='))) options.step = scene.test3.SCENE_STEP;
  if (options.ccd && !engine.hasContinuousCollision)
    throw new UsageError(`--ccd: ${engine.name} has no continuous collision switch`);
  if (options.ccd && options.scene !== 'test10') throw new UsageError('--ccd: only test10 uses it');
  if (options.findMaxVelocity && options.scene !== 'test10') throw new UsageError('--find-max-velocity: only test10 uses it');
  return options;
}

module.exports = { parseArguments, usage, UsageError, SCENES };
