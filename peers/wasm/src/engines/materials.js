'use strict';
const { pairKey } = require('./world');
// Engines without a per-contact hook give each shape a friction and a
// restitution and combine the two shapes' values by a rule. ODE's world
// gives a surface per pair of geoms instead. This finds, for one property,
// per-geom values and a rule that give every touching pair its own value,
// or, where none does, the best it can and the pairs it gets wrong.
//
// The values needed: v(g) for every geom, such that rule(v(a), v(b)) is the
// pair's value for every pair that may touch. Two cases cover the worlds
// this lab makes: every pair alike (any rule), or one geom's value wanted
// against everything else (a ground of restitution 0 and balls each with
// their own: maximum, with the ground at the smallest value).

const RULES = {
  min: Math.min,
  max: Math.max,
  average: (a, b) => (a + b) / 2,
  geometric: (a, b) => Math.sqrt(a * b),
  multiply: (a, b) => a * b,
};

// Pairs of built geoms that may touch and whose value is not the default
// one's, found without visiting every pair: only geoms named in a pair
// surface can differ from the default.
function relevantPairs(world, geoms) {
  const built = new Set(geoms);
  const special = new Set();
  for (const key of world.pairs.keys()) {
    const a = Math.floor(key / 0x100000), b = key % 0x100000;
    if (built.has(a) && built.has(b)) { special.add(a); special.add(b); }
  }
  const pairs = [];
  const budget = 2e7;  // pair checks; beyond it only the named pairs are checked
  if (special.size * geoms.length > budget) {
    for (const key of world.pairs.keys()) {
      const a = Math.floor(key / 0x100000), b = key % 0x100000;
      if (built.has(a) && built.has(b) && world.mayTouch(a, b)) pairs.push([a, b]);
    }
    return { special, pairs };
  }
  for (const a of special)
    for (const b of geoms)
      if (b !== a && !(special.has(b) && b < a) && world.mayTouch(a, b)) pairs.push([a, b]);
  return { special, pairs };
}

// `valueOf(surface)`: the property's value in the engine (friction with
// infinity already capped, restitution 0 where the surface does not bounce).
// `rules`: the rules this engine has, its default first. Returns
// { rule, value(g), exact, wrong: [[a, b, wanted, got]...], pairs }.
function planMaterial(world, geoms, valueOf, rules, cache) {
  const { special, pairs } = cache || relevantPairs(world, geoms);
  const d = valueOf(world.surfaces[world.defaultSurface]);
  const wanted = pairs.map(([a, b]) => valueOf(world.surfaceBetween(a, b)));
  // Each geom's least and greatest wanted value, over every pair it may
  // touch, or over the pairs the world names only (those it set on purpose).
  const bounds = (namedOnly) => {
    const lo = new Map(), hi = new Map();
    pairs.forEach(([a, b], i) => {
      if (namedOnly && !named[i]) return;
      for (const g of [a, b]) {
        lo.set(g, Math.min(lo.has(g) ? lo.get(g) : Infinity, wanted[i]));
        hi.set(g, Math.max(hi.has(g) ? hi.get(g) : -Infinity, wanted[i]));
      }
    });
    return { lo, hi };
  };
  const named = pairs.map(([a, b]) => world.pairs.has(pairKey(a, b)));
  const candidates = [];
  const uniform = wanted.every((w) => w === d);
  if (uniform) candidates.push({ rule: rules[0], pick: () => d });
  for (const namedOnly of [false, true]) {
    const { lo, hi } = bounds(namedOnly);
    if (rules.includes('max')) candidates.push({ rule: 'max', pick: (g) => (lo.has(g) ? lo.get(g) : d) });
    if (rules.includes('min')) candidates.push({ rule: 'min', pick: (g) => (hi.has(g) ? hi.get(g) : d) });
  }
  // The best: fewest named pairs wrong, then fewest pairs wrong.
  let best = null;
  for (const c of candidates) {
    const combine = RULES[c.rule];
    const wrong = [];
    let namedWrong = 0;
    pairs.forEach(([a, b], i) => {
      const got = combine(special.has(a) ? c.pick(a) : d, special.has(b) ? c.pick(b) : d);
      if (Math.abs(got - wanted[i]) > 1e-12 * Math.max(1, Math.abs(wanted[i]))) {
        wrong.push([a, b, wanted[i], got]);
        if (named[i]) ++namedWrong;
      }
    });
    if (!best || namedWrong < best.namedWrong || (namedWrong === best.namedWrong && wrong.length < best.wrong.length))
      best = { rule: c.rule, value: (g) => (special.has(g) ? c.pick(g) : d), wrong, namedWrong };
    if (wrong.length === 0) break;
  }
  return { ...best, exact: best.wrong.length === 0, pairs: pairs.length, uniform };
}

module.exports = { planMaterial, relevantPairs, RULES };
