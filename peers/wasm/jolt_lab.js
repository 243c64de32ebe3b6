#!/usr/bin/env node
'use strict';
// jolt_lab: the thesis's scenes on Jolt's WebAssembly build (doc/peers.md).
require('./src/main').main(require('./src/jolt'));
