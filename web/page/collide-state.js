// SPDX-License-Identifier: GPL-3.0-or-later
// The page's state and its address. The state is the scene, in the address: #scene= followed by
// the scene's JSON, percent-encoded as encodeURIComponent writes it (bytes that are not UTF-8 as
// %XX), so that a link reproduces the page (the contract: web-page.md). Every scene goes through
// the library (Module.solveScene), and only through it; a change is an edit of the scene, kept
// for undo; the scene the page was given (address, preset, file, text) is kept for reset.
'use strict';

(function (collide) {
  const {$, isObject} = collide;

  // The address: bytes in and out of the fragment, a file opened and one downloaded, as every
  // interactive page does them (web/common/files.js).
  const {encodeBytes, decodeFragment, utf8Text, download, opened} = window.impulselabFiles;

  const fragmentKey = '#scene=';
  const presets = window.impulselabPresets || [];
  collide.presets = presets;
  const defaultPreset = 'box-lands-flat';

  // ---------------------------------------------------------------------------------------------
  // The state.

  const state = {
    module: null,
    text: '',       // the scene as the library read it (a string), when it is UTF-8
    bytes: null,    // the scene's bytes, when they are not UTF-8
    scene: null,    // the scene as an object, when its text is JSON shaped like a scene
    fromControls: false,
    out: null,      // what Module.solveScene returned for this scene
    result: null,   // its report, parsed (null when refused)
    details: null,  // the bodies' motion before and after, parsed (null when refused)
    // The last scene the library solved, kept (dimmed) while the scene is refused.
    valid: null,    // {scene, result, details, layout, out}
    layout: null,   // where everything is drawn at t = 0: this scene's, or the last solved one's
    frozen: null,   // the view kept still while something is dragged
    shapes: new Map(),  // each rigid body's drawn shape, by name, kept while the scene is edited
    walls: new Map(),   // static bodies drawn by the editor: their surfaces, by name
    t: 0,           // animation time, in units of the layout's window (-1 .. 1)
    playing: false,
    shown: 0,
    version: 0,
    lastHash: '',
    fragmentTimer: 0,
    lastFragmentWrite: 0,
    history: [],    // earlier scene texts, for undo
    lastEdit: null, // {key, at}: a stream of changes (a slider dragged) is one step of undo
    origin: '',     // the scene as the page was given it (address, preset, file): reset
    signature: '',  // the bodies' names and kinds: a change rebuilds the controls
  };
  collide.state = state;

  // Serial collisions run in slices (Module.solveBegin, solveAdvance), so that every frame is
  // drawn: each slice runs as many collisions as the last ones ran in sliceMs (the rest of a
  // 60 Hz frame is the browser's), and the page
  // shows how far they are until they end (then the answer is solveScene's, exactly).
  const sliceMs = 12;
  // The first frame also redraws the page (about 5 ms at 100 contacts): within a 16.7 ms frame,
  // the library's default bound at 100 contacts (10,000 collisions: 3 ms, or 9 ms with friction's
  // exact rule) fits in it.
  const firstSliceMs = 10;
  const slicing = {perMs: 2000, collisions: 0};

  function sliceCollisions(ms = sliceMs) {
    return Math.max(100, Math.round(slicing.perMs * ms));
  }

  // What the library answered, as the page keeps it; @p ms the time it took, @p before the
  // collisions run before it (to learn how many run in a millisecond).
  function answered(out, ms, before) {
    if (out.pending) {
      const ran = out.collisions - before;
      if (ran > 0 && ms > 0.5) {
        slicing.perMs = 0.5 * slicing.perMs + 0.5 * (ran / ms);
      }
      slicing.collisions = out.collisions;
      return {pending: {collisions: out.collisions, bound: out.bound}, error: '', warnings: [],
              resultText: '', result: null, details: null};
    }
    slicing.collisions = 0;
    return collide.timed('parse', () => ({
      error: out.error,
      warnings: out.warnings,
      resultText: out.result,
      result: out.result ? JSON.parse(out.result) : null,
      details: out.details ? JSON.parse(out.details) : null,
    }));
  }

  function solve(input) {
    const started = performance.now();
    const out = state.module.solveBegin(input, sliceCollisions(firstSliceMs));
    collide.phases.library = performance.now() - started;
    return answered(out, collide.phases.library, 0);
  }

  function sceneShaped(value) {
    return isObject(value) && Array.isArray(value.bodies) && Array.isArray(value.contacts) &&
           value.bodies.every(isObject) && value.contacts.every(isObject);
  }

  const signatureOf = (scene) => (scene ? JSON.stringify([scene.dimension, scene.bodies.map((b) => [b.name, b.kind])]) : '');

  // Shows the scene given as text (or bytes that are not UTF-8). @p options.relayout: a new scene
  // (the view fitted again, the drawn shapes found again); @p options.event: the input event that
  // caused it; @p options.immediate: the address written at once.
  collide.show = (input, options = {}) => {
    const started = performance.now();
    collide.phases = {};
    state.version += 1;  // which scene the side views show (collide-compare.js)
    document.body.dataset.version = String(state.version);
    if (typeof input === 'string') {
      state.text = input;
      state.bytes = null;
    } else {
      state.text = '';
      state.bytes = input;
    }
    let parsed = null;
    if (state.bytes === null) {
      try {
        parsed = JSON.parse(state.text);
      } catch (e) {
        parsed = null;
      }
    }
    state.scene = sceneShaped(parsed) ? parsed : null;
    state.fromControls = Boolean(options.fromControls);
    if (options.relayout) {
      state.shapes.clear();
      state.walls.clear();
      state.frozen = null;
    }
    const solveStart = performance.now();
    state.out = solve(state.bytes === null ? state.text : state.bytes);
    const solveEnd = performance.now();
    present({options, started, since: options.event ? options.event.timeStamp : started,
             solve: solveEnd - solveStart, longest: 0});
  };

  // Draws what the library answered (state.out): at once, or, while serial collisions run, how
  // far they are, the next slice run just after this frame. @p update: the options of the change,
  // when it began, the event's time, the library's time so far and the longest piece of work.
  function present(update) {
    const {options, started, since} = update;
    const pieceStart = update.pieceStart === undefined ? since : update.pieceStart;
    state.result = state.out.result;
    state.details = state.out.details;
    const signature = signatureOf(state.scene);
    collide.timed('layout', () => {
      if (state.details && state.scene) {
        state.layout = collide.layout(state.scene, state.details, state.frozen);
        state.layout.current = true;
        state.valid = {scene: state.scene, result: state.result, details: state.details, layout: state.layout,
                       out: state.out, signature};
      } else if (!state.scene || !state.valid) {
        state.layout = null;
        state.valid = null;
      } else {
        // Refused: drawn dimmed, the bodies where this scene puts them when it has the same bodies
        // as the last one solved (so that the canvas can still be edited), with that one's motion.
        state.layout = state.valid.layout;
        if (signature === state.valid.signature) {
          try {
            state.layout = collide.layout(state.scene, state.valid.details, state.frozen);
            state.layout.current = true;
          } catch (e) {
            state.layout = state.valid.layout;
          }
        }
      }
    });
    const rebuild = options.relayout || signature !== state.signature;
    state.signature = signature;
    const later = collide.render({rebuild});
    collide.timed('address', () => writeFragment(Boolean(options.immediate)));
    const rendered = performance.now();
    update.longest = Math.max(update.longest, rendered - pieceStart);
    if (update.first === undefined) {
      update.first = rendered - since;  // the key to the first thing drawn: a result or how far
    }
    if (state.out.pending) {
      // Not ready (the contract's data-ready) until the result or the refusal is shown.
      document.body.dataset.ready = 'false';
      continueSolving(update);
      return;
    }
    collide.phases.event = started - since;  // from the key to this update's start
    const phases = collide.phases;
    // The update ends when the panels off the screen are drawn too: then the page says so
    // (data-shown counts the updates; data-ready: the first is done).
    const finish = () => {
      const done = performance.now();
      state.shown += 1;
      document.body.dataset.shown = String(state.shown);
      document.body.dataset.ready = 'true';
      if (window.impulselabReadyMs === undefined) {
        window.impulselabReadyMs = done;  // since the page began to load (for web/test/measure.mjs)
      }
      // For web/test/measure.mjs: the time from the event to the result drawn on the screen (the
      // end of this function's own work), to everything drawn, and to the frame that shows it
      // painted (a message posted from the next animation frame runs once that frame's style,
      // layout and paint are done).
      requestAnimationFrame(() => {
        const channel = new MessageChannel();
        channel.port1.onmessage = () => {
          window.impulselabTiming = {
            solve_ms: update.solve,
            update_ms: rendered - since,
            first_ms: update.first,       // to the first thing drawn (how far serial collisions are)
            longest_ms: update.longest,   // the longest piece of work between (one frame's)
            all_ms: done - since,
            frame_ms: performance.now() - since,
            contacts: state.result ? state.result.contacts.length : 0,
            phases,
          };
        };
        channel.port2.postMessage(null);
      });
    };
    if (later) {
      setTimeout(() => {
        later();
        finish();
      }, 0);
    } else {
      finish();
    }
  };

  // The next slice of serial collisions, just after the frame that shows how far they are: while
  // they run, only the words of how far change; their end is drawn in full (present).
  function continueSolving(update) {
    const version = state.version;
    requestAnimationFrame(() => setTimeout(() => {
      if (version !== state.version) {
        return;  // a newer scene replaced this one (and the library's slices of it)
      }
      const before = slicing.collisions;
      const t0 = performance.now();
      const out = state.module.solveAdvance(sliceCollisions());
      const ms = performance.now() - t0;
      update.solve += ms;
      collide.phases.library = (collide.phases.library || 0) + ms;
      state.out = answered(out, ms, before);
      if (state.out.pending) {
        collide.showProgress();
        update.longest = Math.max(update.longest, performance.now() - t0);
        continueSolving(update);
      } else {
        present({...update, pieceStart: t0, options: {...update.options, relayout: false}});
      }
    }, 0));
  }

  // The scene changed through a control: @p change edits the scene object. @p options.event: the
  // input event; @p options.keepView: the view stays where it is (a drag); @p options.stream: a
  // key naming a stream of changes (a slider, a drag) that undo takes back as one.
  collide.edit = (change, options = {}) => {
    if (!state.scene) {
      return;
    }
    const now = performance.now();
    const last = state.lastEdit;
    if (!(options.stream && last && last.key === options.stream && now - last.at < 1500)) {
      remember();
    }
    state.lastEdit = options.stream ? {key: options.stream, at: now} : null;
    change(state.scene);
    if (!options.keepView) {
      state.frozen = null;
    }
    // A stream of changes (a slider dragged, a handle moved) writes the address at most every
    // 150 ms; a single change (a menu, a field left) at once.
    const event = options.event;
    const stream = event && (event.type === 'input' || event.type.startsWith('pointer'));
    collide.show(JSON.stringify(state.scene), {fromControls: true, event, immediate: !stream});
  };

  // Undo and reset.
  function remember() {
    const text = state.bytes !== null ? state.bytes : state.text;
    if (state.history.length && state.history[state.history.length - 1] === text) {
      return;
    }
    state.history.push(text);
    if (state.history.length > 200) {
      state.history.shift();
    }
    collide.syncHistory();
  }

  collide.undo = () => {
    if (!state.history.length) {
      return;
    }
    const text = state.history.pop();
    state.lastEdit = null;
    state.frozen = null;
    collide.show(text, {fromControls: true, immediate: true});
    collide.syncHistory();
  };

  collide.reset = () => {
    remember();
    state.lastEdit = null;
    state.valid = null;
    collide.show(state.origin, {relayout: true, immediate: true});
  };

  // A new scene given to the page (address, preset, file, text): reset comes back to it.
  collide.load = (input) => {
    if (state.module && (state.text || state.bytes)) {
      remember();
    }
    state.origin = input;
    state.lastEdit = null;
    state.valid = null;  // another scene: nothing of the last one is kept
    collide.show(input, {relayout: true, immediate: true});
  };

  collide.syncHistory = () => {
    const undo = $('undo');
    if (undo) {
      undo.disabled = state.history.length === 0;
    }
  };

  // ---------------------------------------------------------------------------------------------
  // The address.

  function writeFragment(immediate) {
    clearTimeout(state.fragmentTimer);
    const write = () => {
      const hash = fragmentKey + (state.bytes !== null ? encodeBytes(state.bytes) : encodeURIComponent(state.text));
      state.lastHash = hash;
      state.lastFragmentWrite = performance.now();
      if (location.hash !== hash) {
        history.replaceState(null, '', hash);
      }
    };
    // A slider dragged across writes the address after the result is drawn, at most every 150 ms
    // (browsers throttle changes of the history); the last position is always written.
    if (immediate) {
      write();
    } else {
      state.fragmentTimer = setTimeout(write, Math.max(0, 150 - (performance.now() - state.lastFragmentWrite)));
    }
  }

  collide.loadFromAddress = () => {
    const hash = location.hash;
    if (hash.startsWith(fragmentKey)) {
      const bytes = decodeFragment(hash.slice(fragmentKey.length));
      const text = utf8Text(bytes);
      state.lastHash = hash;
      collide.load(text !== null ? text : bytes);
    } else {
      collide.loadPreset(defaultPreset);
    }
  };

  collide.loadPreset = (id) => {
    const preset = presets.find((p) => p.id === id) || presets[0];
    collide.load(preset ? JSON.stringify(preset.scene) : '');
  };

  collide.matchingPreset = () => {
    if (!state.scene) {
      return '';
    }
    const canonical = JSON.stringify(state.scene);
    const found = presets.find((p) => JSON.stringify(p.scene) === canonical);
    return found ? found.id : '';
  };

  // The scene as a file: its bytes as given, or the edited scene written out.
  collide.sceneFileText = () => (state.bytes !== null ? new TextDecoder().decode(state.bytes)
                               : state.fromControls && state.scene ? JSON.stringify(state.scene, null, 2) + '\n'
                               : state.text);

  // ---------------------------------------------------------------------------------------------
  // Presets, files, the scene's text.

  collide.buildPresetMenu = () => {
    const select = $('preset');
    const own = document.createElement('option');
    own.value = '';
    own.textContent = 'Your own scene';
    select.appendChild(own);
    let group = null;
    for (const p of presets) {
      if (!group || group.label !== p.group) {
        group = document.createElement('optgroup');
        group.label = p.group;
        select.appendChild(group);
      }
      const option = document.createElement('option');
      option.value = p.id;
      option.textContent = p.label;
      group.appendChild(option);
    }
    select.addEventListener('change', () => {
      if (select.value) {
        collide.pause();
        collide.loadPreset(select.value);
        collide.setTime(0);
      }
    });
  };

  // The scene's text in the editor, while the editor is open (a closed one is filled when opened).
  collide.fillSceneText = () => {
    if ($('scene-text-box').open && document.activeElement !== $('scene-text')) {
      $('scene-text').value = state.bytes !== null ? new TextDecoder().decode(state.bytes)
                            : state.fromControls && state.scene ? JSON.stringify(state.scene, null, 2) : state.text;
    }
  };
  $('scene-text-box').addEventListener('toggle', collide.fillSceneText);

  $('open-file').addEventListener('change', async (event) => {
    const content = await opened(event);
    if (content === null) {
      return;
    }
    collide.pause();
    collide.load(content);
    collide.setTime(0);
  });

  $('download').addEventListener('click', () => {
    download(state.bytes !== null ? state.bytes : collide.sceneFileText(),
             (collide.matchingPreset() || 'scene') + '.json', 'application/json');
  });

  $('apply-text').addEventListener('click', () => {
    collide.pause();
    collide.load($('scene-text').value);
    collide.setTime(0);
  });

  window.addEventListener('hashchange', () => {
    if (location.hash !== state.lastHash && state.module) {
      collide.pause();
      collide.loadFromAddress();
      collide.setTime(0);
    }
  });
})(window.collide);
