'use strict';
// Rapier through its WebAssembly build (@dimforge/rapier3d-compat, float32),
// one world.step() per fixed step with world.timestep = h (default 1/60 s).
//
// In both settings: the ground is a large cuboid (the JS API has no
// half-space); restitution 1.0 on both colliders (Rapier averages them: 1.0);
// Rapier has no damping by default. Its speed cap (every body is clamped to
// 400 m/s times the world's lengthUnit) matters on test10 only: there the
// lengthUnit is raised to 1000 and the two length tolerances the JS API
// exposes (allowed linear error, prediction distance) divided by as much, so
// that in metres they stay Rapier's defaults.
// "best": 50 solver iterations (default 4), except on test2, where more
// iterations lost more energy (50: 1.3% over 20 s at step 0.001, against
// 0.30% with 4), so there best is Rapier's default; on test10 (and with --ccd) the cube has Rapier's CCD on and
// a soft-CCD prediction of twice its travel in a step: the swept CCD alone
// does not stop it at a thin static wall, the predictive contact does.
const { scene, SURFACE_GRAVITY } = require('./constants');
const { plateStack, dominoStarts, tiltDegrees, pendulumMass, kineticEnergy, stackReadout, uprightReadout, throwState, hangingPairReadout } = require('./rigs');
const { ballLayout } = require('./rebound');

const BEST_ITERATIONS = 50;
const GROUND_SIZE = 200;  // m across, 10 m deep, top face at y = 0
const FAST_LENGTH_UNIT = 1000;

async function load() {
  const RAPIER = require('@dimforge/rapier3d-compat');
  await RAPIER.init();
  return RAPIER;
}

const vec = (v) => [v.x, v.y, v.z];

