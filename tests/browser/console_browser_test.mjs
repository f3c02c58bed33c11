#!/usr/bin/env node
// The instructor's console in a real browser: Debian's Chromium, headless, driven through the DevTools
// protocol by puppeteer-core. One headless instructor serving its console and two trainees, all real `lungar`
// processes on loopback (a DDS domain and a classroom of this run's own). Through the page's own controls the test
// logs in as the instructor, adds a pathology and pauses the breath, and reads both trainees' stats JSON (rewritten
// every 50 ms) until each shows it: within 0.5 s of the click. Then it resumes the breath, reads the page's DOM (the
// stations, the pathology), checks the layout at 1280x800 and 800x1280, and logs in as an observer in a second
// browser context: its controls are disabled and a control request from its JS is refused (403), changing nothing.
// Last, from the page, the ventilation map on every display (within 0.5 s) and one of the station's scenarios
// loaded and started (its supine start on both trainees within its 2 s of settling and 0.5 s).
//
//   node tests/browser/console_browser_test.mjs [--lungar PATH] [--chromium PATH] [--screenshot PNG]
//                                                [--screenshot-portrait PNG] [--keep] [--timeout S]
//
// Environment: LUNGAR_BINARY, CHROMIUM, LUNGAR_SCREENSHOT (the same as the options). scripts/test-browser runs it.
// Exit 0 on success; 1 with one "console_browser_test: FAIL: ..." line (after the logs that explain it) otherwise.
// Every child (the stations, the browser) is ended on success, failure, timeout and SIGINT/SIGTERM.
import {spawn, execFileSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {performance} from 'node:perf_hooks';
import {fileURLToPath} from 'node:url';

import puppeteer from 'puppeteer-core';

const NAME = 'console_browser_test';
const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const SPEC = 'pneumothorax:right:30';          // what the trainer adds
const FORBIDDEN_SPEC = 'pneumothorax:left:30';  // what the observer tries to add
const LIMIT_S = 0.5;                            // the most from a click to both trainees' stats JSON
const TRAINEES = ['trainee-1', 'trainee-2'];
const SCENARIO = 'tension pneumothorax';        // one of the shipped scenarios (config/scenarios/), supine from its start
const SETTLE_S = 2.0;                           // a scenario's start brings the class to it over this (ClassControl)

// ---- options ---------------------------------------------------------------------------------------------------

function parseOptions(argv) {
  const o = {
    lungar: process.env.LUNGAR_BINARY || path.join(ROOT, 'build', 'platform', 'lungar'),
    chromium: process.env.CHROMIUM || '/usr/bin/chromium',
    screenshot: process.env.LUNGAR_SCREENSHOT || '',
    screenshotPortrait: '',
    keep: false,
    timeoutS: 150,
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(a + ' needs a value');
      return argv[++i];
    };
    if (a === '--lungar') o.lungar = value();
    else if (a === '--chromium') o.chromium = value();
    else if (a === '--screenshot') o.screenshot = value();
    else if (a === '--screenshot-portrait') o.screenshotPortrait = value();
    else if (a === '--keep') o.keep = true;
    else if (a === '--timeout') o.timeoutS = Number(value());
    else if (a === '-h' || a === '--help') {
      console.log(fs.readFileSync(fileURLToPath(import.meta.url), 'utf8').split('\n').slice(1, 15)
        .map((l) => l.replace(/^\/\/ ?/, '')).join('\n'));
      process.exit(0);
    } else throw new Error('unknown option ' + a + ' (see --help)');
  }
  if (!(o.timeoutS > 0)) throw new Error('--timeout needs a positive number of seconds');
  return o;
}

// ---- failing, and cleaning up whatever happens ---------------------------------------------------------------------

class Failure extends Error {}
const fail = (message) => { throw new Failure(message); };
const check = (ok, message) => { if (!ok) fail(message); };

const children = new Set();  // the station processes still running
let browser = null;
let cleaning = null;

function alive(child) { return child.exitCode === null && child.signalCode === null; }

