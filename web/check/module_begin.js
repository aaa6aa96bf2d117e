// SPDX-License-Identifier: GPL-3.0-or-later
// impulselab-check.js: ImpulseLab's derivation checker compiled to WebAssembly (web/README.md).
//   const checker = await createImpulseLabCheck();
//   const out = checker.checkDerivation(text, {file: 'notes.md'});
//   // out.result: what `impulselab check notes.md --format json` prints, or "" when it refuses
//   // out.error:  its refusal "LINE:COLUMN: what was expected", or ""
// Emscripten's output is wrapped in the function impulselabCheckModule, so that a page opened
// from disk can start a Web Worker from its text (check.html does).
var impulselabCheckModule = function () {
