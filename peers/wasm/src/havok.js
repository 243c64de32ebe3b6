'use strict';
// Havok through its WebAssembly build (@babylonjs/havok: today's Havok for
// the web, float32; not the Havok 6.5 the thesis quotes), driven by the raw
// HP_ API so that one HP_World_Step is one fixed step of h.
//
// What every setting does (each changes a figure silently otherwise):
// - the speed limit (200 m/s linear, 100 rad/s angular by default) is raised
//   out of reach, so a launch is never slowed by it;
// - Havok has no plane: the ground is a box 200 m across, its top at y = 0;
// - no CCD switch and no iteration count exist: its speculative contacts are
//   always on, in both settings;
// - restitution 1.0 on both shapes: Havok combines them by geometric mean, 1.
// "best" also sets the solver's ideal step to h (by default it is tuned for
// 1/60 s and rescaled for other steps) and the angular damping to 0
// (default 0.1).
const fs = require('fs');
const { scene, SURFACE_GRAVITY } = require('./constants');
const { plateStack, dominoStarts, tiltDegrees, pendulumMass, kineticEnergy, stackReadout, uprightReadout, launchedCube, throwState, hangingPairReadout } = require('./rigs');
const { ballLayout } = require('./rebound');

const NO_SPEED_LIMIT = 1e9;  // m/s and rad/s: far beyond the scan's 100 000 m/s
const GROUND_SIZE = 200;     // m across, 10 m deep, top face at y = 0
const IDENTITY = [0, 0, 0, 1];

async function load() {
  const HavokPhysics = require('@babylonjs/havok');
  const wasmBinary = fs.readFileSync(require.resolve('@babylonjs/havok/lib/umd/HavokPhysics.wasm'));
  return HavokPhysics({ wasmBinary });
}

function check(result, what) {
  const status = Array.isArray(result) ? result[0] : result;
  if (status !== undefined && status.value !== undefined && status.value !== 0) throw new Error(`${what} failed`);
  return Array.isArray(result) ? result[1] : undefined;
}