async function cleanup() {
  if (cleaning) return cleaning;
  cleaning = (async () => {
    if (browser) {
      const b = browser;
      browser = null;
      const proc = b.process();
      await Promise.race([b.close().catch(() => {}), sleep(3000)]);
      if (proc && proc.exitCode === null && proc.signalCode === null) proc.kill('SIGKILL');
    }
    for (const c of children) if (alive(c)) c.kill('SIGTERM');
    const until = Date.now() + 3000;
    while ([...children].some(alive) && Date.now() < until) await sleep(20);
    for (const c of children) if (alive(c)) c.kill('SIGKILL');
  })();
  return cleaning;
}

// The last resort (an exception escaping everything, process.exit): nothing may outlive the test.
process.on('exit', () => {
  for (const c of children) if (alive(c)) try { c.kill('SIGKILL'); } catch { /* gone */ }
  const proc = browser && browser.process();
  if (proc && proc.exitCode === null) try { proc.kill('SIGKILL'); } catch { /* gone */ }
});

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// ---- the stations -------------------------------------------------------------------------------------------------

class Station {
  constructor(lungar, name, args, dir) {
    this.name = name;
    this.out = '';
    this.err = '';
    this.log = fs.createWriteStream(path.join(dir, name + '.log'));
    this.child = spawn(lungar, args, {cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe']});
    children.add(this.child);
    this.child.stdout.on('data', (d) => { this.out += d; this.log.write(d); });
    this.child.stderr.on('data', (d) => { this.err += d; this.log.write(d); });
    this.child.on('error', (e) => { this.err += '\n(cannot run: ' + e.message + ')\n'; });
  }

  /// Resolves when `text` is in the station's output; fails when the station ends first or after `seconds`.
  async waitFor(text, seconds) {
    const until = performance.now() + seconds * 1000;
    while (performance.now() < until) {
      if (this.out.includes(text) || this.err.includes(text)) return;
      if (!alive(this.child)) fail(`${this.name} ended (${this.child.exitCode ?? this.child.signalCode}) before "${text}":\n${this.tail()}`);
      await sleep(20);
    }
    fail(`${this.name}: no "${text}" within ${seconds} s:\n${this.tail()}`);
  }

  tail(lines = 25) {
    return (this.out + this.err).trimEnd().split('\n').slice(-lines).map((l) => `  ${this.name}| ${l}`).join('\n');
  }
}

function readStats(file) {
  try { return JSON.parse(fs.readFileSync(file, 'utf8')); } catch { return null; }
}

/// Seconds from `since` (performance.now() ms) until `ok` first holds of each trainee's stats JSON, polled every 5 ms;
/// fails after `seconds` naming what the slow one shows.
async function secondsUntilEach(statsFiles, since, ok, what, seconds = 5, page = null) {
  const seen = new Map();
  while (seen.size < statsFiles.size) {
    const now = performance.now();
    for (const [name, file] of statsFiles) {
      if (seen.has(name)) continue;
      const s = readStats(file);
      if (s && ok(s)) seen.set(name, (now - since) / 1000);
    }
    if (seen.size === statsFiles.size) break;
    if (now - since > seconds * 1000) {
      const late = [...statsFiles.keys()].filter((n) => !seen.has(n));
      const shows = late.map((n) => {
        const s = readStats(statsFiles.get(n));
        return `${n}: pathologies ${JSON.stringify(s?.pathologies)}, breath_state ${JSON.stringify(s?.breath_state)}`;
      });
      const says = page ? `; the page: ${await pageSays(page).catch(() => '?')}` : '';
      fail(`${what}: not in ${late.join(', ')}'s stats JSON within ${seconds} s (${shows.join('; ')}${says})`);
    }
    await sleep(5);
  }
  return seen;
}

// ---- the browser --------------------------------------------------------------------------------------------------

/// base64(sha256(SubjectPublicKeyInfo)) of the certificate: what --ignore-certificate-errors-spki-list trusts.
function spkiHash(certPem) {
  const pub = execFileSync('openssl', ['x509', '-in', certPem, '-noout', '-pubkey']);
  const der = execFileSync('openssl', ['pkey', '-pubin', '-outform', 'der'], {input: pub});
  return execFileSync('openssl', ['dgst', '-sha256', '-binary'], {input: der}).toString('base64');
}

/// Console messages, uncaught exceptions and failed requests of a page; `expected` (a RegExp) marks the ones the
/// test provokes on purpose (a refused request is logged by Chromium as a console error).
function watchPage(page, label, problems) {
  page.on('console', (m) => {
    if (m.type() === 'error' || m.type() === 'warn') problems.push({label, kind: 'console.' + m.type(), text: m.text()});
  });
  page.on('pageerror', (e) => problems.push({label, kind: 'exception', text: String(e && e.message || e)}));
  page.on('response', (r) => {
    if (r.status() >= 400) problems.push({label, kind: 'response', text: `${r.request().method()} ${new URL(r.url()).pathname} ${r.status()}`});
  });
  page.on('requestfailed', (r) => {
    problems.push({label, kind: 'request failed', text: r.url() + ' ' + (r.failure()?.errorText || '')});
  });
}

async function logIn(page, url, user, password) {
  const response = await page.goto(url, {waitUntil: 'domcontentloaded', timeout: 15000});
  check(response && response.ok(), `GET ${url}: ${response ? response.status() : 'no response'}`);
  // The page runs under its own origin's policy only: nothing inline, nothing from elsewhere.
  const csp = response.headers()['content-security-policy'] || '';
  check(/default-src 'self'/.test(csp), `the page is served without a Content-Security-Policy of default-src 'self' ("${csp}")`);
  await page.waitForSelector('#login-user', {visible: true, timeout: 10000});
  const shownBefore = await page.$eval('#console', (e) => getComputedStyle(e).display !== 'none');
  check(!shownBefore, `before logging in as ${user} the page shows the console (its controls and views) already`);
  await page.type('#login-user', user);
  await page.type('#login-password', password);
  await page.click('#login-submit');
  try {
    // Shown and hidden as the user sees them (computed style), not just the attributes.
    await page.waitForSelector('#console', {visible: true, timeout: 10000});
    await page.waitForSelector('#login', {hidden: true, timeout: 2000});
  } catch {
    const shown = await page.evaluate(() => ['console', 'login'].map((id) => getComputedStyle(document.getElementById(id)).display !== 'none'));
    const why = await page.$eval('#login-error', (e) => e.textContent).catch(() => '');
    fail(`logging in as ${user} through the form: the console is ${shown[0] ? 'shown' : 'not shown'}, the login form ` +
         `${shown[1] ? 'still shown' : 'hidden'} (${why || 'no error shown'})`);
  }
  const who = await page.$eval('#who', (e) => e.textContent);
  check(who.includes(user), `logged in as ${user}, the page says "${who}"`);
}

/// The names in the page's stations table.
const stationNames = (page) => page.$$eval('#stations tr', (rows) => rows.map((r) => r.cells[0]?.textContent ?? ''));

/// Waits until `fn` (run in the page) returns truthy; fails with `what` after `seconds`.
async function pageWaits(page, fn, what, seconds = 10, ...args) {
  try {
    await page.waitForFunction(fn, {timeout: seconds * 1000, polling: 50}, ...args);
  } catch {
    fail(typeof what === 'function' ? await what() : what);
  }
}

/// What the page shows (for a failure's line): its status, its link, its pathologies and breath.
const pageSays = (page) => page.evaluate(() => ['status', 'link-state', 'pathologies', 'breath-state']
  .map((id) => `#${id} "${document.getElementById(id)?.textContent.trim().replace(/\s+/g, ' ')}"`).join(', ') +
  // eslint-disable-next-line no-undef -- the page's own script's top-level binding
  (typeof lastSnapshot === 'object' && lastSnapshot ? `, its last view at ${Number(lastSnapshot.t_s).toFixed(2)} s: ${JSON.stringify(lastSnapshot.pathologies)}` : ''));

/// The page's scroll width against its window's: a layout wider than the screen breaks a tablet.
async function layoutFits(page, label) {
  const m = await page.evaluate(() => ({scroll: document.documentElement.scrollWidth, inner: window.innerWidth}));
  check(m.scroll <= m.inner + 1, `layout at ${label}: the page is ${m.scroll} px wide in a ${m.inner} px window (it scrolls sideways)`);
}

/// Every control of the page (buttons, inputs, selects in the console) and whether each is disabled.
const controlsOf = (page) => page.$$eval('#console button.control, #console input, #console select',
  (list) => list.map((e) => ({id: e.id || e.tagName, disabled: e.disabled})));

// ---- the test -----------------------------------------------------------------------------------------------------

async function run(o, tmp, problems, results) {
  check(fs.existsSync(o.lungar), `no lungar at ${o.lungar} (build it: scripts/build, or pass --lungar)`);
  check(fs.existsSync(o.chromium), `no Chromium at ${o.chromium} (apt-get install chromium, or pass --chromium)`);

  // The classroom's keys: the console's certificate and logins come from its authority.
  const room = `browser-${process.pid}-${Math.floor(Math.random() * 1e6)}`;
  const domain = String(1 + (process.pid + 97) % 230);
  const keys = path.join(tmp, 'keys');
  execFileSync(o.lungar, ['classroom-keys', '--classroom', room, '--station', 'instructor', ...TRAINEES.flatMap((t) => ['--station', t]),
    '--out', keys], {stdio: ['ignore', 'pipe', 'pipe']});
  const consoleKeys = path.join(keys, 'console');
  const password = (login) => fs.readFileSync(path.join(consoleKeys, login + '.password'), 'utf8').split('\n')[0].trim();

  const station = (name, role, extra) => new Station(o.lungar, name, [
    '--config', path.join(ROOT, 'config', 'classroom-station.toml'), '--asset', path.join(ROOT, 'tests', 'data', 'hil_lungs.lungbake'),
    '--sync', role, '--station', name, '--classroom', room, '--sync-domain', domain, '--seconds', '90', '--tracker', 'mock',
    '--stats-json', path.join(tmp, name + '.json'), '--snapshot', path.join(tmp, name + '.png'), ...extra], tmp);

  const started = performance.now();
  const instructor = station('instructor', 'instructor', ['--console', '127.0.0.1:0', '--console-keys', consoleKeys]);
  const stations = [instructor];
  results.stations = stations;
  await instructor.waitFor('console: https://', 30);
  const m = /console: (https:\/\/[^/\s]+\/)/.exec(instructor.err + instructor.out);
  check(m, 'no console URL in the instructor\'s log');
  const url = m[1];
  const statsFiles = new Map(TRAINEES.map((t) => [t, path.join(tmp, t + '.json')]));
  for (const t of TRAINEES) stations.push(station(t, 'trainee', ['--stats-every', '0.05']));
  for (const s of stations.slice(1)) await s.waitFor("sync: in step with instructor 'instructor'", 30);
  results.classS = (performance.now() - started) / 1000;

  // Chromium trusts the console's own key (its SPKI hash), nothing else: no blanket --ignore-certificate-errors.
  const spki = spkiHash(path.join(consoleKeys, 'server_cert.pem'));
  const args = [`--ignore-certificate-errors-spki-list=${spki}`, '--disable-dev-shm-usage', '--no-first-run',
                '--no-default-browser-check', '--disable-background-networking', '--disable-extensions'];
  if (process.getuid && process.getuid() === 0) args.push('--no-sandbox');  // Chromium refuses root without it
  browser = await puppeteer.launch({
    executablePath: o.chromium, headless: true, userDataDir: path.join(tmp, 'chromium-profile'), args,
    defaultViewport: {width: 1280, height: 800}, timeout: 30000, protocolTimeout: 30000,
    handleSIGINT: false, handleSIGTERM: false, handleSIGHUP: false,  // ours (cleanup()) end the browser and the stations
  });
  results.chromium = await browser.version();

  // ---- the instructor, through the page's controls
  const page = await browser.newPage();
  watchPage(page, 'instructor page', problems);
  try {
    await logIn(page, url, 'instructor', password('instructor'));
  } catch (e) {
    if (String(e.message).includes('ERR_CERT')) fail(`Chromium did not trust the console's key by its SPKI hash: ${e.message}`);
    throw e;
  }
  await pageWaits(page, () => document.getElementById('link-state').textContent === 'live',
    'the page\'s live view (WebSocket /api/live) did not connect within 10 s');
  await pageWaits(page, (names) => {
    const shown = Array.from(document.querySelectorAll('#stations tr'), (r) => r.cells[0]?.textContent);
    return names.every((n) => shown.includes(n));
  }, async () => `the page does not list both trainees within 10 s (it lists ${JSON.stringify(await stationNames(page))})`, 10, TRAINEES);
  // A few breaths on the plot before the changes, so that the screenshot shows the breath and then the hold.
  await sleep(6000);

  await page.click('#pathology-spec', {clickCount: 3});
  await page.type('#pathology-spec', SPEC);
  let clicked = performance.now();
  await page.click('#pathology-add');
  const added = results.added = await secondsUntilEach(statsFiles, clicked, (s) => Array.isArray(s.pathologies) && s.pathologies.includes(SPEC),
    `the pathology ${SPEC} added from the page`, 5, page);
  await pageWaits(page, (spec) => Array.from(document.querySelectorAll('#pathologies code'), (c) => c.textContent).includes(spec),
    async () => `the page does not show the pathology ${SPEC} within 5 s (${await pageSays(page)})`, 5, SPEC);

  clicked = performance.now();
  await page.click('#breath-pause');
  const paused = results.paused = await secondsUntilEach(statsFiles, clicked, (s) => s.breath_state === 'paused', 'the breath paused from the page', 5, page);
  await pageWaits(page, () => /paused/.test(document.getElementById('breath-state').textContent),
    async () => `the page does not show the breath paused within 5 s (${await pageSays(page)})`, 5);
  const statusLine = await page.$eval('#status', (e) => (e.classList.contains('error') ? 'error: ' : '') + e.textContent);
  check(!statusLine.startsWith('error: '), `the page's status after the pause: ${statusLine}`);

  // What the page shows now: the two trainees, the pathology; a screenshot of it at a 10-inch tablet's 1280x800.
  const names = await stationNames(page);
  for (const t of TRAINEES) check(names.includes(t), `the page's stations are ${JSON.stringify(names)}: no ${t}`);
  await sleep(1500);  // the held breath shows as a flat line on the plot
  await page.evaluate(() => window.scrollTo(0, 0));  // the clicks scrolled the buttons into view
  await layoutFits(page, '1280x800');
  const shot = o.screenshot || path.join(tmp, 'console-tablet.png');
  fs.mkdirSync(path.dirname(path.resolve(shot)), {recursive: true});
  // The whole page as laid out in the tablet's window (it scrolls below the fold: the stations, the pathologies).
  await page.screenshot({path: shot, fullPage: true});
  results.screenshots.push(shot);
  // The same tablet held upright.
  await page.setViewport({width: 800, height: 1280});
  await sleep(400);
  await page.evaluate(() => window.scrollTo(0, 0));
  await layoutFits(page, '800x1280');
  const portrait = o.screenshotPortrait || path.join(tmp, 'console-portrait.png');
  fs.mkdirSync(path.dirname(path.resolve(portrait)), {recursive: true});
  await page.screenshot({path: portrait, fullPage: true});
  results.screenshots.push(portrait);
  await page.setViewport({width: 1280, height: 800});

  clicked = performance.now();
  await page.click('#breath-resume');
  const resumed = results.resumed = await secondsUntilEach(statsFiles, clicked, (s) => s.breath_state === 'breathing', 'the breath resumed from the page', 5, page);

  // A control request without the session's CSRF token, from the instructor's own page: refused.
  const noCsrf = await page.evaluate(async () => {
    const r = await fetch('api/control', {method: 'POST', credentials: 'same-origin',
      headers: {'Content-Type': 'application/json'}, body: JSON.stringify({action: 'breath_pause'})});
    return r.status;
  });
  check(noCsrf === 403, `a control request without the CSRF token got ${noCsrf}, not 403`);

  // ---- an observer, in a browser context of its own (its own cookie)
  const context = await browser.createBrowserContext();
  const watcher = await context.newPage();
  watchPage(watcher, 'observer page', problems);
  await logIn(watcher, url, 'observer', password('observer'));
  await pageWaits(watcher, (spec) => Array.from(document.querySelectorAll('#pathologies code'), (c) => c.textContent).includes(spec),
    `the observer's page does not show the pathology ${SPEC} within 10 s`, 10, SPEC);
  const controls = await controlsOf(watcher);
  const enabled = controls.filter((c) => !c.disabled).map((c) => c.id);
  check(controls.length >= 8, `the observer's page has only ${controls.length} controls: the page changed?`);
  check(enabled.length === 0, `the observer's page leaves controls enabled: ${enabled.join(', ')}`);
  const observerTry = await watcher.evaluate(async (spec) => {
    const login = JSON.parse(sessionStorage.getItem('lungar-login') || '{}');
    const nonce = Array.from(crypto.getRandomValues(new Uint8Array(16)), (b) => b.toString(16).padStart(2, '0')).join('');
    const r = await fetch('api/control', {method: 'POST', credentials: 'same-origin',
      headers: {'Content-Type': 'application/json', 'X-CSRF-Token': login.csrf || '', 'X-Request-Nonce': nonce},
      body: JSON.stringify({action: 'pathology_add', spec, over_s: 0})});
    return {status: r.status, role: login.role, csrf: !!login.csrf};
  }, FORBIDDEN_SPEC);
  check(observerTry.role === 'observer' && observerTry.csrf, `the observer's login is ${JSON.stringify(observerTry)}`);
  check(observerTry.status === 403, `the observer's control request (with its own CSRF token) got ${observerTry.status}, not 403`);
  await sleep(1000);  // two heartbeats: had it been taken, the trainees would show it
  for (const [t, file] of statsFiles) {
    const s = readStats(file);
    check(s && !s.pathologies.includes(FORBIDDEN_SPEC), `${t} shows ${FORBIDDEN_SPEC}: the observer's refused request changed the class`);
    check(s && s.pathologies.includes(SPEC) && s.breath_state === 'breathing', `${t}'s stats JSON now: ${JSON.stringify(s && {p: s.pathologies, b: s.breath_state})}`);
  }
  const refused = Number(await page.$eval('#refused', (e) => e.textContent));
  check(refused >= 2, `the page counts ${refused} refused requests, not the 2 made`);

  // ---- the ventilation map on every display, then one of the station's scenarios run on the class
  clicked = performance.now();
  await page.click('#ventilation-on');
  results.map = await secondsUntilEach(statsFiles, clicked, (s) => s.ventilation_map === true,
    'the ventilation map shown from the page', 5, page);
  await page.select('#scenario-choice', SCENARIO);
  await page.click('#scenario-load');
  await pageWaits(page, () => /ready/.test(document.getElementById('scenario-state').textContent),
    async () => `the page does not show the scenario ready within 5 s (${await pageSays(page)})`, 5);
  clicked = performance.now();
  await page.click('#scenario-start');
  // The scenario starts supine: the class turns over its 2 s of settling, and both trainees draw it.
  results.scenario = await secondsUntilEach(statsFiles, clicked,
    (s) => Array.isArray(s.gravity_lung_last) && s.gravity_lung_last[1] > 0.99,
    `the scenario '${SCENARIO}' started from the page (its patient supine)`, 8, page);
  await pageWaits(page, () => /running/.test(document.getElementById('scenario-state').textContent) &&
      document.querySelectorAll('#scenario-cues li button').length > 0,
    async () => `the page does not show the scenario running with its cues within 5 s (${await pageSays(page)})`, 5);

  // Everything the pages logged, except the two refusals provoked above (Chromium logs a 403 as a console error).
  const provoked = /^POST \/api\/control 403$|status of 403 \(Forbidden\)$/;
  const unexpected = problems.filter((p) => !provoked.test(p.text));
  check(unexpected.length === 0, `the pages logged ${unexpected.length} error(s): ` +
    unexpected.map((p) => `[${p.label} ${p.kind}] ${p.text}`).join(' | '));

  for (const s of stations) check(alive(s.child), `${s.name} ended during the test:\n${s.tail()}`);
}

async function main() {
  let o;
  try {
    o = parseOptions(process.argv.slice(2));
  } catch (e) {
    console.error(`${NAME}: FAIL: ${e.message}`);
    process.exit(2);
  }
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'lungar_browser_'));
  const problems = [];
  const results = {screenshots: [], stations: []};
  const t0 = performance.now();
  let failure = null;
  let timer;
  const onSignal = (sig) => { failure = failure || `interrupted (${sig})`; cleanup().finally(() => finish()); };
  for (const sig of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.on(sig, onSignal);
  const timeout = new Promise((resolve) => {
    timer = setTimeout(() => resolve(`the whole test took over ${o.timeoutS} s`), o.timeoutS * 1000);
  });
  try {
    const outcome = await Promise.race([run(o, tmp, problems, results).then(() => null), timeout]);
    if (outcome) failure = outcome;
  } catch (e) {
    failure = e instanceof Failure ? e.message : `${e && e.stack || e}`;
  }
  clearTimeout(timer);
  await cleanup();
  finish();

  function finish() {
    const wall = ((performance.now() - t0) / 1000).toFixed(1);
    const ms = (map, t) => (map && map.has(t) ? (map.get(t) * 1000).toFixed(0) + ' ms' : '–');
    if (results.added) {
      console.log(`${NAME}: click to stats JSON: ` + TRAINEES.map((t) =>
        `${t} pathology ${ms(results.added, t)}, pause ${ms(results.paused, t)}, resume ${ms(results.resumed, t)}, ` +
        `ventilation map ${ms(results.map, t)}, scenario start (a 2 s turn) ${ms(results.scenario, t)}`).join('; ') +
        ` (limit ${LIMIT_S * 1000} ms)`);
    }
    if (!failure) {
      if (problems.length) console.log(`${NAME}: provoked on purpose and logged by the pages: ` + problems.map((p) => p.text).join(' | '));
      console.log(`${NAME}: ${results.chromium}; class in step ${results.classS.toFixed(1)} s after the start; screenshots ${results.screenshots.join(', ')}`);
      const slow = [];
      for (const [what, map, limit] of [['pathology', results.added, LIMIT_S], ['pause', results.paused, LIMIT_S],
                                         ['the ventilation map', results.map, LIMIT_S],
                                         ['the scenario\'s start', results.scenario, SETTLE_S + LIMIT_S]]) {
        for (const t of TRAINEES) if (map.get(t) > limit) slow.push(`${what} reached ${t} after ${ms(map, t)}`);
      }
      if (slow.length) failure = `over ${LIMIT_S * 1000} ms from the click: ${slow.join(', ')}`;
    }
    // The screenshots stay (under the temporary folder unless asked elsewhere); the rest goes unless --keep or a failure.
    if (failure) {
      const [head, ...rest] = failure.split('\n');
      if (rest.length) console.error(rest.join('\n'));
      for (const s of results.stations) console.error(s.tail(15));
      for (const p of problems) console.error(`  [${p.label} ${p.kind}] ${p.text}`);
      console.error(`  (logs and stats JSON in ${tmp})`);
      console.error(`${NAME}: FAIL: ${head}`);
      process.exit(1);
    }
    if (!o.keep) {
      const kept = new Set(results.screenshots.map((s) => path.resolve(s)));
      for (const e of fs.readdirSync(tmp)) if (!kept.has(path.join(tmp, e))) fs.rmSync(path.join(tmp, e), {recursive: true, force: true});
      if (!fs.readdirSync(tmp).length) fs.rmSync(tmp, {recursive: true, force: true});
    }
    console.log(`${NAME}: ok in ${wall} s` + (o.keep ? ` (everything kept in ${tmp})` : ''));
    process.exit(0);
  }
}

main();
