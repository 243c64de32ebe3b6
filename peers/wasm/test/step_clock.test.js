'use strict';
// The engine's step time (src/engines/clock.js) holds the step and nothing
// of the clock's own: reading the process's CPU counters is a system call
// that a busy machine makes slow, and when it fell inside the wall window
// every adapter's engine_wall_seconds carried it.
//   node --test peers/wasm/test/step_clock.test.js
const test = require('node:test');
const assert = require('node:assert');
const { StepClock } = require('../src/engines/clock');

const SLOW_READ_MS = 5;  // a CPU-counter read made slow on purpose

function busyWait(ms) {
  const until = process.hrtime.bigint() + BigInt(Math.round(ms * 1e6));
  while (process.hrtime.bigint() < until);
}

test('the wall time of a step excludes the clock reading its CPU counters', () => {
  const real = process.cpuUsage;
  process.cpuUsage = (...args) => {
    busyWait(SLOW_READ_MS);
    return real.apply(process, args);
  };
  const clock = new StepClock();
  const steps = 20;
  try {
    for (let i = 0; i < steps; ++i) clock.time(() => {});
  } finally {
    process.cpuUsage = real;
  }
  // An empty step takes microseconds; one slow read inside the window
  // would add SLOW_READ_MS to each. Half of it leaves room for a busy machine.
  const perStepMs = (clock.wallSeconds() / steps) * 1e3;
  assert.ok(perStepMs < SLOW_READ_MS / 2, `an empty step timed at ${perStepMs.toFixed(3)} ms (a CPU read takes ${SLOW_READ_MS} ms)`);
});

test('the CPU time of a step still counts the step', () => {
  const clock = new StepClock();
  clock.time(() => busyWait(50));
  assert.ok(clock.wallSeconds() >= 0.049, `wall ${clock.wallSeconds()}`);
  // The CPU counters see some of 50 ms of busy waiting, however busy the machine.
  assert.ok(clock.cpuSeconds() > 0, `cpu ${clock.cpuSeconds()}`);
});
