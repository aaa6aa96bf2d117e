// SPDX-License-Identifier: GPL-3.0-or-later
// Headless Chromium driven through the DevTools protocol over a pipe (--remote-debugging-pipe):
// no driver to install, no browser downloaded; Debian's chromium, started as the docs test starts
// it (no sandbox, no GPU, no network: every host name unresolvable), with a fresh profile.
//
//   const browser = await Browser.launch();
//   const page = await browser.newPage({width: 1280, height: 800});
//   await page.goto('file:///…/collide.html#scene=…');
//   await page.waitFor('document.body.dataset.ready === "true"');
//   const text = await page.evaluate('document.getElementById("result-json").textContent');
//   await browser.close();
//
// Each page records what the page printed to the console as an error, the exceptions it threw
// and every request it made (page.problems(), page.requests). Browser.launch({hostResolverRules})
// lets a host through, e.g. 'MAP * ~NOTFOUND, EXCLUDE 127.0.0.1' for a test's own web server.
import {spawn} from 'node:child_process';
import {mkdtempSync, rmSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join} from 'node:path';

export class Browser {
  static async launch(options = {}) {
    const executable = process.env.IMPULSELAB_CHROMIUM || options.executable || '/usr/bin/chromium';
    const profile = mkdtempSync(join(tmpdir(), 'impulselab-web-'));
    const args = [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-default-apps', '--disable-extensions', '--mute-audio', '--hide-scrollbars',
      // Every tab runs at full speed, not only the one in front (a test may open several at once).
      '--disable-background-timer-throttling', '--disable-backgrounding-occluded-windows',
      '--disable-renderer-backgrounding',
      `--host-resolver-rules=${options.hostResolverRules || 'MAP * ~NOTFOUND'}`,
      `--user-data-dir=${profile}`, '--remote-debugging-pipe', 'about:blank',
    ];
    const child = spawn(executable, args, {stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe']});
    const browser = new Browser(child, profile);
    await new Promise((resolve, reject) => {
      child.once('spawn', resolve);
      child.once('error', (e) => reject(new Error(`cannot start ${executable}: ${e.message} ` +
                                                  '(scripts/install-deps chromium)')));
    });
    await browser.send('Browser.getVersion');
    return browser;
  }

  constructor(child, profile) {
    this.child = child;
    this.profile = profile;
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = new Map();  // sessionId -> handler(method, params)
    this.stderr = '';
    child.stderr.on('data', (d) => { this.stderr = (this.stderr + d).slice(-4000); });
    let buffer = '';
    child.stdio[4].on('data', (chunk) => {
      buffer += chunk.toString('utf8');
      let end;
      while ((end = buffer.indexOf('\0')) >= 0) {
        const message = JSON.parse(buffer.slice(0, end));
        buffer = buffer.slice(end + 1);
        this.receive(message);
      }
    });
    child.on('exit', (code) => {
      for (const {reject} of this.pending.values()) {
        reject(new Error(`chromium exited (${code}):\n${this.stderr}`));
      }
      this.pending.clear();
    });
  }

  receive(message) {
    if (message.id !== undefined) {
      const call = this.pending.get(message.id);
      this.pending.delete(message.id);
      if (!call) {
        return;
      }
      if (message.error) {
        call.reject(new Error(`${call.method}: ${message.error.message} ${message.error.data || ''}`));
      } else {
        call.resolve(message.result);
      }
    } else if (message.sessionId && this.listeners.has(message.sessionId)) {
      this.listeners.get(message.sessionId)(message.method, message.params);
    }
  }

  send(method, params = {}, sessionId = undefined) {
    const id = this.nextId++;
    const message = {id, method, params};
    if (sessionId) {
      message.sessionId = sessionId;
    }
    return new Promise((resolve, reject) => {
      this.pending.set(id, {resolve, reject, method});
      this.child.stdio[3].write(JSON.stringify(message) + '\0');
    });
  }

  async newPage({width = 1280, height = 800, deviceScaleFactor = 1, mobile = false} = {}) {
    const {targetId} = await this.send('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await this.send('Target.attachToTarget', {targetId, flatten: true});
    const page = new Page(this, sessionId, targetId);
    this.listeners.set(sessionId, (method, params) => page.event(method, params));
    await page.send('Page.enable');
    await page.send('Runtime.enable');
    await page.send('Log.enable');
    await page.send('Network.enable');
    await page.setViewport({width, height, deviceScaleFactor, mobile});
    return page;
  }

  async close() {
    try {
      await Promise.race([this.send('Browser.close'), new Promise((r) => setTimeout(r, 3000))]);
    } catch (e) {
      // already gone
    }
    if (this.child.exitCode === null) {
      const exited = new Promise((resolve) => this.child.once('exit', resolve));
      await Promise.race([exited, new Promise((r) => setTimeout(r, 3000))]);
    }
    if (this.child.exitCode === null) {
      this.child.kill('SIGKILL');
      await new Promise((resolve) => this.child.once('exit', resolve));
    }
    rmSync(this.profile, {recursive: true, force: true, maxRetries: 5, retryDelay: 100});
  }
}

export class Page {
  constructor(browser, sessionId, targetId) {
    this.browser = browser;
    this.sessionId = sessionId;
    this.targetId = targetId;
    this.errors = [];    // console errors, exceptions, failed loads
    this.requests = [];  // every URL requested
    this.waiters = [];
  }

  send(method, params = {}) {
    return this.browser.send(method, params, this.sessionId);
  }

  event(method, params) {
    if (method === 'Runtime.consoleAPICalled' && (params.type === 'error' || params.type === 'assert')) {
      this.errors.push(`console.${params.type}: ${params.args.map((a) => a.value ?? a.description).join(' ')}`);
    } else if (method === 'Runtime.exceptionThrown') {
      const d = params.exceptionDetails;
      this.errors.push(`exception: ${d.exception ? d.exception.description : d.text} at ${d.url}:${d.lineNumber}`);
    } else if (method === 'Log.entryAdded' && params.entry.level === 'error') {
      this.errors.push(`log: ${params.entry.text} ${params.entry.url || ''}`);
    } else if (method === 'Network.requestWillBeSent') {
      this.requests.push(params.request.url);
    }
    for (const waiter of this.waiters) {
      waiter(method, params);
    }
  }

  problems() {
    return [...this.errors];
  }

  async setViewport({width, height, deviceScaleFactor = 1, mobile = false}) {
    await this.send('Emulation.setDeviceMetricsOverride', {width, height, deviceScaleFactor, mobile});
  }

  // Navigates and waits for the load event (a change of the fragment alone loads nothing).
  async goto(url) {
    const loaded = new Promise((resolve) => {
      const waiter = (method) => {
        if (method === 'Page.loadEventFired') {
          this.waiters = this.waiters.filter((w) => w !== waiter);
          resolve();
        }
      };
      this.waiters.push(waiter);
    });
    const result = await this.send('Page.navigate', {url});
    if (result.errorText) {
      throw new Error(`cannot open ${url}: ${result.errorText}`);
    }
    await loaded;
  }

  async evaluate(expression) {
    const result = await this.send('Runtime.evaluate', {expression, returnByValue: true, awaitPromise: true});
    if (result.exceptionDetails) {
      const d = result.exceptionDetails;
      throw new Error(`evaluate: ${d.exception ? d.exception.description : d.text}`);
    }
    return result.result.value;
  }

  // Waits until @p expression is true in the page (polled), at most @p timeout ms.
  async waitFor(expression, timeout = 10000) {
    const start = Date.now();
    for (;;) {
      if (await this.evaluate(`Boolean(${expression})`)) {
        return;
      }
      if (Date.now() - start > timeout) {
        throw new Error(`timed out waiting for ${expression}`);
      }
      await new Promise((r) => setTimeout(r, 20));
    }
  }

  async screenshot(file, writeFile) {
    const {data} = await this.send('Page.captureScreenshot', {format: 'png', captureBeyondViewport: false});
    await writeFile(file, Buffer.from(data, 'base64'));
  }

  // The whole page: the window made as tall as the page for the shot, so that what is drawn only
  // near the window (content-visibility: auto) is drawn; then the window as it was.
  async fullScreenshot(file, writeFile, viewport) {
    const {cssContentSize} = await this.send('Page.getLayoutMetrics');
    const height = Math.ceil(cssContentSize.height);
    await this.setViewport({...viewport, height});
    await new Promise((r) => setTimeout(r, 200));
    const {data} = await this.send('Page.captureScreenshot', {format: 'png'});
    await writeFile(file, Buffer.from(data, 'base64'));
    await this.setViewport(viewport);
  }

  // Keyboard: a key on the focused element ('ArrowRight', 'Tab', 'Enter', ' ').
  async press(key) {
    const codes = {ArrowRight: 39, ArrowLeft: 37, ArrowUp: 38, ArrowDown: 40, Tab: 9, Enter: 13, ' ': 32,
                   Home: 36, End: 35};
    const code = codes[key];
    const params = {key, code: key === ' ' ? 'Space' : key, windowsVirtualKeyCode: code, nativeVirtualKeyCode: code};
    await this.send('Input.dispatchKeyEvent', {type: 'rawKeyDown', ...params});
    if (key === 'Enter' || key === ' ') {
      await this.send('Input.dispatchKeyEvent', {type: 'char', ...params, text: key === 'Enter' ? '\r' : ' '});
    }
    await this.send('Input.dispatchKeyEvent', {type: 'keyUp', ...params});
  }

  async mouse(type, x, y, buttons = 0) {
    await this.send('Input.dispatchMouseEvent', {type, x, y, button: type === 'mouseMoved' ? 'none' : 'left',
                                                 buttons, clickCount: type === 'mouseMoved' ? 0 : 1});
  }

  async drag(from, to, steps = 8) {
    await this.mouse('mouseMoved', from[0], from[1]);
    await this.mouse('mousePressed', from[0], from[1], 1);
    for (let k = 1; k <= steps; ++k) {
      await this.send('Input.dispatchMouseEvent', {
        type: 'mouseMoved', x: from[0] + (to[0] - from[0]) * k / steps,
        y: from[1] + (to[1] - from[1]) * k / steps, button: 'left', buttons: 1});
    }
    await this.mouse('mouseReleased', to[0], to[1], 0);
  }

  async close() {
    await this.browser.send('Target.closeTarget', {targetId: this.targetId});
  }
}
