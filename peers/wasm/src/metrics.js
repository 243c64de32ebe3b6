'use strict';
// The metrics as utils/Metrics.cpp writes them: ordered "name = value" lines
// and a flat JSON object, whole numbers exact, the rest to 10 significant
// digits as C++'s default stream prints them, non-finite values as null.
const { writeAtomically } = require('./files');

function formatNumber(value) {
  if (!Number.isFinite(value)) return 'null';
  if (Number.isInteger(value) && Math.abs(value) < 2 ** 53) return value.toFixed(0);
  // %.10g: scientific below 1e-4 and from 1e10 up; trailing zeros dropped.
  const [mantissa, exponentText] = value.toExponential(9).split('e');
  const exponent = Number(exponentText);
  const trim = (s) => (s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s);
  if (exponent < -4 || exponent >= 10) {
    const sign = exponent < 0 ? '-' : '+';
    return `${trim(mantissa)}e${sign}${String(Math.abs(exponent)).padStart(2, '0')}`;
  }
  return trim(value.toFixed(9 - exponent));
}

class Metrics {
  constructor() {
    this.entries = new Map();
  }
  set(name, value) {
    this.entries.set(name, Number(value));
  }
  get(name) {
    return this.entries.has(name) ? this.entries.get(name) : NaN;
  }
  text() {
    return [...this.entries].map(([name, value]) => `${name} = ${formatNumber(value)}\n`).join('');
  }
  json() {
    const lines = [...this.entries].map(([name, value]) => `\n  "${name}": ${formatNumber(value)}`);
    return `{${lines.join(',')}\n}\n`;
  }
  // Whole or not at all, and only over a regular file (src/files.js).
  writeJsonAtomically(file) {
    writeAtomically(file, this.json());
  }
}

module.exports = { Metrics, formatNumber };
