'use strict';
// Translation notes: one plain sentence per fact the engine could not
// express exactly, each said once. `fresh()` hands over those not yet sent.
class Notes {
  constructor() {
    this.all = [];
    this.seen = new Set();
    this.sent = 0;
  }
  add(sentence) {
    if (this.seen.has(sentence)) return;
    this.seen.add(sentence);
    this.all.push(sentence);
  }
  fresh() {
    const list = this.all.slice(this.sent);
    this.sent = this.all.length;
    return list;
  }
}

// A number as a note prints it: short, and never "Infinity".
function fmt(x) {
  if (x === Infinity) return 'infinity';
  if (x === -Infinity) return '-infinity';
  return String(Number(x.toPrecision(6)));
}

module.exports = { Notes, fmt };
