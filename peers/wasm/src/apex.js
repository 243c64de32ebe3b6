'use strict';
// The apex rule of tests/shared/ApexTracker.h (test1, test9 and the C++
// peers), for the web peers: an apex is a local maximum of height after a
// step, at least `minimumRise` above the lowest point since the previous
// one, placed at the vertex of the parabola through the last three samples.
// checks/ compares the two on recorded trajectories (peers/wasm/parity).

class ApexTracker {
  constructor(minimumRise = 1e-6) {
    this.minimumRise = minimumRise;
    this.samples = [null, null, null];
    this.filled = 0;
    this.lowest = 0;
    this.count = 0;
    this.releaseApex = null;
  }

  restart(time, position) {
    const sample = { t: time, p: [...position] };
    this.samples = [sample, sample, sample];
    this.filled = 1;
    this.lowest = position[1];
    this.count = 0;
    this.releaseApex = { time, position: [...position] };
  }

  // The apex ({time, position}) when the previous sample was one, else null.
  update(time, position) {
    this.samples = [this.samples[1], this.samples[2], { t: time, p: [...position] }];
    if (this.filled < 3 && ++this.filled === 3) this.releaseApex = this.vertex();
    const before = this.samples[0].p[1], top = this.samples[1].p[1], after = this.samples[2].p[1];
    this.lowest = before < this.lowest ? before : this.lowest;
    if (this.filled < 3 || !(top > before && top >= after) || top - this.lowest < this.minimumRise) return null;
    const apex = this.vertex();
    this.lowest = top;
    ++this.count;
    return apex;
  }

  vertex() {
    const [s0, s1, s2] = this.samples;
    const curvature = s0.p[1] - 2 * s1.p[1] + s2.p[1];
    const slope = 0.5 * (s2.p[1] - s0.p[1]);
    const u = curvature < 0 ? -slope / curvature : 0.0;
    const position = [0, 1, 2].map((i) => {
      const a = 0.5 * (s0.p[i] - 2 * s1.p[i] + s2.p[i]);
      const b = 0.5 * (s2.p[i] - s0.p[i]);
      return s1.p[i] + b * u + a * u * u;
    });
    return { time: s1.t + (u * (s2.t - s0.t)) / 2, position };
  }
}

module.exports = { ApexTracker };
