#!/usr/bin/env node
'use strict';
// The JavaScript measurement rules (src/measurements.js) on a trajectory
// written by record.js: the metrics, as the web peers name them, on stdout
// as JSON. Usage: replay.js FILE
const { readBounded } = require('../src/files');
const m = require('../src/measurements');
const { Metrics } = require('../src/metrics');
const { measureRebounds, ballLayout } = require('../src/rebound');
const { measureUpright } = require('../src/upright');

// record.js's longest trajectory (test1's fifty balls) is a few megabytes.
const MAX_TRAJECTORY_BYTES = 256 << 20;

function readTrajectory(file) {
  const lines = readBounded(file, MAX_TRAJECTORY_BYTES).toString('utf8').trim().split('\n');
  const header = {};
  let i = 0;
  for (; lines[i] !== 'rows'; ++i) {
    const [key, value] = lines[i].split(' ');
    header[key] = key === 'scene' ? value : Number(value);
  }
  return { header, rows: lines.slice(i + 1).map((line) => line.split(' ').map(Number)) };
}

// A model that gives back the recorded readings: row 0 before any step.
function replayModel(rows, read) {
  let at = 0;
  const row = () => {
    if (at >= rows.length) throw new Error('the trajectory ended before the measurement did');
    return rows[at];
  };
  return { step: () => { ++at; }, ...read(row) };
}

function main([file]) {
  const { header, rows } = readTrajectory(file);
  const options = { scene: header.scene, step: header.step, seconds: header.seconds, ccd: false,
    findMaxVelocity: false, velocity: header.velocity };
  const metrics = new Metrics();
  const pendulum = (row) => ({ centreOfMass: () => row().slice(0, 3), kineticEnergy: () => row()[3], mass: () => header.mass });
  switch (header.scene) {
    case 'test2': m.measureEnergy(replayModel(rows, pendulum), options, metrics); break;
    case 'test8': m.measureElongation(replayModel(rows, pendulum), options, metrics); break;
    case 'test9': m.measureBounces(replayModel(rows, (row) => ({ centre: () => row().slice(0, 3) })), options, metrics); break;
    case 'test4':
      m.measureHold(replayModel(rows, (row) => ({ bigCentre: () => row().slice(0, 3), bigTiltDegrees: () => row()[3],
        deepestPenetration: () => row()[4] })), header.mass, options, metrics);
      break;
    case 'test1': {
      const count = header.count;
      const model = replayModel(rows, (row) => ({ centre: (i) => row().slice(4 * i, 4 * i + 3), speed: (i) => row()[4 * i + 3] }));
      measureRebounds({ ...model, count, bounceVelocity: header.bounce_velocity, bounce: (i) => ballLayout(i).bounce },
        options, metrics);
      break;
    }
    case 'test5': {
      // The recorded row after each step; a plate dropped since shows where it was put.
      let at = 0, dropped = [];
      const row = () => rows[at];
      const recorded = () => row()[0];
      const model = {
        step: () => { ++at; dropped = []; },
        dropPlate: (height) => dropped.push(height),
        count: () => recorded() + dropped.length,
        plateCentre: (i) => (i < recorded() ? row().slice(1 + 5 * i, 4 + 5 * i) : [0, dropped[i - recorded()], 0]),
        plateSpeed: (i) => (i < recorded() ? row()[4 + 5 * i] : 0),
        plateYawDegrees: (i) => (i < recorded() ? row()[5 + 5 * i] : 0),
      };
      m.measurePlates(model, { ...options, plates: header.plates, spawnInterval: header.spawn_interval }, metrics);
      break;
    }
    case 'test3': {
      const count = header.count;
      const model = replayModel(rows, (row) => ({ tiltDegrees: (i) => row()[i], activeBodies: () => row()[count] }));
      m.measureChain({ ...model, count, sleeps: header.sleeps !== 0 }, options, metrics);
      break;
    }
    case 'test6':
      measureUpright(replayModel(rows, (row) => ({ bigCentre: () => row().slice(0, 3), bigTiltDegrees: () => row()[3],
        smallSink: () => row()[4] })), options, metrics);
      break;
    case 'test7':
      m.measureJoints(replayModel(rows, (row) => ({ throwCube: () => {}, jointError: () => row()[0],
        pivotAngularSpeed: () => row()[1], pivotCentre: () => row().slice(2, 5), testCubeCentre: () => row().slice(5, 8) })),
      options, metrics);
      break;
    default:
      m.measureWall(() => replayModel(rows, (row) => ({ cubeCentre: () => row().slice(0, 3), cubeVelocityX: () => row()[3] })),
        options, metrics);
  }
  process.stdout.write(metrics.json());
}

if (!require('../src/safe_exit').restartedWithSafeExit(__filename)) {
  main(process.argv.slice(2));
}
