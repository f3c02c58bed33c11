// The instructor's console page: logs in, shows the live view the server pushes over a WebSocket (/api/live), and
// sends control requests (/api/control) with the session's CSRF token and a fresh nonce each. Everything the server
// sends is put in the page as text (textContent), never as HTML.
'use strict';

const $ = (id) => document.getElementById(id);
const PLOT_SECONDS = 20;

let login = null;  // {user, role, csrf} while logged in
let socket = null;
let samples = [];  // [t_s, dv_ml, left_ml, right_ml], ordered by t_s, the last PLOT_SECONDS
let lastSnapshot = null;
let formsFilled = false;
let replaying = false;  // the view is a replay's (`lungar replay --console`): read-only

function hex(bytes) {
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

function nonce() {
  return hex(crypto.getRandomValues(new Uint8Array(16)));
}

function setStatus(text, isError) {
  const s = $('status');
  s.textContent = text;
  s.classList.toggle('error', !!isError);
}

// An observer watches, and a replay only plays: either way every control is off.
function readOnly() {
  return !login || login.role !== 'instructor' || replaying;
}

function applyReadOnly() {
  const off = readOnly();
  document.querySelectorAll('.control, #console input, #console select').forEach((e) => {
    e.disabled = off;
  });
}

function num(v, digits) {
  return typeof v === 'number' && isFinite(v) ? v.toFixed(digits) : '–';
}

// ---- logging in and out ------------------------------------------------------------------------------------------

async function doLogin(event) {
  event.preventDefault();
  $('login-error').textContent = '';
  try {
    const r = await fetch('api/login', {
      method: 'POST',
      credentials: 'same-origin',
      headers: {'Content-Type': 'application/json'},
      body: JSON.stringify({user: $('login-user').value, password: $('login-password').value}),
    });
    const body = await r.json().catch(() => ({}));
    if (!r.ok) {
      $('login-error').textContent = body.error || ('login refused (' + r.status + ')');
      return;
    }
    $('login-password').value = '';
    startConsole(body);
  } catch (e) {
    $('login-error').textContent = 'cannot reach the console: ' + e.message;
  }
}

function startConsole(body) {
  login = body;
  try {
    sessionStorage.setItem('lungar-login', JSON.stringify(body));
  } catch (e) { /* private mode */
  }
  $('login').hidden = true;
  $('console').hidden = false;
  $('logout').hidden = false;
  $('who').textContent = body.user + ' (' + body.role + ')';
  applyReadOnly();
  if (readOnly() && !replaying) setStatus('Observer: watching only; the controls are the instructor\'s.');
  fetchState();
  connect();
}

function endConsole(message) {
  login = null;
  try {
    sessionStorage.removeItem('lungar-login');
  } catch (e) { /* private mode */
  }
  if (socket) {
    socket.onclose = null;
    socket.close();
    socket = null;
  }
  $('console').hidden = true;
  $('logout').hidden = true;
  $('login').hidden = false;
  $('who').textContent = '';
  $('login-error').textContent = message || '';
  setLink(false);
}

async function doLogout() {
  await fetch('api/logout', {method: 'POST', credentials: 'same-origin'}).catch(() => {});
  endConsole('');
}

// ---- the live view -----------------------------------------------------------------------------------------------

function setLink(up) {
  const l = $('link-state');
  l.textContent = up ? 'live' : 'offline';
  l.className = up ? 'in-step' : 'lost';
}

async function fetchState() {
  const r = await fetch('api/state', {credentials: 'same-origin'}).catch(() => null);
  if (r && r.status === 401) return endConsole('Your session ended: log in again.');
  if (r && r.ok) render(await r.json().catch(() => null));
}

function connect() {
  if (!login) return;
  const url = (location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host +
      location.pathname.replace(/[^/]*$/, '') + 'api/live';
  socket = new WebSocket(url);
  socket.onopen = () => setLink(true);
  socket.onmessage = (m) => {
    try {
      render(JSON.parse(m.data));
    } catch (e) { /* a bad message: wait for the next */
    }
  };
  socket.onclose = () => {
    setLink(false);
    socket = null;
    // The session may have ended (the server closes the socket then): fetchState says so; else try again.
    setTimeout(() => {
      if (login) {
        fetchState();
        connect();
      }
    }, 2000);
  };
}

function render(s) {
  if (!s || typeof s !== 'object') return;
  lastSnapshot = s;
  const replay = s.replay && typeof s.replay === 'object' ? s.replay : null;
  if (!!replay !== replaying) {
    replaying = !!replay;
    $('mode').hidden = !replaying;
    applyReadOnly();
    if (replaying) setStatus('Replay of ' + (replay.file || 'a session record') + ': read-only, the controls are off.');
  }
  $('station').textContent = s.station ? (replaying ? 'recorded by ' : 'station ') + s.station : '';
  $('refused').textContent = s.refused ?? 0;
  renderBreath(s.breath || {});
  renderSamples(s.samples || []);
  renderOrientation(s.orientation || {});
  renderPostureControl(s.posture || {});
  renderDisplay(s.display || {});
  renderScenario(s.scenario || {});
  renderPathologies(s.pathologies || [], s.pathologies_changing || '');
  renderStations(s.stations || []);
  renderEvents(s.events || []);
  renderTimeline(s.events || [], s.t_s, replay);
  fillForms(s);
}

function renderBreath(b) {
  $('breath-state').textContent =
      b.state ? '— ' + b.state + (b.preset ? ', ' + b.preset : '') + (b.source ? ' (' + b.source + ')' : '') : '';
  // The form follows the breath until the user starts editing it.
  for (const [id, key] of [
           ['breath-rate', 'rate_bpm'], ['breath-tidal', 'tidal_volume_ml'], ['breath-ie', 'ie_ratio']]) {
    const e = $(id);
    if (document.activeElement !== e && !e.dataset.edited && typeof b[key] === 'number') e.value = b[key];
  }
  const preset = $('breath-preset');
  if (document.activeElement !== preset && !preset.dataset.edited && b.preset) preset.value = b.preset;
  // A breath followed from the patient (a trace, a chest marker): the console's changes take it over with the
  // model's until it is given back.
  $('breath-follow').hidden = !b.followed;
  $('breath-follow').disabled = readOnly() || !b.taken_over;
  $('breath-help').textContent = !b.followed ? '' :
      b.taken_over ? 'The console\'s breath is in place of ' + b.followed + ' on every station.' :
                     'The breath follows ' + b.followed + '; a change here takes it over with the model\'s.';
}

function renderSamples(list) {
  let newest = samples.length ? samples[samples.length - 1][0] : -Infinity;
  for (const row of list) {
    if (!Array.isArray(row) || typeof row[0] !== 'number') continue;
    if (row[0] < newest - 1) samples = [];  // time went back: a new run
    if (row[0] > newest) {
      samples.push(row);
      newest = row[0];
    }
  }
  while (samples.length && samples[0][0] < newest - PLOT_SECONDS) samples.shift();
  drawPlot();
}

function drawPlot() {
  const c = $('breath-plot');
  const w = c.clientWidth || c.width, h = c.clientHeight || c.height;
  const ratio = window.devicePixelRatio || 1;
  if (c.width !== Math.round(w * ratio)) {
    c.width = Math.round(w * ratio);
    c.height = Math.round(h * ratio);
  }
  const g = c.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.clearRect(0, 0, w, h);
  if (samples.length < 2) return;
  const t1 = samples[samples.length - 1][0], t0 = t1 - PLOT_SECONDS;
  let lo = 0, hi = 100;
  for (const r of samples)
    for (let i = 1; i < 4; i++)
      if (typeof r[i] === 'number') {
        lo = Math.min(lo, r[i]);
        hi = Math.max(hi, r[i]);
      }
  const pad = 24, x = (t) => pad + (t - t0) / PLOT_SECONDS * (w - pad - 4);
  const y = (v) => h - 16 - (v - lo) / (hi - lo) * (h - 28);
  g.strokeStyle = '#d8dde4';
  g.fillStyle = '#5b6676';
  g.font = '11px system-ui';
  g.lineWidth = 1;
  g.beginPath();
  g.moveTo(pad, y(0));
  g.lineTo(w - 4, y(0));
  g.stroke();
  g.fillText(Math.round(hi) + ' mL', 2, 12);
  g.fillText('-' + PLOT_SECONDS + ' s', pad, h - 3);
  g.fillText('now', w - 26, h - 3);
  for (const [i, colour] of [[2, '#1f6feb'], [3, '#e8710a'], [1, '#1c2430']]) {
    g.strokeStyle = colour;
    g.lineWidth = i === 1 ? 2 : 1.25;
    g.beginPath();
    let last = null;  // the previous sample's time: the pen lifts over a gap (no samples), drawing no made-up line
    for (const r of samples) {
      if (typeof r[i] !== 'number') {
        last = null;
        continue;
      }
      if (last !== null && r[0] - last < 0.25)
        g.lineTo(x(r[0]), y(r[i]));
      else
        g.moveTo(x(r[0]), y(r[i]));
      last = r[0];
    }
    g.stroke();
  }
}

function renderOrientation(o) {
  $('posture').textContent = o.posture || '–';
  $('pitch').textContent = num(o.pitch_deg, 1);
  $('roll').textContent = num(o.roll_deg, 1);
}

function renderPathologies(list, changing) {
  $('pathologies-changing').textContent = changing ? '(changing: ' + changing + ')' : '';
  const ul = $('pathologies');
  const key = JSON.stringify(list);
  if (ul.dataset.key === key) return;  // unchanged: keep what the user is typing in a severity box
  ul.dataset.key = key;
  ul.replaceChildren();
  const observer = readOnly();
  list.forEach((spec, i) => {
    const li = document.createElement('li');
    const code = document.createElement('code');
    code.textContent = spec;
    const to = document.createElement('input');
    to.id = 'pathology-to-' + i;
    to.value = spec;
    to.setAttribute('aria-label', 'new severity of ' + spec);
    const change = button(
        'Set', 'pathology-set-' + i,
        () => control({action: 'pathology_severity', spec: spec, to: to.value.trim(), over_s: overSeconds()}));
    const remove = button(
        'Remove', 'pathology-remove-' + i,
        () => control({action: 'pathology_remove', spec: spec, over_s: overSeconds()}));
    to.disabled = change.disabled = remove.disabled = observer;
    li.append(code, to, change, remove);
    ul.append(li);
  });
  if (!list.length) {
    const li = document.createElement('li');
    li.textContent = 'none';
    ul.append(li);
  }
}

function button(text, id, onclick) {
  const b = document.createElement('button');
  b.type = 'button';
  b.className = 'small control';
  b.id = id;
  b.textContent = text;
  b.addEventListener('click', onclick);
  return b;
}

function renderStations(list) {
  const rows = list.map((st) => {
    const tr = document.createElement('tr');
    const state = String(st.state ?? '–');
    const cells = [
      st.name ?? '–', state, num(st.breath_offset_ms, 1), num(st.pose_age_ms, 0), num(st.fps, 0),
      st.secure === true      ? 'yes' :
          st.secure === false ? 'no' :
                                '–'
    ];
    cells.forEach((text, i) => {
      const td = document.createElement('td');
      td.textContent = text;
      if (i >= 2 && i <= 4) td.className = 'num';
      if (i === 1) td.className = 'state-' + state.replace(/\s+/g, '-');
      tr.append(td);
    });
    return tr;
  });
  $('stations').replaceChildren(...rows);
}

function renderEvents(list) {
  const ol = $('events');
  const key = list.length + ':' + (list.length ? JSON.stringify(list[list.length - 1]) : '');
  if (ol.dataset.key === key) return;
  ol.dataset.key = key;
  ol.replaceChildren(...list.slice().reverse().map((e) => {
    const li = document.createElement('li');
    li.textContent =
        num(e.t_s, 1) + ' s · ' + (e.kind || '') + (e.text ? ': ' + e.text : '') + (e.user ? ' (' + e.user + ')' : '');
    return li;
  }));
}

// ---- the timeline: a tick per event over the session's time, coloured by kind; the cursor at the view's time -----

function kindClass(kind) {
  const first = String(kind || '').split(' ')[0];
  return 'k-' + (['pathology', 'breath', 'marker', 'refused'].includes(first) ? first : 'other');
}

function eventText(e) {
  return num(e.t_s, 1) + ' s · ' + (e.kind || '') + (e.text ? ': ' + e.text : '') + (e.user ? ' (' + e.user + ')' : '');
}

function chooseTick(tick) {
  document.querySelectorAll('#timeline .tick.chosen').forEach((t) => t.classList.remove('chosen'));
  if (!tick) return;
  tick.classList.add('chosen');
  $('timeline-text').textContent = tick.dataset.text;
}

// The tick nearest the pointer, within 24 px: a tap on a tablet need not hit a 4 px line.
function tickNear(clientX) {
  let best = null, bestDx = 24;
  document.querySelectorAll('#timeline .tick').forEach((t) => {
    const r = t.getBoundingClientRect();
    const dx = Math.abs(r.left + r.width / 2 - clientX);
    if (dx <= bestDx) {
      best = t;
      bestDx = dx;
    }
  });
  return best;
}

function renderTimeline(list, now, replay) {
  const strip = $('timeline');
  const cursor = typeof now === 'number' && isFinite(now) ? now : 0;
  // A replay's axis is the record's whole session; a live class's runs to now (the cursor at its right end).
  let span = Math.max(replay && typeof replay.duration_s === 'number' ? replay.duration_s : 0, cursor);
  for (const e of list)
    if (typeof e.t_s === 'number' && isFinite(e.t_s)) span = Math.max(span, e.t_s);
  if (!(span > 0)) span = 1;
  const key = list.length + ':' + (list.length ? JSON.stringify(list[list.length - 1]) : '');
  if (strip.dataset.key !== key) {
    strip.dataset.key = key;
    const chosen = strip.querySelector('.tick.chosen');
    const chosenText = chosen ? chosen.dataset.text : null;
    strip.querySelectorAll('.tick').forEach((t) => t.remove());
    list.forEach((e) => {
      const t = document.createElement('button');
      t.type = 'button';
      t.className = 'tick ' + kindClass(e.kind);
      t.dataset.t = typeof e.t_s === 'number' ? e.t_s : 0;
      t.dataset.text = eventText(e);
      t.title = t.dataset.text;
      t.setAttribute('aria-label', t.dataset.text);
      t.addEventListener('focus', () => chooseTick(t));
      if (t.dataset.text === chosenText) t.classList.add('chosen');
      strip.append(t);
    });
  }
  const at = (t) => Math.min(100, Math.max(0, t / span * 100)) + '%';
  strip.querySelectorAll('.tick').forEach((t) => {
    t.style.left = at(+t.dataset.t);
    t.classList.toggle('later', +t.dataset.t > cursor);
  });
  $('timeline-cursor').style.left = at(cursor);
  $('timeline-now').textContent =
      (replay ? '— replay at ' : '— now ') + num(cursor, 1) + ' s' + (replay ? ' of ' + num(span, 1) + ' s' : '');
  $('timeline-end').textContent = num(span, 1) + ' s';
}

// A tracked patient is turned by hand, on the table: the console turns a simulated one only.
function renderPostureControl(p) {
  const off = readOnly() || !p.simulated;
  for (const id of ['posture-choice', 'posture-over', 'posture-set']) $(id).disabled = off;
  $('posture-help').textContent =
      p.simulated === false ? 'A tracker measures the patient: turn the patient (or the mannequin) itself.' : '';
}

// The station's scenarios, the one loaded, where it stands, and a Jump button per cue.
function renderScenario(sc) {
  const available = Array.isArray(sc.available) ? sc.available : [];
  const choice = $('scenario-choice');
  const names = available.map((a) => a.name).join('\n');
  if (choice.dataset.names !== names) {
    choice.dataset.names = names;
    choice.replaceChildren(...available.map((a) => {
      const o = document.createElement('option');
      o.value = a.name;
      o.textContent = a.name + ' (' + num(a.duration_s, 0) + ' s)';
      o.title = a.description || '';
      return o;
    }));
  }
  const loaded = sc.loaded;
  const chosen = available.find((a) => a.name === choice.value);
  $('scenario-description').textContent = chosen ? chosen.description || '' : 'No scenario on this station.';
  $('scenario-state').textContent = loaded ? '— ' + loaded.name + ', ' + loaded.phase + ' at ' + num(loaded.t_s, 1) +
          ' of ' + num(loaded.duration_s, 0) + ' s' :
                                             '';
  const running = loaded && loaded.phase === 'running';
  const off = readOnly();
  $('scenario-load').disabled = off || !available.length || running || (loaded && loaded.phase === 'paused');
  $('scenario-start').disabled = off || !loaded || running || loaded.phase === 'ended';
  $('scenario-pause').disabled = off || !running;
  $('scenario-stop').disabled = off || !loaded || !(running || loaded.phase === 'paused' || loaded.phase === 'ended');
  const cues = loaded && Array.isArray(loaded.cues) ? loaded.cues : [];
  const list = $('scenario-cues');
  const key = loaded ? loaded.name + ':' + cues.length : '';
  if (list.dataset.key !== key) {
    list.dataset.key = key;
    list.replaceChildren(...cues.map((c, i) => {
      const li = document.createElement('li');
      const text = document.createElement('span');
      text.textContent = num(c.t_s, 1) + ' s · ' + c.kind + (c.text ? ': ' + c.text : '');
      li.append(text, button('Jump', 'scenario-jump-' + i, () => control({action: 'scenario_jump', cue: i})));
      return li;
    }));
  }
  cues.forEach((c, i) => {
    const li = list.children[i];
    if (!li) return;
    li.classList.toggle('done', !!loaded && c.t_s < loaded.t_s);
    li.querySelector('button').disabled = off;
  });
}

function renderDisplay(d) {
  const map = d.ventilation_map;
  $('ventilation-state').textContent = map === true ? 'shown' : map === false ? 'hidden' : 'each station\'s own';
}

function fillForms(s) {
  if (s.posture && Array.isArray(s.posture.choices) && !$('posture-choice').options.length) {
    $('posture-choice').replaceChildren(...s.posture.choices.map((p) => {
      const o = document.createElement('option');
      o.value = p;
      o.textContent = p.replace(/_/g, ' ');
      return o;
    }));
  }
  if (formsFilled) return;
  if (Array.isArray(s.presets) && s.presets.length) {
    $('breath-preset').replaceChildren(...s.presets.map((p) => {
      const o = document.createElement('option');
      o.value = p;
      o.textContent = p;
      return o;
    }));
    if (s.breath && s.breath.preset) $('breath-preset').value = s.breath.preset;
    formsFilled = true;
  }
  if (Array.isArray(s.pathology_forms)) {
    $('pathology-forms').replaceChildren(...s.pathology_forms.map((f) => {
      const o = document.createElement('option');
      o.value = f;
      return o;
    }));
    $('pathology-help').textContent = s.pathology_forms.join(' · ');
  }
}

// ---- control requests --------------------------------------------------------------------------------------------

function overSeconds() {
  const v = parseFloat($('pathology-over').value);
  return isFinite(v) ? v : 0;
}

async function control(request) {
  if (!login) return;
  setStatus('…');
  try {
    const r = await fetch('api/control', {
      method: 'POST',
      credentials: 'same-origin',
      headers: {'Content-Type': 'application/json', 'X-CSRF-Token': login.csrf, 'X-Request-Nonce': nonce()},
      body: JSON.stringify(request),
    });
    const body = await r.json().catch(() => ({}));
    if (r.status === 401) return endConsole('Your session ended: log in again.');
    if (!r.ok) return setStatus(body.error || ('refused (' + r.status + ')'), true);
    setStatus(body.done || body.text || (request.action.replace(/_/g, ' ') + ': done'));
    return body;
  } catch (e) {
    setStatus('cannot reach the console: ' + e.message, true);
  }
}

function breathSet() {
  const request = {action: 'breath_set'};
  const preset = $('breath-preset').value;
  if (preset && (!lastSnapshot || !lastSnapshot.breath || preset !== lastSnapshot.breath.preset))
    request.preset = preset;
  for (const [id, key] of [
           ['breath-rate', 'rate_bpm'], ['breath-tidal', 'tidal_volume_ml'], ['breath-ie', 'ie_ratio']]) {
    const v = parseFloat($(id).value);
    const now = lastSnapshot && lastSnapshot.breath ? lastSnapshot.breath[key] : undefined;
    if (isFinite(v) && v !== now) request[key] = v;
  }
  for (const id of ['breath-preset', 'breath-rate', 'breath-tidal', 'breath-ie']) delete $(id).dataset.edited;
  control(request);
}

function setUp() {
  $('login').addEventListener('submit', doLogin);
  $('logout').addEventListener('click', doLogout);
  $('breath-pause').addEventListener('click', () => control({action: 'breath_pause'}));
  $('breath-resume').addEventListener('click', () => control({action: 'breath_resume'}));
  $('breath-apply').addEventListener('click', breathSet);
  $('breath-follow').addEventListener('click', () => control({action: 'breath_follow'}));
  for (const id of ['breath-preset', 'breath-rate', 'breath-tidal', 'breath-ie'])
    $(id).addEventListener('input', () => {
      $(id).dataset.edited = '1';
    });
  $('pathology-add').addEventListener('click', async () => {
    const spec = $('pathology-spec').value.trim();
    if (!spec) return setStatus('Name a pathology to add (one of the forms below).', true);
    const r = await control({action: 'pathology_add', spec: spec, over_s: overSeconds()});
    if (r) $('pathology-spec').value = '';
  });
  $('posture-set').addEventListener('click', () => {
    const over = parseFloat($('posture-over').value);
    control({action: 'posture_set', posture: $('posture-choice').value, over_s: isFinite(over) ? over : 0});
  });
  $('scenario-choice')
      .addEventListener('change', () => renderScenario(lastSnapshot ? lastSnapshot.scenario || {} : {}));
  $('scenario-load')
      .addEventListener('click', () => control({action: 'scenario_load', name: $('scenario-choice').value}));
  $('scenario-start').addEventListener('click', () => control({action: 'scenario_start'}));
  $('scenario-pause').addEventListener('click', () => control({action: 'scenario_pause'}));
  $('scenario-stop').addEventListener('click', () => control({action: 'scenario_stop'}));
  $('ventilation-on').addEventListener('click', () => control({action: 'display_set', ventilation_map: true}));
  $('ventilation-off').addEventListener('click', () => control({action: 'display_set', ventilation_map: false}));
  $('marker-add').addEventListener('click', async () => {
    const text = $('marker-text').value.trim();
    if (!text) return;
    const r = await control({action: 'marker', text: text});
    if (r) $('marker-text').value = '';
  });
  $('marker-text').addEventListener('keydown', (e) => {
    if (e.key === 'Enter') $('marker-add').click();
  });
  window.addEventListener('resize', drawPlot);
  $('timeline').addEventListener('pointermove', (e) => {
    if (e.pointerType === 'mouse') chooseTick(tickNear(e.clientX));
  });
  $('timeline').addEventListener('click', (e) => chooseTick(tickNear(e.clientX)));
  // A reload keeps the session (the cookie is the server's; the CSRF token is kept for this tab only).
  let saved = null;
  try {
    saved = JSON.parse(sessionStorage.getItem('lungar-login'));
  } catch (e) {
    saved = null;
  }
  if (saved && saved.csrf) startConsole(saved);
}

document.addEventListener('DOMContentLoaded', setUp);