class World {
  constructor(R, gravity, options, { fast = false } = {}) {
    this.R = R;
    this.world = new R.World({ x: 0, y: -gravity, z: 0 });
    this.world.timestep = options.step;
    if (options.setting === 'best' && options.scene !== 'test2') this.world.numSolverIterations = BEST_ITERATIONS;
    if (fast) {
      const p = this.world.integrationParameters;
      const error = p.normalizedAllowedLinearError, prediction = p.normalizedPredictionDistance;
      this.world.lengthUnit = FAST_LENGTH_UNIT;
      p.normalizedAllowedLinearError = error / FAST_LENGTH_UNIT;
      p.normalizedPredictionDistance = prediction / FAST_LENGTH_UNIT;
    }
  }
  // mass 0: fixed. `mass` {mass, inertia, centre} sets the body's mass
  // properties and makes its colliders massless; a number gives the collider that mass.
  body(colliders, mass, position, { restitution, combine, friction, configure } = {}) {
    const R = this.R;
    let desc = (mass ? R.RigidBodyDesc.dynamic() : R.RigidBodyDesc.fixed())
      .setTranslation(...position).setCanSleep(false);
    if (mass && typeof mass === 'object') {
      const [ix, iy, iz] = mass.inertia;
      desc = desc.setAdditionalMassProperties(mass.mass, { x: 0, y: 0, z: 0 }, { x: ix, y: iy, z: iz },
        { x: 0, y: 0, z: 0, w: 1 });
    }
    if (configure) desc = configure(desc);
    const body = this.world.createRigidBody(desc);
    for (const [collider, offset] of colliders) {
      let c = collider.setTranslation(...(offset || [0, 0, 0]));
      if (typeof mass === 'number' && mass > 0) c = c.setMass(mass);
      else if (mass) c = c.setDensity(0);
      if (restitution !== undefined) c = c.setRestitution(restitution);
      if (combine !== undefined) c = c.setRestitutionCombineRule(combine);
      if (friction !== undefined) c = c.setFriction(friction);
      this.world.createCollider(c, body);
    }
    return body;
  }
  ground() {
    return this.body([[this.R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0]);
  }
  step() {
    this.world.step();
  }
  dispose() {
    this.world.free();
  }
}

function pendulum(R, bobMass, options) {
  const { ANCHOR_HEIGHT, ROD_LENGTH, ROD_THICKNESS, BOB_RADIUS } = scene.test2;
  const rig = pendulumMass(bobMass);
  const world = new World(R, SURFACE_GRAVITY, options);
  const body = world.body([
    [R.ColliderDesc.cuboid(ROD_LENGTH / 2, ROD_THICKNESS / 2, ROD_THICKNESS / 2), [rig.rodOffset, 0, 0]],
    [R.ColliderDesc.ball(BOB_RADIUS), [rig.bobOffset, 0, 0]],
  ], rig, [rig.centre, ANCHOR_HEIGHT, 0]);
  const anchor = world.body([], 0, [0, ANCHOR_HEIGHT, 0]);
  const hinge = R.JointData.revolute({ x: 0, y: 0, z: 0 }, { x: -rig.centre, y: 0, z: 0 }, { x: 0, y: 0, z: 1 });
  // An impulse joint in both settings: the multibody joint (generalized
  // coordinates) was tried and lost more energy (4.4% against 0.3% over 5 s
  // at step 0.001).
  world.world.createImpulseJoint(hinge, anchor, body, true);
  return {
    step: () => world.step(),
    centreOfMass: () => vec(body.translation()),
    kineticEnergy: () => {
      const q = body.rotation();
      return kineticEnergy(rig.mass, rig.inertia, vec(body.linvel()), vec(body.angvel()), [q.x, q.y, q.z, q.w]);
    },
    mass: () => rig.mass,
  };
}

function ball(R, options) {
  const { START_HEIGHT, BALL_RADIUS, BALL_MASS, BOUNCE, GRAVITY_FACTOR } = scene.test9;
  const world = new World(R, GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  world.body([[R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0], { restitution: BOUNCE });
  const body = world.body([[R.ColliderDesc.ball(BALL_RADIUS)]], BALL_MASS, [0, START_HEIGHT, 0], { restitution: BOUNCE });
  return { step: () => world.step(), centre: () => vec(body.translation()) };
}

// test1: Rapier averages restitutions unless told otherwise; the balls'
// colliders combine by maximum against the ground's 0, so each contact has
// the ball's own (a collider pair uses the larger of the two rules).
function balls(R, options) {
  const t = scene.test1;
  const world = new World(R, t.GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  world.body([[R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0], { restitution: 0 });
  const bodies = [], bounces = [];
  for (let i = 0; i < t.BALL_COUNT; ++i) {
    const { position, bounce } = ballLayout(i);
    bodies.push(world.body([[R.ColliderDesc.ball(t.BALL_RADIUS)]], t.BALL_MASS, position,
      { restitution: bounce, combine: R.CoefficientCombineRule.Max }));
    bounces.push(bounce);
  }
  return {
    count: bodies.length, bounceVelocity: 0,  // Rapier applies restitution at any speed
    bounce: (i) => bounces[i], step: () => world.step(), centre: (i) => vec(bodies[i].translation()),
    speed: (i) => Math.hypot(...vec(bodies[i].linvel())),
  };
}

// test6: the 5000 kg cube on a spherical impulse joint 2 m above the 1 kg
// cube resting on the ground cuboid, every collider with test6's no-slip friction.
function axisSystem(R, options) {
  const t = scene.test6;
  const world = new World(R, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  world.body([[R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0], { friction });
  const cube = (side) => R.ColliderDesc.cuboid(side / 2, side / 2, side / 2);
  const small = world.body([[cube(t.SMALL_SIDE)]], t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0], { friction });
  const big = world.body([[cube(t.BIG_SIDE)]], t.BIG_MASS, [0, t.ANCHOR_HEIGHT + t.BIG_SIDE / 2, 0], { friction });
  const joint = R.JointData.spherical({ x: 0, y: t.ANCHOR_HEIGHT - t.SMALL_SIDE / 2, z: 0 }, { x: 0, y: -t.BIG_SIDE / 2, z: 0 });
  world.world.createImpulseJoint(joint, small, big, true);
  const rotation = (b) => {
    const q = b.rotation();
    return [q.x, q.y, q.z, q.w];
  };
  return uprightReadout({ step: () => world.step(), position: (b) => vec(b.translation()), rotation }, small, big);
}

// test7: the pivot on a spherical impulse joint to a fixed body at the
// anchor, the big cube on another to the pivot (contacts between the joined
// bodies off, as in the ODE programs), the test cube thrown at the pivot;
// every collider with test7's no-slip friction (Rapier averages: 100).
function hangingPair(R, options) {
  const t = scene.test7;
  const world = new World(R, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  const cube = (side) => R.ColliderDesc.cuboid(side / 2, side / 2, side / 2);
  world.body([[R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0], { friction });
  const pivot = world.body([[cube(t.PIVOT_SIDE)]], t.PIVOT_MASS, [0, t.PIVOT_CENTRE_Y, 0], { friction });
  const big = world.body([[cube(t.BIG_SIDE)]], t.BIG_MASS, [0, t.BIG_CENTRE_Y, 0], { friction });
  const thrown = world.body([[cube(t.TEST_CUBE_SIDE)]], t.TEST_CUBE_MASS, throwState().position, { friction });
  const anchor = world.body([], 0, [0, t.ANCHOR_HEIGHT, 0]);
  const joint = (a, b, inA, inB) => world.world.createImpulseJoint(R.JointData.spherical(
    { x: inA[0], y: inA[1], z: inA[2] }, { x: inB[0], y: inB[1], z: inB[2] }), a, b, true).setContactsEnabled(false);
  joint(anchor, pivot, [0, 0, 0], [0, t.PIVOT_SIDE / 2, 0]);
  joint(pivot, big, [0, -t.PIVOT_SIDE / 2, 0], [0, t.BIG_SIDE / 2, 0]);
  const throwCube = () => {
    const { position, velocity } = throwState();
    thrown.setTranslation({ x: position[0], y: position[1], z: position[2] }, true);
    thrown.setRotation({ x: 0, y: 0, z: 0, w: 1 }, true);
    thrown.setLinvel({ x: velocity[0], y: velocity[1], z: velocity[2] }, true);
    thrown.setAngvel({ x: 0, y: 0, z: 0 }, true);
  };
  throwCube();
  const rotation = (b) => {
    const q = b.rotation();
    return [q.x, q.y, q.z, q.w];
  };
  return hangingPairReadout({ step: () => world.step(), position: (b) => vec(b.translation()), rotation,
    spin: (b) => vec(b.angvel()) }, pivot, big, thrown, throwCube);
}

// test3: the domino spiral, friction 1.0 (average: 1.0), Rapier's own
// sleeping on (its thresholds are not exposed in the JS API).
function dominoes(R, options) {
  const t = scene.test3;
  const world = new World(R, SURFACE_GRAVITY, options);
  const friction = t.DEFAULT_MU;
  world.body([[R.ColliderDesc.cuboid(GROUND_SIZE / 2, 5, GROUND_SIZE / 2)]], 0, [0, -5, 0], { friction });
  const bodies = dominoStarts(t.DEFAULT_DOMINOES).map((d) => world.body(
    [[R.ColliderDesc.cuboid(t.DOMINO_THICKNESS / 2, t.DOMINO_HEIGHT / 2, t.DOMINO_WIDTH / 2)]], t.DOMINO_MASS, d.centre, {
      friction,
      configure: (desc) => desc.setCanSleep(true)
        .setRotation({ x: d.rotation[0], y: d.rotation[1], z: d.rotation[2], w: d.rotation[3] })
        .setLinvel(...d.velocity).setAngvel({ x: d.spin[0], y: d.spin[1], z: d.spin[2] }),
    }));
  return {
    step: () => world.step(), count: bodies.length, sleeps: true,
    tiltDegrees: (i) => {
      const q = bodies[i].rotation();
      return tiltDegrees([q.x, q.y, q.z, q.w]);
    },
    activeBodies: () => bodies.filter((b) => !b.isSleeping()).length,
  };
}

// test5: plates dropped onto the platform, every collider with test5's no-slip friction.
function plates(R, options) {
  const t = scene.test5;
  const world = new World(R, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  world.body([[R.ColliderDesc.cuboid(t.PLATFORM_SIDE / 2, t.PLATFORM_THICKNESS / 2, t.PLATFORM_SIDE / 2)]], 0,
    [0, -t.PLATFORM_THICKNESS / 2, 0], { friction });
  const rotation = (b) => {
    const q = b.rotation();
    return [q.x, q.y, q.z, q.w];
  };
  return plateStack({ step: () => world.step(), position: (b) => vec(b.translation()), rotation, velocity: (b) => vec(b.linvel()) },
    (height) => world.body([[R.ColliderDesc.cuboid(t.PLATE_WIDTH / 2, t.PLATE_THICKNESS / 2, t.PLATE_WIDTH / 2)]], t.PLATE_MASS,
      [0, height, 0], { friction }));
}

function stack(R, bigMass, options) {
  const t = scene.test4;
  const world = new World(R, SURFACE_GRAVITY, options);
  const cuboid = (side) => R.ColliderDesc.cuboid(side / 2, side / 2, side / 2);
  world.body([[R.ColliderDesc.cuboid(t.PLATFORM_SIDE / 2, t.PLATFORM_THICKNESS / 2, t.PLATFORM_SIDE / 2)]], 0,
    [0, -t.PLATFORM_THICKNESS / 2, 0]);
  const small = world.body([[cuboid(t.SMALL_SIDE)]], t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0]);
  const big = world.body([[cuboid(t.BIG_SIDE)]], bigMass, [0, t.BIG_START_HEIGHT, 0]);
  const rotation = (b) => {
    const q = b.rotation();
    return [q.x, q.y, q.z, q.w];
  };
  return stackReadout({ step: () => world.step(), position: (b) => vec(b.translation()),
    transform: (b) => [vec(b.translation()), rotation(b)] }, small, big);
}

// The speed Rapier lets the cube have when launched at `velocity`: it
// clamps every body's speed in its step (400 m/s times the lengthUnit, so
// 4e5 m/s here), not when the velocity is set, so the value set reads back
// unclamped. One step of the lone cube, without gravity, in a world with
// the launch's parameters reads back what the launch really starts at.
function reachedSpeed(R, velocity, options) {
  const t = scene.test10;
  const half = t.CUBE_SIDE / 2;
  const probe = new World(R, 0, options, { fast: true });
  const cube = probe.body([[R.ColliderDesc.cuboid(half, half, half)]], t.CUBE_MASS, [0, 0, 0], {
    configure: (desc) => desc.setLinvel(velocity, 0, 0),
  });
  probe.step();
  const reached = cube.linvel().x;
  probe.dispose();
  return reached;
}

function launch(R, velocity, options) {
  const t = scene.test10;
  const reached = reachedSpeed(R, velocity, options);
  const world = new World(R, SURFACE_GRAVITY, options, { fast: true });
  world.ground();
  world.body([[R.ColliderDesc.cuboid(t.WALL_THICKNESS / 2, t.WALL_HEIGHT / 2, t.WALL_WIDTH / 2)]], 0,
    [t.WALL_X, t.WALL_HEIGHT / 2, 0]);
  const half = t.CUBE_SIDE / 2;
  const sweep = options.ccd || options.setting === 'best';
  const start = Math.min(velocity, reached);  // the speed the cube has from its first step on
  const cube = world.body([[R.ColliderDesc.cuboid(half, half, half)]], t.CUBE_MASS, [t.LAUNCH_X, t.LAUNCH_Y, t.LAUNCH_Z], {
    configure: (desc) => (sweep ? desc.setCcdEnabled(true).setSoftCcdPrediction(2 * start * options.step) : desc)
      .setLinvel(start, 0, 0),
  });
  return {
    launchedVelocityX: reached,
    step: () => world.step(),
    cubeCentre: () => vec(cube.translation()),
    cubeVelocityX: () => cube.linvel().x,
    dispose: () => world.dispose(),
  };
}

function settingText(options) {
  const best = options.setting === 'best';
  let text = `world.step() with timestep h, ${options.scene === 'test3' ? '' : 'sleeping off, '}no damping; `;
  text += best && options.scene !== 'test2' ? '50 solver iterations' : "Rapier's defaults (4 solver iterations)";
  if (options.scene === 'test2' || options.scene === 'test8') text += ', impulse revolute joint';
  if (options.scene === 'test9') text += '; restitution 1.0 on both colliders (average: 1.0), ground a 200 m cuboid';
  if (options.scene === 'test1') text += "; each ball's restitution combined by maximum with the ground's 0, ground a 200 m cuboid";
  if (options.scene === 'test5') text += '; friction 100 on every collider (test5\'s never-sliding contacts)';
  if (options.scene === 'test3') text += "; friction 1.0, Rapier's own sleeping (thresholds not exposed), ground a 200 m cuboid";
  if (options.scene === 'test6') text += '; friction 100 on every collider (test6\'s never-sliding contacts)';
  if (options.scene === 'test7') text += '; spherical impulse joints, friction 100 on every collider, ground a 200 m cuboid';
  if (options.scene === 'test10') {
    text += '; lengthUnit 1000 with the length tolerances divided by 1000 (speed cap 400 km/s)';
    text += options.ccd || best ? '; cube: CCD on, soft-CCD prediction 2 v h' : '; no CCD';
  }
  return text;
}

module.exports = { name: 'rapier', packageName: '@dimforge/rapier3d-compat', hasContinuousCollision: true, load, settingText, plateStack: plates, dominoes, balls, axisSystem, hangingPair, pendulum, ball, stack, launch };
