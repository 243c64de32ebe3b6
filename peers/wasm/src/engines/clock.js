'use strict';
// The time an engine spends in its own step calls. In Node.js: wall time
// from the monotonic clock and CPU time from the process's counters. A
// web page cannot read its CPU time, so there the CPU figure is the wall
// figure (doc/engine-protocol.md says so).
const inNode = typeof process !== 'undefined' && process.versions != null && process.versions.node != null;

class StepClock {
  constructor() {
    this.wall = 0;  // seconds
    this.cpu = 0;
  }

  // Runs `step` and adds its time.
  time(step) {
    if (!inNode) {
      const start = performance.now();
      step();
      const seconds = (performance.now() - start) / 1e3;
      this.wall += seconds;
      this.cpu += seconds;
      return;
    }
    // The wall window lies inside the CPU one: reading the CPU counters is
    // a system call that costs from 10 us to hundreds on a busy machine
    // (profiled: a third of a Havok run's time), and inside the window it
    // was counted as the engine's own step.
    const cpu = process.cpuUsage();
    const wall = process.hrtime.bigint();
    step();
    const wallEnd = process.hrtime.bigint();
    const used = process.cpuUsage(cpu);
    this.wall += Number(wallEnd - wall) / 1e9;
    this.cpu += (used.user + used.system) / 1e6;
  }

  wallSeconds() {
    return this.wall;
  }

  cpuSeconds() {
    return this.cpu;
  }
}

module.exports = { StepClock };
