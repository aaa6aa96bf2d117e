// SPDX-License-Identifier: GPL-3.0-or-later
// The controls: a card of fields per body (mass, moment of inertia, elasticity, velocity, spin,
// each a number field and a slider), the solver's menus, the scene's friction μ and default
// elasticity. Every refusal and warning of the library that names a place in the scene is shown
// beside the field of that place, in a reader's words ("left, mass: must be positive and finite,
// got -1"), the field marked invalid; #scene-error and #warnings keep the library's own text. A
// number a field cannot hold (1e400, beyond doubles) is refused at the field.
'use strict';

(function (collide) {
  const {$, isObject, num, round, vec, escapeHtml, colour, state} = collide;
  const fields = [];  // {input, slider, refresh(scene)}
  collide.fields = fields;

  // ---------------------------------------------------------------------------------------------
  // Messages at their fields.

  const keyWords = {mass: 'mass', inertia: 'moment of inertia', elasticity: 'elasticity', velocity: 'velocity',
                    momentum: 'momentum', angular_velocity: 'spin', angular_momentum: 'angular momentum',
                    position: 'position', name: 'name', kind: 'kind', normal: 'normal', normal_angle: 'normal',
                    point: 'point', friction: 'friction μ', bumper: 'bumper', wedge: 'wedge'};
  const fieldOfKey = {mass: 'mass', inertia: 'inertia', elasticity: 'elasticity', velocity: 'vx', momentum: 'vx',
                      angular_velocity: 'spin', angular_momentum: 'spin'};

  // Where a message of the library points: {words, field} (the field's id, or '' when the page
  // has no field for it), from its place, "bodies[1].mass: …".
  collide.placeOf = (message) => {
    const scene = state.scene;
    const m = /^(bodies|contacts)\[(\d+)\](?:\.([a-z_]+))?(?:\[\d+\])?: ([^]*)$/.exec(message) ||
              /^(elasticity|friction|dimension|solver)(?:\.([a-z_]+))?: ([^]*)$/.exec(message);
    if (!m) {
      return {words: message, field: ''};
    }
    if (m[1] === 'bodies' || m[1] === 'contacts') {
      const k = Number(m[2]);
      const key = m[3];
      const rest = m[4];
      if (m[1] === 'bodies') {
        const body = scene && scene.bodies[k];
        const name = body && typeof body.name === 'string' && body.name ? body.name : `body ${k + 1}`;
        const field = key && fieldOfKey[key] ? `body-${k}-${fieldOfKey[key]}` : '';
        return {words: `${name}${key ? `, ${keyWords[key] || key.replace(/_/g, ' ')}` : ''}: ${rest}`,
                field: field && $(field) ? field : ''};
      }
      const c = scene && scene.contacts[k];
      const pair = c && typeof c.bumper === 'string' && typeof c.wedge === 'string' ? ` (${c.bumper}–${c.wedge})` : '';
      return {words: `contact ${k}${pair}${key ? `, ${keyWords[key] || key.replace(/_/g, ' ')}` : ''}: ${m[4]}`, field: ''};
    }
    const rest = m[3];
    if (m[1] === 'elasticity') {
      return {words: `elasticity of every body without its own: ${rest}`, field: 'default-elasticity-number'};
    }
    if (m[1] === 'friction') {
      return {words: `friction μ: ${rest}`, field: 'friction-number'};
    }
    if (m[1] === 'solver') {
      const field = {method: 'method', dependent: 'dependent', restitution: 'restitution'}[m[2]] || '';
      return {words: `solver${m[2] ? `, ${m[2].replace(/_/g, ' ')}` : ''}: ${rest}`, field};
    }
    return {words: `${m[1]}: ${rest}`, field: ''};
  };

  // Puts each refusal and warning beside its field (or beside the scene's text, when the page has
  // no field for its place); fields that a number did not fit keep their own message.
  collide.showMessages = () => {
    for (const old of document.querySelectorAll('.field-message[data-from="library"]')) {
      const input = $(old.dataset.for);
      if (input) {
        input.removeAttribute('aria-invalid');
        input.classList.remove('warned');
        input.removeAttribute('aria-describedby');
      }
      old.remove();
    }
    const out = state.out;
    if (!out) {
      return;
    }
    const messages = [...(out.error ? [[out.error, 'error']] : []), ...out.warnings.map((w) => [w, 'warning'])];
    const elsewhere = [];
    for (const [text, kind] of messages) {
      const place = collide.placeOf(text);
      const input = place.field ? $(place.field) : null;
      if (!input) {
        if (place.words !== text || kind === 'error') {
          elsewhere.push([place.words, kind]);
        }
        continue;
      }
      fieldMessage(input, place.words, kind, 'library');
    }
    const box = $('text-messages');
    box.innerHTML = elsewhere.map(([words, kind]) => `<li class="${kind}">${escapeHtml(words)}</li>`).join('');
    // The refusal again over the canvas, in the same words, with the way to its field.
    const refusal = $('refusal-words');
    refusal.textContent = '';
    if (out.pending) {
      refusal.append(progressWords(out.pending));
    }
    if (out.error) {
      const place = collide.placeOf(out.error);
      refusal.append(state.valid ? 'Refused (the last scene solved stays, dimmed): ' : 'Refused: ');
      if (place.field) {
        const link = document.createElement('a');
        link.href = `#${place.field}`;
        link.textContent = place.words;
        link.addEventListener('click', (event) => {
          event.preventDefault();
          $(place.field).focus();
        });
        refusal.append(link);
      } else {
        refusal.append(place.words);
      }
    }
  };

  // Serial collisions run a slice per frame: how far they are, until the answer.
  function progressWords({collisions, bound}) {
    return `Serial collisions: ${collide.countText(collisions)} so far, of at most ` +
           `${collide.countText(bound)}; the result follows when they end` +
           (state.valid ? ' (the last scene solved stays, dimmed).' : '.');
  }

  // Between the slices, only the words of how far change.
  collide.showProgress = () => {
    if (state.out && state.out.pending) {
      $('refusal-words').textContent = progressWords(state.out.pending);
    }
  };

  function fieldMessage(input, words, kind, from) {
    const row = input.closest('.row') || input.parentElement;
    const id = `${input.id}-message`;
    let p = $(id);
    if (!p) {
      p = document.createElement('p');
      p.id = id;
      p.className = 'field-message';
      row.after(p);
    }
    p.dataset.for = input.id;
    p.dataset.from = from;
    p.classList.toggle('warning', kind === 'warning');
    p.textContent = words;
    input.setAttribute('aria-describedby', id);
    if (kind === 'error') {
      input.setAttribute('aria-invalid', 'true');
    } else {
      input.classList.add('warned');
    }
  }

  // A field whose text is no number a double holds ("1e400", or half typed): refused there; the
  // scene keeps its last value, and the results are dimmed until the field is right again.
  function fieldRefusal(input, what) {
    const own = $(`${input.id}-message`);
    if (input.validity.badInput) {
      fieldMessage(input, `${what}: not a number the library can take (at most about 1.8e308 in size); ` +
                          'the scene keeps its last value', 'error', 'field');
    } else if (own && own.dataset.from === 'field') {
      own.remove();
      input.removeAttribute('aria-invalid');
      input.removeAttribute('aria-describedby');
    }
    document.body.classList.toggle('field-refused', Boolean(document.querySelector('.field-message[data-from="field"]')));
  }
  collide.fieldRefusal = fieldRefusal;

  // ---------------------------------------------------------------------------------------------
  // The fields of each body, built once per scene; their values follow the scene.

  function addField(container, spec) {
    // spec: {id, label, value(scene), set(scene, value), min, slider: [min, max, step], log, ariaName, hint}
    const row = document.createElement('div');
    row.className = 'row';
    const label = document.createElement('label');
    label.htmlFor = spec.id;
    label.textContent = spec.label;
    row.appendChild(label);
    let slider = null;
    if (spec.slider) {
      slider = document.createElement('input');
      slider.type = 'range';
      slider.id = spec.id + '-slider';
      slider.setAttribute('aria-label', `${spec.ariaName}, slider${spec.log ? ' (logarithmic)' : ''}`);
      [slider.min, slider.max, slider.step] = spec.slider.map(String);
      row.appendChild(slider);
    }
    const input = document.createElement('input');
    input.type = 'number';
    input.id = spec.id;
    input.step = 'any';
    if (spec.min !== undefined) {
      input.min = String(spec.min);
    }
    input.setAttribute('aria-label', spec.ariaName);
    row.appendChild(input);
    container.appendChild(row);
    if (spec.hint) {
      const hint = document.createElement('p');
      hint.className = 'field-hint';
      hint.textContent = spec.hint;
      container.appendChild(hint);
    }
    const toSlider = (x) => (spec.log ? Math.log10(x) : x);
    const fromSlider = (s) => (spec.log ? round(10 ** s, 3) : round(s, 3));
    const field = {
      input,
      slider,
      last: NaN,
      refresh(scene) {
        const value = spec.value(scene);
        if (Object.is(value, field.last)) {
          return;  // as written last time (a scene of many bodies: hundreds of fields)
        }
        field.last = document.activeElement === input || document.activeElement === slider ? NaN : value;
        if (document.activeElement !== input && value !== undefined && input.value !== String(value) &&
            !input.validity.badInput) {
          input.value = String(value);
        }
        if (slider && document.activeElement !== slider && typeof value === 'number' && isFinite(value) &&
            slider.value !== String(toSlider(value))) {
          slider.value = String(toSlider(value));
        }
      },
    };
    input.addEventListener('input', (event) => {
      fieldRefusal(input, spec.words);
      const value = input.valueAsNumber;
      if (input.value.trim() === '' || !isFinite(value)) {
        return;  // half typed, or refused at the field
      }
      collide.edit((scene) => spec.set(scene, value), {event, stream: `field-${spec.id}`});
      if (slider) {
        slider.value = String(toSlider(value));
      }
    });
    input.addEventListener('change', () => fieldRefusal(input, spec.words));
    if (slider) {
      slider.addEventListener('input', (event) => {
        const value = fromSlider(Number(slider.value));
        input.value = String(value);
        fieldRefusal(input, spec.words);
        collide.edit((scene) => spec.set(scene, value), {event, stream: `slider-${spec.id}`});
      });
    }
    fields.push(field);
    return field;
  }

  function bodyVelocity(scene, i) {
    const body = scene.bodies[i];
    if (body.velocity !== undefined) {
      return vec(body.velocity);
    }
    return state.details ? vec(state.details.bodies[i].before.velocity) : [0, 0];
  }

  function bodySpin(scene, i) {
    const body = scene.bodies[i];
    if (body.angular_velocity !== undefined) {
      return Number(body.angular_velocity);
    }
    return state.details ? state.details.bodies[i].before.angular_velocity : 0;
  }

  collide.buildBodyControls = () => {
    const container = $('bodies');
    container.textContent = '';
    fields.length = 0;
    const scene = state.scene;
    if (!scene) {
      container.innerHTML = '<p class="static-note">The controls appear when the scene is a JSON object with bodies ' +
                            'and contacts.</p>';
      return;
    }
    const dim = scene.dimension === 1 ? 1 : 2;
    // Scenes of hundreds of bodies get controls for the first 40 only (the canvas and the scene
    // text reach the rest).
    const shown = Math.min(scene.bodies.length, 40);
    for (let i = 0; i < shown; ++i) {
      const body = scene.bodies[i];
      const name = String(body.name);
      const card = document.createElement('fieldset');
      card.className = 'body-card';
      const legend = document.createElement('legend');
      legend.innerHTML = `<span class="swatch" style="background:${colour(i)}"></span>` +
                         `${escapeHtml(name)} <small>(${escapeHtml(body.kind)})</small>`;
      card.appendChild(legend);
      const id = `body-${i}`;
      if (body.kind === 'static') {
        const note = document.createElement('p');
        note.className = 'static-note';
        note.textContent = 'Static: it does not move; it adds nothing to A and B.';
        card.appendChild(note);
        container.appendChild(card);
        continue;
      }
      addField(card, {id: `${id}-mass`, label: 'Mass', ariaName: `Mass of ${name}`, words: `${name}, mass`, min: 0,
                      slider: [-2, 6, 0.01], log: true,
                      value: (s) => s.bodies[i].mass, set: (s, x) => { s.bodies[i].mass = x; }});
      if (body.kind === 'rigid') {
        addField(card, {id: `${id}-inertia`, label: 'Moment of inertia', ariaName: `Moment of inertia of ${name}`,
                        words: `${name}, moment of inertia`, min: 0, slider: [-3, 4, 0.01], log: true,
                        value: (s) => s.bodies[i].inertia, set: (s, x) => { s.bodies[i].inertia = x; }});
      }
      addField(card, {id: `${id}-elasticity`, label: 'Elasticity', ariaName: `Elasticity of ${name}`,
                      words: `${name}, elasticity`, min: 0, slider: [0, 3, 0.05],
                      hint: '1: perfectly inelastic (they stop approaching); 2: perfectly elastic (energy kept).',
                      value: (s) => (s.bodies[i].elasticity !== undefined ? s.bodies[i].elasticity : s.elasticity),
                      set: (s, x) => { s.bodies[i].elasticity = x; }});
      const setVelocity = (s, axis, x) => {
        const v = bodyVelocity(s, i);
        v[axis] = x;
        delete s.bodies[i].momentum;
        s.bodies[i].velocity = dim === 1 ? v[0] : v;
      };
      const axes = dim === 1 ? [['', 0]] : [[' x', 0], [' y', 1]];
      for (const [suffix, axis] of axes) {
        addField(card, {id: `${id}-v${axis ? 'y' : 'x'}`, label: `Velocity${suffix}`,
                        ariaName: `Velocity of ${name}${suffix ? `,${suffix}` : ''}`, words: `${name}, velocity${suffix}`,
                        slider: [-10, 10, 0.1], value: (s) => bodyVelocity(s, i)[axis], set: (s, x) => setVelocity(s, axis, x)});
      }
      if (body.kind === 'rigid') {
        addField(card, {id: `${id}-spin`, label: 'Spin (angular velocity)', ariaName: `Spin of ${name}`,
                        words: `${name}, spin`, slider: [-20, 20, 0.1], value: (s) => bodySpin(s, i),
                        set: (s, x) => {
                          delete s.bodies[i].angular_momentum;
                          s.bodies[i].angular_velocity = x;
                        }});
      }
      container.appendChild(card);
    }
    if (shown < scene.bodies.length) {
      const note = document.createElement('p');
      note.className = 'static-note';
      note.textContent = `Controls for the first ${shown} of ${scene.bodies.length} bodies; edit the others in the ` +
                         'scene\'s JSON below.';
      container.appendChild(note);
    }
  };

  // ---------------------------------------------------------------------------------------------
  // The solver and the scene's defaults.

  const methodSelect = $('method');
  const dependentSelect = $('dependent');
  const restitutionSelect = $('restitution');
  const frictionRange = $('friction');
  const frictionNumber = $('friction-number');
  const defaultRange = $('default-elasticity');
  const defaultNumber = $('default-elasticity-number');

  // The contacts that have a μ of their own (the page edits only the scene's default): named
  // under the control, so that a reader knows why the slider does not move them.
  function contactFrictionNote(scene) {
    const own = scene.contacts.map((c, v) => [c, v]).filter(([c]) => c.friction !== undefined);
    if (own.length === 0) {
      return '';
    }
    const shown = own.slice(0, 6).map(([c, v]) => `contact ${v} (${c.bumper}–${c.wedge}) μ = ${num(Number(c.friction))}`);
    return `Contacts with a μ of their own, which the slider leaves as they are: ${shown.join('; ')}` +
           `${own.length > shown.length ? `; and ${own.length - shown.length} more` : ''} (edit them in the scene's JSON below).`;
  }

  collide.syncControls = () => {
    const scene = state.scene;
    for (const element of [methodSelect, dependentSelect, restitutionSelect, frictionRange, frictionNumber,
                           defaultRange, defaultNumber]) {
      element.disabled = !scene;
    }
    $('contact-friction').textContent = scene ? contactFrictionNote(scene) : '';
    if (scene) {
      const solver = isObject(scene.solver) ? scene.solver : {};
      methodSelect.value = solver.method || 'simultaneous';
      dependentSelect.value = solver.dependent || 'minimum-norm';
      restitutionSelect.value = solver.restitution || 'newton';
      // No key is μ = 0: a frictionless scene.
      const mu = scene.friction === undefined ? 0 : scene.friction;
      if (typeof mu === 'number') {
        if (document.activeElement !== frictionNumber && frictionNumber.valueAsNumber !== mu && !frictionNumber.validity.badInput) {
          frictionNumber.value = String(mu);
        }
        if (document.activeElement !== frictionRange) {
          frictionRange.value = String(mu);
        }
      }
      const hasDefault = typeof scene.elasticity === 'number';
      $('default-elasticity-row').hidden = !hasDefault;
      if (hasDefault) {
        if (document.activeElement !== defaultNumber && !defaultNumber.validity.badInput) {
          defaultNumber.value = String(scene.elasticity);
        }
        if (document.activeElement !== defaultRange) {
          defaultRange.value = String(scene.elasticity);
        }
      }
      for (const field of fields) {
        field.refresh(scene);
      }
    }
    $('preset').value = collide.matchingPreset();
    collide.fillSceneText();
  };

  function setSolver(key, value, fallback) {
    collide.edit((scene) => {
      if (!isObject(scene.solver)) {
        scene.solver = {};
      }
      if (value === fallback) {
        delete scene.solver[key];
      } else {
        scene.solver[key] = value;
      }
      if (Object.keys(scene.solver).length === 0) {
        delete scene.solver;
      }
    });
  }

  methodSelect.addEventListener('change', () => setSolver('method', methodSelect.value, 'simultaneous'));
  dependentSelect.addEventListener('change', () => setSolver('dependent', dependentSelect.value, 'minimum-norm'));
  // Newton's law is the default: choosing it removes the key, so that a scene without friction
  // stays the paper's, byte for byte.
  restitutionSelect.addEventListener('change', () => setSolver('restitution', restitutionSelect.value, 'newton'));

  // The scene's default μ. 0 removes the key (a frictionless scene keeps its text, and so its
  // address and result); a new key goes after the default elasticity, where the scene format's
  // examples write it, so that μ set back to a preset's value gives that preset's scene again.
  function setFriction(scene, mu) {
    if (mu === 0) {
      delete scene.friction;
      return;
    }
    if (Object.prototype.hasOwnProperty.call(scene, 'friction')) {
      scene.friction = mu;
      return;
    }
    const entries = Object.entries(scene);
    const after = entries.findIndex(([key]) => key === 'elasticity');
    const at = after >= 0 ? after + 1 : entries.findIndex(([key]) => key === 'dimension') + 1;
    entries.splice(at, 0, ['friction', mu]);
    for (const [key] of entries) {
      delete scene[key];
    }
    for (const [key, value] of entries) {
      scene[key] = value;
    }
  }
  frictionRange.addEventListener('input', (event) => {
    frictionNumber.value = frictionRange.value;
    fieldRefusal(frictionNumber, 'friction μ');
    collide.edit((scene) => setFriction(scene, Number(frictionRange.value)), {event, stream: 'friction-slider'});
  });
  frictionNumber.addEventListener('input', (event) => {
    fieldRefusal(frictionNumber, 'friction μ');
    if (frictionNumber.value.trim() === '' || !isFinite(frictionNumber.valueAsNumber)) {
      return;  // half typed, or refused at the field
    }
    frictionRange.value = frictionNumber.value;
    collide.edit((scene) => setFriction(scene, frictionNumber.valueAsNumber), {event, stream: 'friction-number'});
  });
  defaultRange.addEventListener('input', (event) => {
    defaultNumber.value = defaultRange.value;
    fieldRefusal(defaultNumber, 'elasticity of every body without its own');
    collide.edit((scene) => { scene.elasticity = Number(defaultRange.value); }, {event, stream: 'elasticity-slider'});
  });
  defaultNumber.addEventListener('input', (event) => {
    fieldRefusal(defaultNumber, 'elasticity of every body without its own');
    if (defaultNumber.value.trim() === '' || !isFinite(defaultNumber.valueAsNumber)) {
      return;
    }
    defaultRange.value = defaultNumber.value;
    collide.edit((scene) => { scene.elasticity = defaultNumber.valueAsNumber; }, {event, stream: 'elasticity-number'});
  });
  for (const input of [frictionNumber, defaultNumber]) {
    input.addEventListener('change', () => fieldRefusal(input, input === frictionNumber ? 'friction μ'
                                                                 : 'elasticity of every body without its own'));
  }
})(window.collide);