class World {
  constructor(HK, gravity, options) {
    this.HK = HK;
    this.h = options.step;
    this.best = options.setting === 'best';
    this.id = check(HK.HP_World_Create(), 'HP_World_Create');
    check(HK.HP_World_SetGravity(this.id, [0, -gravity, 0]), 'HP_World_SetGravity');
    check(HK.HP_World_SetSpeedLimit(this.id, NO_SPEED_LIMIT, NO_SPEED_LIMIT), 'HP_World_SetSpeedLimit');
    if (this.best) check(HK.HP_World_SetIdealStepTime(this.id, this.h), 'HP_World_SetIdealStepTime');
    this.owned = [];
  }
  box(size) {
    return check(this.HK.HP_Shape_CreateBox([0, 0, 0], IDENTITY, size), 'HP_Shape_CreateBox');
  }
  sphere(radius) {
    return check(this.HK.HP_Shape_CreateSphere([0, 0, 0], radius), 'HP_Shape_CreateSphere');
  }
  // A body at `position`. mass 0: static. inertia: principal moments (kg m^2)
  // about the centre, or left to Havok (computed from the shape).
  body(shape, mass, position, inertia) {
    const HK = this.HK;
    const id = check(HK.HP_Body_Create(), 'HP_Body_Create');
    if (shape) check(HK.HP_Body_SetShape(id, shape), 'HP_Body_SetShape');
    check(HK.HP_Body_SetMotionType(id, mass > 0 ? HK.MotionType.DYNAMIC : HK.MotionType.STATIC), 'HP_Body_SetMotionType');
    if (mass > 0) {
      const built = check(HK.HP_Shape_BuildMassProperties(shape), 'HP_Shape_BuildMassProperties');
      const perUnitMass = inertia ? inertia.map((i) => i / mass) : built[2];
      check(HK.HP_Body_SetMassProperties(id, [[0, 0, 0], mass, perUnitMass, IDENTITY]), 'HP_Body_SetMassProperties');
      if (this.best) check(HK.HP_Body_SetAngularDamping(id, 0), 'HP_Body_SetAngularDamping');
    }
    check(HK.HP_Body_SetQTransform(id, [position, IDENTITY]), 'HP_Body_SetQTransform');
    check(HK.HP_World_AddBody(this.id, id, false), 'HP_World_AddBody');
    // Sleeping off, as in every peer: a body put to sleep would hide what is measured.
    if (mass > 0) check(HK.HP_Body_SetActivationControl(id, HK.ActivationControl.ALWAYS_ACTIVE), 'HP_Body_SetActivationControl');
    this.owned.push(id);
    return id;
  }
  // Friction as Havok's default (0.5); `combine`: how Havok joins two
  // shapes' restitutions (its default: the geometric mean).
  restitution(shape, value, combine = 'GEOMETRIC_MEAN') {
    const HK = this.HK;
    check(HK.HP_Shape_SetMaterial(shape, [0.5, 0.5, value, HK.MaterialCombine.GEOMETRIC_MEAN,
      HK.MaterialCombine[combine]]), 'HP_Shape_SetMaterial');
  }
  // Friction `value` (static and dynamic), restitution 0; combined by geometric mean.
  friction(shape, value) {
    const HK = this.HK;
    check(HK.HP_Shape_SetMaterial(shape, [value, value, 0, HK.MaterialCombine.GEOMETRIC_MEAN,
      HK.MaterialCombine.GEOMETRIC_MEAN]), 'HP_Shape_SetMaterial');
    return shape;
  }
  ground() {
    return this.body(this.box([GROUND_SIZE, 10, GROUND_SIZE]), 0, [0, -5, 0]);
  }
  step() {
    this.HK.HP_World_Step(this.id, this.h);
  }
  transform(body) {
    return this.HK.HP_Body_GetQTransform(body)[1];
  }
  position(body) {
    return this.transform(body)[0];
  }
  velocity(body) {
    return this.HK.HP_Body_GetLinearVelocity(body)[1];
  }
  spin(body) {
    return this.HK.HP_Body_GetAngularVelocity(body)[1];
  }
  dispose() {
    this.HK.HP_World_Release(this.id);
  }
}

// test2 / test8: the rod and the bob as one body (a container shape) hinged
// to a static body at the anchor: a 6-DOF constraint with every axis locked
// but the rotation about z.
function pendulum(HK, bobMass, options) {
  const { ANCHOR_HEIGHT, ROD_LENGTH, ROD_THICKNESS, BOB_RADIUS } = scene.test2;
  const rig = pendulumMass(bobMass);
  const world = new World(HK, SURFACE_GRAVITY, options);
  const container = check(HK.HP_Shape_CreateContainer(), 'HP_Shape_CreateContainer');
  HK.HP_Shape_AddChild(container, world.box([ROD_LENGTH, ROD_THICKNESS, ROD_THICKNESS]), [[rig.rodOffset, 0, 0], IDENTITY, [1, 1, 1]]);
  HK.HP_Shape_AddChild(container, world.sphere(BOB_RADIUS), [[rig.bobOffset, 0, 0], IDENTITY, [1, 1, 1]]);
  const body = world.body(container, rig.mass, [rig.centre, ANCHOR_HEIGHT, 0], rig.inertia);
  const anchor = world.body(null, 0, [0, ANCHOR_HEIGHT, 0]);
  const hinge = check(HK.HP_Constraint_Create(), 'HP_Constraint_Create');
  HK.HP_Constraint_SetParentBody(hinge, anchor);
  HK.HP_Constraint_SetChildBody(hinge, body);
  // The constraint's x axis is the hinge (world z), its y axis world x.
  HK.HP_Constraint_SetAnchorInParent(hinge, [0, 0, 0], [0, 0, 1], [1, 0, 0]);
  HK.HP_Constraint_SetAnchorInChild(hinge, [-rig.centre, 0, 0], [0, 0, 1], [1, 0, 0]);
  const A = HK.ConstraintAxis, LOCKED = HK.ConstraintAxisLimitMode.LOCKED;
  for (const axis of [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_Y, A.ANGULAR_Z])
    HK.HP_Constraint_SetAxisMode(hinge, axis, LOCKED);
  HK.HP_Constraint_SetAxisMode(hinge, A.ANGULAR_X, HK.ConstraintAxisLimitMode.FREE);
  HK.HP_Constraint_SetCollisionsEnabled(hinge, false);
  HK.HP_Constraint_SetEnabled(hinge, true);
  return {
    step: () => world.step(),
    centreOfMass: () => world.position(body),
    kineticEnergy: () => kineticEnergy(rig.mass, rig.inertia, world.velocity(body), world.spin(body), world.transform(body)[1]),
    mass: () => rig.mass,
  };
}

