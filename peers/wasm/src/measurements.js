'use strict';
// The thesis's measurements as peers/Measurements.cpp makes them, for the
// web peers: each runs one scene on an engine's model and sets the metrics
// the ODE program of that scene writes (same names, same definitions).
// checks/ runs both on the same recorded trajectories (peers/wasm/parity).
const { performance } = require('perf_hooks');
const { scene, SURFACE_GRAVITY } = require('./constants');
const { ApexTracker } = require('./apex');
// test10's scan steps, VelocityScan's own (tests/shared/VelocityScan.h).
const scan = scene.top;

const finite = (v) => v.every(Number.isFinite);
const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
// std::lround: halves away from zero.
const lround = (x) => Math.sign(x) * Math.round(Math.abs(x));

function defaultSeconds(name) {
  return { test1: scene.test1.RUN_SECONDS, test2: scene.test2.RUN_SECONDS, test8: scene.test8.RUN_SECONDS, test9: scene.test9.RUN_SECONDS,
    test4: scene.test4.RUN_SECONDS, test3: scene.test3.RUN_SECONDS, test5: scene.test5.RUN_SECONDS, test6: scene.test6.DEFAULT_SECONDS,
    test7: scene.test7.DEFAULT_THROWS * scene.test7.DEFAULT_THROW_INTERVAL }[name] ?? 0;
}

function stepsFor(options) {
  return lround((options.seconds >= 0 ? options.seconds : defaultSeconds(options.scene)) / options.step);
}

// test2: total energy m g y + kinetic, its largest deviation from the start.
// `pendulum`: {step(), centreOfMass() -> [x,y,z], kineticEnergy(), mass()}.
function measureEnergy(pendulum, options, metrics) {
  const weight = pendulum.mass() * SURFACE_GRAVITY;
  const energy = () => weight * pendulum.centreOfMass()[1] + pendulum.kineticEnergy();
  const start = energy();
  let low = start, high = start, last = start;
  const tally = { steps: 0, finite: true };
  for (let i = 0, n = stepsFor(options); i < n; ++i) {
    pendulum.step();
    last = energy();
    if (!Number.isFinite(last)) {
      tally.finite = false;
      break;
    }
    low = Math.min(low, last);
    high = Math.max(high, last);
    ++tally.steps;
  }
  metrics.set('energy_rel_variation', (high - low) / high);
  metrics.set('energy_drift', (last - start) / start);
  metrics.set('energy_max_deviation', Math.max(high - start, start - low) / start);
  metrics.set('energy_start_J', start);
  metrics.set('energy_min_J', low);
  metrics.set('energy_max_J', high);
  metrics.set('energy_last_J', last);
  metrics.set('composite_mass_kg', pendulum.mass());
  return tally;
}

// test8: relative elongation (l - l0) / l0 of the anchor-to-centre-of-mass distance.
function measureElongation(pendulum, options, metrics) {
  const anchor = [0, scene.test2.ANCHOR_HEIGHT, 0];
  const startLength = distance(pendulum.centreOfMass(), anchor);
  let largest = 0, sum = 0;
  const tally = { steps: 0, finite: true };
  for (let i = 0, n = stepsFor(options); i < n; ++i) {
    pendulum.step();
    const centre = pendulum.centreOfMass();
    if (!finite(centre)) {
      tally.finite = false;
      break;
    }
    const elongation = (distance(centre, anchor) - startLength) / startLength;
    largest = Math.max(largest, Math.abs(elongation));
    sum += elongation;
    ++tally.steps;
  }
  metrics.set('max_relative_elongation', largest);
  metrics.set('mean_relative_elongation', tally.steps ? sum / tally.steps : 0);
  metrics.set('start_length_m', startLength);
  metrics.set('composite_mass_kg', pendulum.mass());
  return tally;
}

