'use strict';
// The scene constants as the C++ programs see them: read from the C++
// headers themselves (tests/shared/SceneConstants.h, utils/WorldSettings.h,
// tests/shared/LaunchOutcome.h, tests/shared/VelocityScan.h, peers/Test10Scene.h),
// never copied. A constant is `constexpr double NAME = expression;` inside a
// scene's namespace; the expression may use numbers, + - * / ( ) and names
// defined before it in the same namespace or at the top. A constant this
// reader cannot evaluate throws when it is used, naming itself, so a new
// kind of expression in the header fails loudly instead of giving a wrong
// number.
const fs = require('fs');
const path = require('path');

const ROOT = path.resolve(__dirname, '..', '..', '..');
const HEADERS = [
  path.join(ROOT, 'utils', 'WorldSettings.h'),
  path.join(ROOT, 'tests', 'shared', 'SceneConstants.h'),
  path.join(ROOT, 'tests', 'shared', 'LaunchOutcome.h'),  // test10's settling time, beside its outcome rule
  path.join(ROOT, 'tests', 'shared', 'VelocityScan.h'),  // test10's scan steps
  path.join(ROOT, 'peers', 'Test10Scene.h'),  // test10's launch rule and scan, as the C++ peers run them
  path.join(ROOT, 'peers', 'Surfaces.h'),  // the ODE scenes' surface choices, as every peer maps them
];
const DECLARATION = /constexpr\s+(?:double|int|long)\s+([^;]+);/g;
const SAFE_EXPRESSION = /^[\w\s.+\-*/()]+$/;

function splitTopLevel(text) {
  const parts = [];
  let depth = 0, start = 0;
  for (let i = 0; i < text.length; ++i) {
    if (text[i] === '(') ++depth;
    else if (text[i] === ')') --depth;
    else if (text[i] === ',' && depth === 0) {
      parts.push(text.slice(start, i));
      start = i + 1;
    }
  }
  parts.push(text.slice(start));
  return parts;
}

function evaluate(expression, scope) {
  const text = expression.trim();
  if (!SAFE_EXPRESSION.test(text)) throw new Error(`unsupported expression "${text}"`);
  const withNames = text.replace(/\b[A-Za-z_]\w*\b/g, (name) => {
    if (!(name in scope)) throw new Error(`unknown name ${name} in "${text}"`);
    return `(${scope[name]})`;
  });
  const value = Function(`"use strict"; return (${withNames});`)();
  if (typeof value !== 'number' || !Number.isFinite(value)) throw new Error(`"${text}" is not a finite number`);
  return value;
}

// Parses one header's text into {top: {...}, <namespace>: {...}}.
function parseHeader(text, file, into) {
  const stripped = text.replace(/\/\/[^\n]*/g, '').replace(/\/\*[\s\S]*?\*\//g, '');
  // The scene namespaces: `namespace testN {` ... its closing brace.
  const spans = [];
  const opener = /namespace\s+([\w:]+)\s*\{/g;
  let found;
  while ((found = opener.exec(stripped))) {
    let depth = 1, i = opener.lastIndex;
    for (; i < stripped.length && depth > 0; ++i) {
      if (stripped[i] === '{') ++depth;
      else if (stripped[i] === '}') --depth;
    }
    spans.push({ name: found[1].split('::').pop(), start: opener.lastIndex, end: i });
  }
  const innermost = (at) => spans.filter((s) => s.start <= at && at < s.end).sort((a, b) => b.start - a.start)[0];
  let declaration;
  DECLARATION.lastIndex = 0;
  while ((declaration = DECLARATION.exec(stripped))) {
    const span = innermost(declaration.index);
    const group = span && /^test\d+$/.test(span.name) ? span.name : 'top';
    into[group] = into[group] || {};
    for (const part of splitTopLevel(declaration[1])) {
      const [name, expression] = part.split('=').map((s) => s.trim());
      if (!name || expression === undefined) continue;
      const scope = { ...into.top, ...into[group] };
      try {
        const value = evaluate(expression, scope);
        Object.defineProperty(into[group], name, { value, enumerable: true, configurable: true });
      } catch (error) {
        Object.defineProperty(into[group], name, {
          enumerable: false, configurable: true,
          get() { throw new Error(`${path.relative(ROOT, file)}: ${group}::${name}: ${error.message}`); },
        });
      }
    }
  }
  return into;
}

function loadConstants(headers = HEADERS) {
  const all = { top: {} };
  for (const file of headers) parseHeader(fs.readFileSync(file, 'utf8'), file, all);
  return all;
}

// A name the headers do not define is an error, not undefined.
function strict(groups) {
  const guard = (group, name) => new Proxy(group, {
    get(target, key) {
      if (typeof key === 'string' && !(key in target)) throw new Error(`no constant ${name}::${key} in the scene headers`);
      return target[key];
    },
  });
  return Object.fromEntries(Object.entries(groups).map(([name, group]) => [name, guard(group, name)]));
}

const constants = strict(loadConstants());
// The names the scenes use: scene.test9.BALL_RADIUS, SURFACE_GRAVITY.
module.exports = { scene: constants, SURFACE_GRAVITY: constants.top.SURFACE_GRAVITY, parseHeader, loadConstants };