// test9: the ball on the ground box, restitution 1.0 on both.
function ball(HK, options) {
  const { START_HEIGHT, BALL_RADIUS, BALL_MASS, BOUNCE, GRAVITY_FACTOR } = scene.test9;
  const world = new World(HK, GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  const groundShape = world.box([GROUND_SIZE, 10, GROUND_SIZE]);
  const ballShape = world.sphere(BALL_RADIUS);
  world.restitution(groundShape, BOUNCE);
  world.restitution(ballShape, BOUNCE);
  world.body(groundShape, 0, [0, -5, 0]);
  const body = world.body(ballShape, BALL_MASS, [0, START_HEIGHT, 0]);
  return { step: () => world.step(), centre: () => world.position(body) };
}

// test1: fifty balls, ball i with restitution i/49, over the ground box. The
// ground's restitution is 1 and both combine by minimum, so each contact has
// the ball's own (the geometric mean would give sqrt(e)).
function balls(HK, options) {
  const t = scene.test1;
  const world = new World(HK, t.GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  const groundShape = world.box([GROUND_SIZE, 10, GROUND_SIZE]);
  world.restitution(groundShape, 1, 'MINIMUM');
  world.body(groundShape, 0, [0, -5, 0]);
  const bodies = [], bounces = [];
  for (let i = 0; i < t.BALL_COUNT; ++i) {
    const { position, bounce } = ballLayout(i);
    const shape = world.sphere(t.BALL_RADIUS);
    world.restitution(shape, bounce, 'MINIMUM');
    bodies.push(world.body(shape, t.BALL_MASS, position));
    bounces.push(bounce);
  }
  return {
    count: bodies.length, bounceVelocity: NaN,  // Havok states no restitution threshold
    bounce: (i) => bounces[i], step: () => world.step(), centre: (i) => world.position(bodies[i]),
    speed: (i) => Math.hypot(...world.velocity(bodies[i])),
  };
}

// test6: the 5000 kg cube on a ball joint 2 m above the 1 kg cube resting
// on the ground box, every shape with test6's no-slip friction.
function axisSystem(HK, options) {
  const t = scene.test6;
  const world = new World(HK, SURFACE_GRAVITY, options);
  const box = (size) => world.friction(world.box(size), scene.top.NO_SLIP_FRICTION);
  world.body(box([GROUND_SIZE, 10, GROUND_SIZE]), 0, [0, -5, 0]);
  const small = world.body(box([t.SMALL_SIDE, t.SMALL_SIDE, t.SMALL_SIDE]), t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0]);
  const big = world.body(box([t.BIG_SIDE, t.BIG_SIDE, t.BIG_SIDE]), t.BIG_MASS, [0, t.ANCHOR_HEIGHT + t.BIG_SIDE / 2, 0]);
  ballJoint(HK, small, big, [0, t.ANCHOR_HEIGHT - t.SMALL_SIDE / 2, 0], [0, -t.BIG_SIDE / 2, 0]);
  return uprightReadout({ step: () => world.step(), position: (b) => world.position(b),
    rotation: (b) => world.transform(b)[1] }, small, big);
}

// A ball joint: every linear axis locked, every angular one free; the two
// bodies do not collide with each other (as in the ODE programs).
function ballJoint(HK, parent, child, inParent, inChild) {
  const joint = check(HK.HP_Constraint_Create(), 'HP_Constraint_Create');
  HK.HP_Constraint_SetParentBody(joint, parent);
  HK.HP_Constraint_SetChildBody(joint, child);
  HK.HP_Constraint_SetAnchorInParent(joint, inParent, [1, 0, 0], [0, 1, 0]);
  HK.HP_Constraint_SetAnchorInChild(joint, inChild, [1, 0, 0], [0, 1, 0]);
  const A = HK.ConstraintAxis;
  for (const axis of [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z]) HK.HP_Constraint_SetAxisMode(joint, axis, HK.ConstraintAxisLimitMode.LOCKED);
  for (const axis of [A.ANGULAR_X, A.ANGULAR_Y, A.ANGULAR_Z]) HK.HP_Constraint_SetAxisMode(joint, axis, HK.ConstraintAxisLimitMode.FREE);
  HK.HP_Constraint_SetCollisionsEnabled(joint, false);
  HK.HP_Constraint_SetEnabled(joint, true);
  return joint;
}

// test7: the pivot on a ball joint to a static body at the anchor, the big
// cube on a ball joint to the pivot, the test cube thrown at the pivot;
// every shape with test7's no-slip friction.
function hangingPair(HK, options) {
  const t = scene.test7;
  const world = new World(HK, SURFACE_GRAVITY, options);
  const box = (side) => world.friction(world.box([side, side, side]), scene.top.NO_SLIP_FRICTION);
  world.body(world.friction(world.box([GROUND_SIZE, 10, GROUND_SIZE]), scene.top.NO_SLIP_FRICTION), 0, [0, -5, 0]);
  const pivot = world.body(box(t.PIVOT_SIDE), t.PIVOT_MASS, [0, t.PIVOT_CENTRE_Y, 0]);
  const big = world.body(box(t.BIG_SIDE), t.BIG_MASS, [0, t.BIG_CENTRE_Y, 0]);
  const cube = world.body(box(t.TEST_CUBE_SIDE), t.TEST_CUBE_MASS, throwState().position);
  const anchor = world.body(null, 0, [0, t.ANCHOR_HEIGHT, 0]);
  ballJoint(HK, anchor, pivot, [0, 0, 0], [0, t.PIVOT_SIDE / 2, 0]);
  ballJoint(HK, pivot, big, [0, -t.PIVOT_SIDE / 2, 0], [0, t.BIG_SIDE / 2, 0]);
  const throwCube = () => {
    const { position, velocity } = throwState();
    HK.HP_Body_SetQTransform(cube, [position, IDENTITY]);
    HK.HP_Body_SetLinearVelocity(cube, velocity);
    HK.HP_Body_SetAngularVelocity(cube, [0, 0, 0]);
  };
  throwCube();
  return hangingPairReadout({ step: () => world.step(), position: (b) => world.position(b),
    rotation: (b) => world.transform(b)[1], spin: (b) => world.spin(b) }, pivot, big, cube, throwCube);
}

// test3: the domino spiral, friction 1.0 (geometric mean: 1.0), Havok's own
// sleeping on (its thresholds are not exposed: test3's 0.1 cannot be set).
function dominoes(HK, options) {
  const t = scene.test3;
  const world = new World(HK, SURFACE_GRAVITY, options);
  world.body(world.friction(world.box([GROUND_SIZE, 10, GROUND_SIZE]), t.DEFAULT_MU), 0, [0, -5, 0]);
  const bodies = dominoStarts(t.DEFAULT_DOMINOES).map((d) => {
    const shape = world.friction(world.box([t.DOMINO_THICKNESS, t.DOMINO_HEIGHT, t.DOMINO_WIDTH]), t.DEFAULT_MU);
    const id = world.body(shape, t.DOMINO_MASS, d.centre);
    HK.HP_Body_SetQTransform(id, [d.centre, d.rotation]);
    HK.HP_Body_SetLinearVelocity(id, d.velocity);
    HK.HP_Body_SetAngularVelocity(id, d.spin);
    HK.HP_Body_SetActivationControl(id, HK.ActivationControl.SIMULATION_CONTROLLED);
    return id;
  });
  return {
    step: () => world.step(), count: bodies.length, sleeps: true,
    tiltDegrees: (i) => tiltDegrees(world.transform(bodies[i])[1]),
    activeBodies: () => bodies.filter((b) => HK.HP_Body_GetActivationState(b)[1] === HK.ActivationState.ACTIVE).length,
  };
}

// test5: plates dropped onto the platform, every shape with test5's no-slip friction.
function plates(HK, options) {
  const t = scene.test5;
  const world = new World(HK, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  world.body(world.friction(world.box([t.PLATFORM_SIDE, t.PLATFORM_THICKNESS, t.PLATFORM_SIDE]), friction), 0,
    [0, -t.PLATFORM_THICKNESS / 2, 0]);
  return plateStack({ step: () => world.step(), position: (b) => world.position(b), rotation: (b) => world.transform(b)[1],
    velocity: (b) => world.velocity(b) },
  (height) => world.body(world.friction(world.box([t.PLATE_WIDTH, t.PLATE_THICKNESS, t.PLATE_WIDTH]), friction),
    t.PLATE_MASS, [0, height, 0]));
}

// test4: the big cube on the small cube on the platform.
function stack(HK, bigMass, options) {
  const t = scene.test4;
  const world = new World(HK, SURFACE_GRAVITY, options);
  world.body(world.box([t.PLATFORM_SIDE, t.PLATFORM_THICKNESS, t.PLATFORM_SIDE]), 0, [0, -t.PLATFORM_THICKNESS / 2, 0]);
  const small = world.body(world.box([t.SMALL_SIDE, t.SMALL_SIDE, t.SMALL_SIDE]), t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0]);
  const big = world.body(world.box([t.BIG_SIDE, t.BIG_SIDE, t.BIG_SIDE]), bigMass, [0, t.BIG_START_HEIGHT, 0]);
  return stackReadout(world, small, big);
}

// test10: the cube launched at the wall over the ground.
function launch(HK, velocity, options) {
  const t = scene.test10;
  const world = new World(HK, SURFACE_GRAVITY, options);
  world.ground();
  world.body(world.box([t.WALL_THICKNESS, t.WALL_HEIGHT, t.WALL_WIDTH]), 0, [t.WALL_X, t.WALL_HEIGHT / 2, 0]);
  const cube = world.body(world.box([t.CUBE_SIDE, t.CUBE_SIDE, t.CUBE_SIDE]), t.CUBE_MASS, [t.LAUNCH_X, t.LAUNCH_Y, t.LAUNCH_Z]);
  HK.HP_Body_SetLinearVelocity(cube, [velocity, 0, 0]);
  return launchedCube(world, cube);
}

function settingText(options) {
  const best = options.setting === 'best';
  let text = `HP_World_Step(h), speed limit raised to 1e9, ${options.scene === 'test3' ? '' : 'sleeping off, '}speculative contacts (always on); `;
  text += best ? 'ideal step time h, angular damping 0' : "Havok's defaults (ideal step time 1/60 s, angular damping 0.1)";
  if (options.scene === 'test9') text += '; restitution 1.0 on both shapes (geometric mean: 1.0), ground a 200 m box';
  if (options.scene === 'test1') text += "; each ball's restitution, the ground's 1.0, combined by minimum; ground a 200 m box";
  if (options.scene === 'test10') text += '; ground a 200 m box';
  if (options.scene === 'test5') text += '; friction 100 on every shape (test5\'s never-sliding contacts)';
  if (options.scene === 'test3') text += "; friction 1.0, Havok's own sleeping (thresholds not exposed), ground a 200 m box";
  if (options.scene === 'test6') text += '; friction 100 on every shape (test6\'s never-sliding contacts)';
  if (options.scene === 'test7') text += '; ball joints (6-DOF, linear axes locked), friction 100 on every shape, ground a 200 m box';
  return text;
}

module.exports = { name: 'havok', packageName: '@babylonjs/havok', hasContinuousCollision: false, load, settingText, plateStack: plates, dominoes, balls, axisSystem, hangingPair, pendulum, ball, stack, launch };
