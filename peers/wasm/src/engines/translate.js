'use strict';
// What every engine here says the same way about a world: the facts of
// ODE's that none of Havok, Jolt and Rapier has, as translation notes.
const { fmt } = require('./notes');

// `engine`: its name in a sentence; `has`: what this engine does express
// ({ iterations: bool, bounceVelocity: bool, jointErp: bool }).
function commonNotes(world, notes, engine, has = {}) {
  const s = world.settings;
  notes.add(`float32: ${engine}'s WebAssembly build computes in single precision (about 7 significant digits)`);
  notes.add(`the world's ERP ${fmt(s.erp)} and CFM ${fmt(s.cfm)} have no counterpart in ${engine}, which corrects penetration and joint error its own way`);
  if (s.solver === 'step') notes.add(`ODE's dWorldStep (the exact "big matrix" solver) has no counterpart: ${engine} solves iteratively`);
  if (!has.iterations) notes.add(`${engine} takes no iteration count: the world's ${s.iterations} QuickStep iterations are not applied`);
  if (s.contactMaxCorrectingVelocity !== Infinity)
    notes.add(`ODE's contact max correcting velocity ${fmt(s.contactMaxCorrectingVelocity)} m/s has no counterpart in ${engine}`);
  if (s.contactSurfaceLayer > 0)
    notes.add(`ODE's contact surface layer ${fmt(s.contactSurfaceLayer)} m has no counterpart in ${engine} (it keeps its own slop)`);
  for (const j of world.joints) {
    if (!Number.isNaN(j.erp) || !Number.isNaN(j.cfm))
      notes.add(`a joint's own ERP/CFM (${j.type} joint) has no counterpart in ${engine}: its joints are rigid`);
  }
  for (const sf of world.surfacesInUse()) {
    if (sf.softErp !== undefined) notes.add(`a surface's soft ERP ${fmt(sf.softErp)} has no counterpart in ${engine}: its contacts are rigid`);
    if (sf.softCfm !== undefined) notes.add(`a surface's soft CFM ${fmt(sf.softCfm)} has no counterpart in ${engine}: its contacts are rigid`);
    if (sf.approx1) notes.add(`ODE's friction pyramid (friction_pyramid) is not chosen in ${engine}, which uses its own friction model`);
    if (sf.bounce && sf.bounceVelocity > 0 && !has.bounceVelocity)
      notes.add(`${engine} has no bounce threshold: ODE's bounce velocity ${fmt(sf.bounceVelocity)} m/s (no bounce below it) is not applied`);
  }
  const caps = world.bodies.filter((b) => b.maxAngularSpeed !== Infinity);
  if (caps.length && !has.maxAngularSpeed)
    notes.add(`${engine} has no per-body angular speed cap: max_angular_speed ${fmt(caps[0].maxAngularSpeed)} rad/s is not applied`);
}

// Infinite friction in an engine that takes a number.
function frictionValue(mu, cap, notes, engine) {
  if (mu === Infinity) {
    notes.add(`infinite friction (mu = infinity) became friction ${fmt(cap)} in ${engine}`);
    return cap;
  }
  return mu;
}

// The note for a property a material plan could not give every pair.
function planNotes(plan, what, engine, notes, ruleName) {
  if (plan.exact) {
    if (!plan.uniform)
      notes.add(`${what} per pair of geoms: each shape's ${what} set so that ${engine}'s ${ruleName(plan.rule)} of the two gives every pair its own`);
    return;
  }
  const [a, b, wanted, got] = plan.wrong[0];
  const kept = plan.namedWrong === 0 ? ' (every pair the world names has its own; the others are pairs of the default surface)' : '';
  notes.add(`${what}: ${engine} combines the two shapes' values (${ruleName(plan.rule)}), and no choice gives every pair its own: `
    + `${plan.wrong.length} pair(s) of geoms that may touch differ, e.g. geoms ${a} and ${b} want ${fmt(wanted)} and get ${fmt(got)}${kept}`);
}

module.exports = { commonNotes, frictionValue, planNotes };
