#!/usr/bin/env node
'use strict';
// rapier_lab: the thesis's scenes on Rapier's WebAssembly build (doc/peers.md).
require('./src/main').main(require('./src/rapier'));
