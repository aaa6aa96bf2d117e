// SPDX-License-Identifier: GPL-3.0-or-later
// The derivation page's Web Worker: it holds the checker (impulselab-check.js) and checks one text
// at a time, so that the page never waits for a check while the reader types. This script only
// defines the function; check.js starts the worker from the text of impulselabCheckModule (the
// checker) and of this function, as a Blob: a page opened from disk may not start a worker from
// a file, and may from a Blob.
//
// Messages in:  {id, text, file}   text a string, or a Uint8Array for bytes that are not UTF-8
// Messages out: {ready: true, seconds}                        once the module is compiled
//               {failed: message}                             if it cannot be
//               {id, result, error, line, column, status, seconds}
//                                                             checkDerivation's answer (web/README.md)
//               {id, crashed: message}                        the module stopped; this worker ends
function impulselabCheckWorker() {
  'use strict';
  const start = performance.now();
  let checker = null;
  const waiting = [];

  function check(message) {
    const begin = performance.now();
    let out;
    try {
      out = checker.checkDerivation(message.text, {file: message.file});
    } catch (error) {
      // The module stopped (a WebAssembly trap, memory exhausted): it cannot be used again, and
      // the page starts a new worker.
      self.postMessage({id: message.id, crashed: String(error && error.message ? error.message : error)});
      checker = null;
      self.close();
      return;
    }
    self.postMessage({
      id: message.id,
      result: out.result,
      error: out.error,
      line: out.line,
      column: out.column,
      status: out.status,
      seconds: (performance.now() - begin) / 1000,
    });
  }

  self.onmessage = (event) => {
    if (checker) {
      check(event.data);
    } else {
      waiting.push(event.data);
    }
  };

  createImpulseLabCheck().then((module) => {
    checker = module;
    self.postMessage({ready: true, seconds: (performance.now() - start) / 1000});
    for (const message of waiting.splice(0)) {
      check(message);
    }
  }, (error) => {
    self.postMessage({failed: String(error && error.message ? error.message : error)});
  });
}
