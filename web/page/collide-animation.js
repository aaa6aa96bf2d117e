// SPDX-License-Identifier: GPL-3.0-or-later
// The animation: play, pause, step back and forward, slow motion (one fifth) and a time slider
// over a window before and after the impulses (the motion itself: collide-motion.js); and serial
// collisions replayed one collision at a time, each the state the library gives after it
// (Module.serialStep).
'use strict';

(function (collide) {
  const {$, num, round, state} = collide;
  const timeInput = $('time');
  const playButton = $('play');
  let lastFrame = 0;

  collide.setTime = (t) => {
    state.t = Math.max(-1, Math.min(1, t));
    timeInput.value = String(Math.round(state.t * 1000));
    const seconds = state.layout ? state.t * state.layout.scales.window : 0;
    const when = state.t < 0 ? 'before the impulses' : state.t > 0 ? 'after the impulses' : 'the instant of the impulses';
    $('time-text').textContent = `t = ${num(round(seconds, 3))}, ${when}`;
    collide.draw();
  };

  function frame(now) {
    if (!state.playing) {
      return;
    }
    const started = performance.now();
    const elapsed = Math.min(0.1, (now - lastFrame) / 1000);
    lastFrame = now;
    // The whole window (-T .. T) takes 3 s, or 15 s in slow motion.
    const rate = (2 / 3) * ($('slow').checked ? 0.2 : 1);
    let t = state.t + elapsed * rate;
    if (t > 1) {
      t = -1;
    }
    collide.setTime(t);
    window.impulselabFrameMs = performance.now() - started;  // the cost of one frame's drawing
    requestAnimationFrame(frame);
  }

  collide.play = () => {
    if (state.playing || !state.layout) {
      return;
    }
    collide.stepTo(0);
    state.playing = true;
    playButton.setAttribute('aria-pressed', 'true');
    playButton.textContent = '\u23F8\uFE0E Pause';
    if (state.t >= 1) {
      state.t = -1;
    }
    lastFrame = performance.now();
    requestAnimationFrame(frame);
  };

  collide.pause = () => {
    state.playing = false;
    playButton.setAttribute('aria-pressed', 'false');
    playButton.textContent = '\u25B6\uFE0E Play';
  };

  playButton.addEventListener('click', () => (state.playing ? collide.pause() : collide.play()));
  $('step-back').addEventListener('click', () => {
    collide.pause();
    collide.setTime(state.t - 0.05);
  });
  $('step-forward').addEventListener('click', () => {
    collide.pause();
    collide.setTime(state.t + 0.05);
  });
  timeInput.addEventListener('input', () => {
    collide.pause();
    collide.setTime(Number(timeInput.value) / 1000);
  });

  // ---------------------------------------------------------------------------------------------
  // Serial collisions, one at a time: collision k of the scene's run (0: the whole result).

  const serial = {k: 0, step: null, text: null};

  // The collisions of the scene's serial run, when its method is serial and it ran them.
  const collisions = () => {
    const r = state.result;
    return r && r.method === 'serial' && r.serial && typeof r.serial.collisions === 'number' ? r.serial.collisions : 0;
  };

  collide.serialShown = () => (serial.k > 0 && serial.text === state.text ? serial.step : null);

  collide.stepTo = (k) => {
    const total = collisions();
    serial.k = Math.max(0, Math.min(total, k));
    serial.step = null;
    serial.text = state.text;
    if (serial.k > 0) {
      const out = state.module.serialStep(state.bytes !== null ? state.bytes : state.text, serial.k);
      serial.step = out.step ? JSON.parse(out.step) : null;
      if (!serial.step) {
        serial.k = 0;
      }
    }
    syncSerial();
    collide.draw();
  };

  function syncSerial() {
    const total = collisions();
    $('serial-steps').hidden = total === 0;
    if (serial.text !== state.text) {
      serial.k = 0;
      serial.step = null;
    }
    $('collision-back').disabled = serial.k === 0;
    $('collision-forward').disabled = serial.k >= total;
    const step = serial.k > 0 ? serial.step : null;
    let text = `${total} collision${total === 1 ? '' : 's'} in all: the result. Step through them one at a time.`;
    if (step) {
      const c = state.scene ? state.scene.contacts[step.contact] : null;
      const previous = serial.k > 1 && serial.previous ? serial.previous.Fdt[step.contact] : 0;
      text = `Collision ${serial.k} of ${total}: contact ${step.contact}${c ? ` (${c.bumper}–${c.wedge})` : ''}, ` +
             `its impulse F dt ${num(step.Fdt[step.contact] - previous)} (${num(step.Fdt[step.contact])} at that contact so far); ` +
             `kinetic energy after it ${num(step.energy_after)}.`;
    }
    $('collision-text').textContent = text;
  }
  collide.syncSerial = syncSerial;

  $('collision-forward').addEventListener('click', () => {
    collide.pause();
    collide.setTime(0);
    serial.previous = serial.step;
    collide.stepTo(serial.k + 1);
  });
  $('collision-back').addEventListener('click', () => {
    collide.pause();
    collide.setTime(0);
    serial.previous = serial.k > 2 ? JSON.parse(state.module.serialStep(state.text, serial.k - 2).step || 'null') : null;
    collide.stepTo(serial.k - 1);
  });
})(window.collide);
