'use strict';
// The installed version of an npm package of peers/wasm, as its package.json says.
const fs = require('fs');
const path = require('path');

function packageVersion(name) {
  const file = path.join(__dirname, '..', '..', 'node_modules', name, 'package.json');
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

module.exports = { packageVersion };