// test9: apex error relative to the start height above the contact, after 5, 10, 20 bounces.
// `ball`: {step(), centre()}.
function measureBounces(ball, options, metrics) {
  const { START_HEIGHT, BALL_RADIUS } = scene.test9;
  const start = ball.centre();
  const tracker = new ApexTracker();
  tracker.restart(0, start);
  const errors = [];
  let drift = 0;
  const tally = { steps: 0, finite: true };
  for (let i = 0, n = stepsFor(options); i < n; ++i) {
    ball.step();
    const c = ball.centre();
    if (!finite(c)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    drift = Math.max(drift, Math.hypot(c[0], c[2]));
    const apex = tracker.update(tally.steps * options.step, c);
    if (apex) errors.push(Math.abs(apex.position[1] - tracker.releaseApex.position[1]) / (START_HEIGHT - BALL_RADIUS));
  }
  for (const bounces of [5, 10, 20]) metrics.set(`apex_error_${bounces}`, bounces <= errors.length ? errors[bounces - 1] : NaN);
  metrics.set('max_horizontal_drift', drift);
  metrics.set('bounces', tracker.count);
  metrics.set('last_apex_error', errors.length ? errors[errors.length - 1] : NaN);
  metrics.set('start_height_m', start[1]);
  metrics.set('ball_radius_m', BALL_RADIUS);
  return tally;
}

// test4: how long the big cube stays balanced on the small one (test4's rule).
// `stack`: {step(), bigCentre(), bigTiltDegrees(), deepestPenetration()}.
function measureHold(stack, bigMass, options, metrics) {
  const { SIDEWAYS_LIMIT, BIG_FALLEN_HEIGHT } = scene.test4;
  let heldUntil = -1, maxTilt = 0, maxPenetration = 0;
  const tally = { steps: 0, finite: true };
  for (let i = 0, n = stepsFor(options); i < n; ++i) {
    stack.step();
    const p = stack.bigCentre();
    if (!finite(p)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    const time = tally.steps * options.step;
    if (heldUntil < 0 && (Math.hypot(p[0], p[2]) > SIDEWAYS_LIMIT || p[1] < BIG_FALLEN_HEIGHT)) heldUntil = time;
    maxTilt = Math.max(maxTilt, stack.bigTiltDegrees());
    maxPenetration = Math.max(maxPenetration, stack.deepestPenetration());
  }
  const held = heldUntil < 0 && tally.finite;
  metrics.set('big_mass', bigMass);
  metrics.set('seconds_held', held ? tally.steps * options.step : Math.max(heldUntil, 0));
  metrics.set('held', held ? 1 : 0);
  metrics.set('max_tilt_degrees', maxTilt);
  metrics.set('max_penetration', maxPenetration);
  return tally;
}

// An engine whose launch reads back at least this share of the asked speed
// launched at it (float32 rounds a speed by 6e-8 of it); below, the engine
// clamped the speed.
const UNCLAMPED_SHARE = 1 - 1e-6;

// test10: one launch, stepped until test10's rule decides it.
// `cube`: {step(), cubeCentre(), cubeVelocityX()}, and launchedVelocityX
// where the engine may clamp the launch (Rapier): the speed it really starts
// at. A clamped launch is noted in tally.clampedTo (the lowest speed reached).
function launchAndResolve(makeLaunch, options, velocity, tally) {
  const t = scene.test10;
  const half = t.CUBE_SIDE / 2, farFace = t.WALL_X + t.WALL_THICKNESS / 2;
  const cube = makeLaunch(velocity);
  const launched = cube.launchedVelocityX === undefined ? velocity : cube.launchedVelocityX;
  const clamped = launched < velocity * UNCLAMPED_SHARE;
  if (clamped) tally.clampedTo = Math.min(tally.clampedTo ?? Infinity, launched);
  const reachSeconds = (farFace + half - t.LAUNCH_X) / (clamped ? launched : velocity);
  try {
    for (let steps = 1; ; ++steps) {
      cube.step();
      ++tally.steps;
      const p = cube.cubeCentre();
      const vx = cube.cubeVelocityX();
      if (!finite(p) || !Number.isFinite(vx)) return 'blew-up';
      if (p[0] - half > farFace) return 'passed';
      if (vx <= 0 && p[0] < t.WALL_X) return 'stopped';
      if (steps * options.step > reachSeconds + t.SETTLE_SECONDS) return p[0] > farFace ? 'passed' : 'stopped';
    }
  } finally {
    if (cube.dispose) cube.dispose();
  }
}

// test10: one launch at --velocity, or the scan for the highest velocity with
// every launch up to it stopped.
function measureWall(makeLaunch, options, metrics) {
  const t = scene.test10;
  const tally = { steps: 0, finite: true };
  let launched = 0, stopped = 0, passed = 0;
  const run = (velocity) => {
    const outcome = launchAndResolve(makeLaunch, options, velocity, tally);
    ++launched;
    if (outcome === 'stopped') ++stopped;
    if (outcome === 'passed') ++passed;
    if (outcome === 'blew-up') tally.finite = false;
    return outcome;
  };
  const half = t.CUBE_SIDE / 2;
  metrics.set('launch_velocity', options.findMaxVelocity ? 0 : options.velocity);
  metrics.set('geometric_prediction', (half + t.WALL_THICKNESS) / options.step);
  metrics.set('guaranteed_stop_velocity', (half + t.WALL_THICKNESS / 2) / options.step);
  metrics.set('ccd', options.ccd ? 1 : 0);
  // The scene as built, under test10's names (reportScene in the shared header).
  metrics.set('cube_half_size_m', t.CUBE_HALF_SIZE);
  metrics.set('cube_mass_kg', t.CUBE_MASS);
  metrics.set('wall_thickness_m', t.WALL_THICKNESS);
  metrics.set('wall_x_m', t.WALL_X);
  metrics.set('wall_height_m', t.WALL_HEIGHT);
  metrics.set('wall_width_m', t.WALL_WIDTH);
  metrics.set('launch_x_m', t.LAUNCH_X);
  metrics.set('launch_y_m', t.LAUNCH_Y);
  metrics.set('ground_y_m', t.GROUND_Y);
  if (!options.findMaxVelocity) {
    run(options.velocity);
  } else {
    let maxVelocity = 0, firstFailure = 0, tested = 0;
    for (let v = scan.FINE_STEP; v <= t.SCAN_LIMIT * (1 + 1e-12);
      v = v < scan.FINE_LIMIT ? v + scan.FINE_STEP : v * (1 + scan.COARSE_RATIO)) {
      const outcome = run(v);
      if (outcome === 'blew-up') break;
      ++tested;
      if (outcome !== 'stopped') {
        firstFailure = v;
        break;
      }
      maxVelocity = v;
    }
    metrics.set('max_velocity', maxVelocity);
    metrics.set('max_velocity_resolution', maxVelocity < scan.FINE_LIMIT ? scan.FINE_STEP : maxVelocity * scan.COARSE_RATIO);
    metrics.set('first_failure_velocity', firstFailure);
    metrics.set('tested_velocities', tested);
  }
  // A launch the engine clamped (Rapier above 4e5 m/s) never happened at the
  // asked speed: the metrics name the speed reached and say so, so that no
  // reader counts a 4e5 m/s stop as one at 1e7 m/s.
  if (tally.clampedTo !== undefined) {
    if (!options.findMaxVelocity) metrics.set('launch_velocity', tally.clampedTo);
    metrics.set('launch_velocity_asked', options.findMaxVelocity ? 0 : options.velocity);
    metrics.set('launch_velocity_clamped', 1);
  }
  metrics.set('launches', launched);
  metrics.set('stopped', stopped);
  metrics.set('passed_through', passed);
  return tally;
}

// The mean cost per step over the last `window` simulated seconds
// (tests/shared/StepCostWindow.h).
class StepCostWindow {
  constructor(window) {
    this.window = window;
    this.samples = [];
    this.sum = 0;
  }
  add(time, seconds) {
    this.samples.push([time, seconds]);
    this.sum += seconds;
    while (this.samples.length && this.samples[0][0] <= time - this.window) this.sum -= this.samples.shift()[1];
  }
  meanMilliseconds() {
    return this.samples.length ? (1000 * this.sum) / this.samples.length : 0;
  }
}

// test5: plates dropped every spawn interval (6 m up, or 1 m above the stack
// once it nears that, and clear of plates still falling) until the plate
// count is reached; a plate has landed once older than LANDING_MIN_AGE and
// slower than LANDED_SPEED (peers/Measurements.cpp's measurePlates).
// `stack`: {step(), dropPlate(height), count(), plateCentre(i), plateSpeed(i), plateYawDegrees(i)}.
function measurePlates(stack, options, metrics) {
  const t = scene.test5;
  const limit = options.plates || t.DEFAULT_PLATES;
  const interval = options.spawnInterval || t.DEFAULT_SPAWN_INTERVAL;
  const bornAt = [], landed = [];
  let firstInAir = 0, nextSpawn = 0;
  const wallCost = new StepCostWindow(t.COST_WINDOW), cpuCost = new StepCostWindow(t.COST_WINDOW);
  const stackHeight = () => {
    let top = 0;
    for (let i = 0; i < stack.count(); ++i) if (landed[i]) top = Math.max(top, stack.plateCentre(i)[1] + t.PLATE_THICKNESS / 2);
    return top;
  };
  const tally = { steps: 0, finite: true };
  let lastCpu = process.cpuUsage();
  for (let n = stepsFor(options); tally.steps < n;) {
    const before = performance.now();
    stack.step();
    const wall = (performance.now() - before) / 1000;
    ++tally.steps;
    const time = tally.steps * options.step;
    const cpu = process.cpuUsage(lastCpu);
    lastCpu = process.cpuUsage();
    wallCost.add(time, wall);
    cpuCost.add(time, (cpu.user + cpu.system) / 1e6);
    for (let i = firstInAir; i < landed.length; ++i)
      if (!landed[i] && time - bornAt[i] >= t.LANDING_MIN_AGE && stack.plateSpeed(i) <= t.LANDED_SPEED) landed[i] = true;
    while (firstInAir < landed.length && landed[firstInAir]) ++firstInAir;
    if (stack.count() < limit && time >= nextSpawn) {
      let height = Math.max(t.SPAWN_HEIGHT, stackHeight() + t.SPAWN_ABOVE_STACK);
      for (let i = 0; i < stack.count(); ++i) if (!landed[i]) height = Math.max(height, stack.plateCentre(i)[1] + t.MIN_SPAWN_SEPARATION);
      stack.dropPlate(height);
      bornAt.push(time);
      landed.push(false);
      nextSpawn += interval;
    }
    let finiteNow = true;
    for (let i = 0; i < stack.count(); ++i) finiteNow = finiteNow && finite(stack.plateCentre(i));
    if (!finiteNow) {
      tally.finite = false;
      break;
    }
  }
  let offset = 0, twist = 0;
  for (let i = 0; i < stack.count(); ++i) {
    const p = stack.plateCentre(i);
    offset = Math.max(offset, Math.hypot(p[0], p[2]));
    const yaw = Math.abs(stack.plateYawDegrees(i)) % 90;  // square plates: 0 to 45 degrees
    twist = Math.max(twist, Math.min(yaw, 90 - yaw));
  }
  metrics.set('plates', stack.count());
  metrics.set('landed_plates', landed.filter(Boolean).length);
  metrics.set('ms_per_step', wallCost.meanMilliseconds());
  metrics.set('cpu_ms_per_step', cpuCost.meanMilliseconds());
  metrics.set('max_axis_offset', offset);
  metrics.set('stack_height', stackHeight());
  metrics.set('plate_thickness_m', t.PLATE_THICKNESS);
  metrics.set('max_twist_degrees', twist);
  metrics.set('plates_frozen_in_air', 0);  // sleeping is off: nothing freezes
  metrics.set('auto_disable', 0);
  metrics.set('threads', 1);
  return tally;
}

// test3: whether the chain completes (every domino past FALLEN_TILT_DEGREES),
// when the last one fell, and how many bodies are awake at the end.
// `chain`: {step(), count, tiltDegrees(i), activeBodies(), sleeps}.
function measureChain(chain, options, metrics) {
  const { FALLEN_TILT_DEGREES } = scene.test3;
  const fellAt = new Array(chain.count).fill(-1);
  const tally = { steps: 0, finite: true };
  for (let n = stepsFor(options); tally.steps < n;) {
    chain.step();
    ++tally.steps;
    for (let i = 0; i < chain.count; ++i) {
      const tilt = chain.tiltDegrees(i);
      if (!Number.isFinite(tilt)) tally.finite = false;
      if (fellAt[i] < 0 && tilt > FALLEN_TILT_DEGREES) fellAt[i] = tally.steps * options.step;
    }
    if (!tally.finite) break;
  }
  let fallen = 0, last = 0, leastTilt = 180;
  for (let i = 0; i < chain.count; ++i) {
    if (fellAt[i] < 0) continue;
    ++fallen;
    last = Math.max(last, fellAt[i]);
    leastTilt = Math.min(leastTilt, chain.tiltDegrees(i));
  }
  metrics.set('dominoes', chain.count);
  metrics.set('fallen_fraction', chain.count ? fallen / chain.count : 0);
  metrics.set('chain_seconds', last);
  metrics.set('active_bodies', chain.activeBodies());
  metrics.set('auto_disable', chain.sleeps ? 1 : 0);
  metrics.set('min_fallen_tilt_degrees', fallen ? leastTilt : 0);
  return tally;
}

// The test cube is past the pivot, level with it: beyond the pivot's far
// face in x while its outline overlaps the pivot's in y and z. A cube thrown
// at the pivot gets there only through it (a contact too soft to stop it).
function beyondPivot(pivot, cube) {
  const { PIVOT_SIDE, TEST_CUBE_SIDE } = scene.test7;
  const touching = (PIVOT_SIDE + TEST_CUBE_SIDE) / 2;
  return cube[0] - pivot[0] > touching && Math.abs(cube[1] - pivot[1]) < touching && Math.abs(cube[2] - pivot[2]) < touching;
}

// test7: the largest ball-joint error and the pivot's largest spin while the
// test cube is thrown at 0, S, 2S, ... (test7's headless run).
// `pair`: {step(), throwCube(), jointError(), pivotAngularSpeed(), pivotCentre(), testCubeCentre()},
// built with the first throw made.
function measureJoints(pair, options, metrics) {
  const { DEFAULT_THROWS, DEFAULT_THROW_INTERVAL } = scene.test7;
  const throwEvery = lround(DEFAULT_THROW_INTERVAL / options.step);
  let throws = 1, maxError = 0, maxSpin = 0, passed = false;
  const tally = { steps: 0, finite: true };
  for (let i = 0, n = stepsFor(options); i < n; ++i) {
    if (i > 0 && i % throwEvery === 0 && throws < DEFAULT_THROWS) {
      pair.throwCube();
      ++throws;
    }
    pair.step();
    const error = pair.jointError(), spin = pair.pivotAngularSpeed();
    if (!Number.isFinite(error) || !Number.isFinite(spin)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    maxError = Math.max(maxError, error);
    maxSpin = Math.max(maxSpin, spin);
    passed = passed || beyondPivot(pair.pivotCentre(), pair.testCubeCentre());
  }
  metrics.set('max_joint_error', maxError);
  metrics.set('max_angular_speed', maxSpin);
  metrics.set('max_angular_speed_limit', 0);  // no peer caps the spin (test7's --max-angular-speed 0)
  metrics.set('throws', throws);
  metrics.set('cube_passed_pivot', passed ? 1 : 0);
  return tally;
}

module.exports = { measurePlates, measureChain, measureJoints, measureEnergy, measureElongation, measureBounces, measureHold, measureWall, defaultSeconds, stepsFor };
