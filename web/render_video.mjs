// Renders the animation page of `tumble run --animate` into a video, so that the video and the
// page come from one renderer: headless Chromium opens the page offline, puts it in video mode
// (window.tumble.videoMode(): the 3D view alone, with the name and the time over it), seeks to
// each frame's time, screenshots the viewport as PNG and pipes the PNGs to ffmpeg.
//   node web/render_video.mjs PAGE OUTPUT WIDTH HEIGHT FPS SPEED FRAMES [CHROMIUM]
// `tumble run --video` runs it (app/video_export.cpp), which computes FRAMES (docs/video.md):
// frame k shows t = t0 + k * SPEED / FPS, where t0 is the page's first row, and lasts 1 / FPS, so
// the video lasts FRAMES / FPS. OUTPUT ends in .mp4 (H.264, yuv420p: WIDTH and HEIGHT even) or
// .gif. ffmpeg writes it under a temporary name beside OUTPUT that is renamed only once ffmpeg
// has succeeded: OUTPUT is never half written, and nothing is left behind on failure.
// Environment: TUMBLE_FFMPEG (default `ffmpeg` on PATH), TUMBLE_CHROMIUM (default
// /usr/bin/chromium) when CHROMIUM is not given. Exit status 0 done, 2 bad arguments, 1 anything
// else, with one line on stderr saying why.
import { spawn } from 'node:child_process';
import { once } from 'node:events';
import {
  existsSync, mkdtempSync, readdirSync, readFileSync, renameSync, rmSync, statSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
// Resolved from web/node_modules, where web/package-lock.json pins it with the page's packages.
import { chromium } from 'playwright-core';

// A failure the user can act on: its message is the whole report.
class Failure extends Error {}

function parseArguments(argv) {
  const usage =
    'usage: node render_video.mjs PAGE OUTPUT WIDTH HEIGHT FPS SPEED FRAMES [CHROMIUM]';
  if (argv.length < 7 || argv.length > 8) throw new Failure(usage);
  const [page, output, width, height, fps, speed, frames, browser] = argv;
  const integer = (text, name, lo, hi) => {
    const n = Number(text);
    if (!/^[0-9]+$/.test(text) || n < lo || n > hi) {
      throw new Failure(`${name} ${text}: expected a whole number from ${lo} to ${hi}`);
    }
    return n;
  };
  const format = { '.mp4': 'mp4', '.gif': 'gif' }[/\.[^./]*$/.exec(output)?.[0].toLowerCase()];
  if (!format) throw new Failure(`${output}: the video's name must end in .mp4 or .gif`);
  const args = {
    page: resolve(page),
    output: resolve(output),
    format,
    width: integer(width, 'WIDTH', 16, 8192),
    height: integer(height, 'HEIGHT', 16, 8192),
    fps: integer(fps, 'FPS', 1, 240),
    speed: Number(speed),
    frames: integer(frames, 'FRAMES', 1, 1e6),
    chromium: browser ?? process.env.TUMBLE_CHROMIUM ?? '/usr/bin/chromium',
  };
  if (!(args.speed > 0 && Number.isFinite(args.speed))) {
    throw new Failure(`SPEED ${speed}: expected a positive number`);
  }
  // H.264 in yuv420p stores colour at half resolution in both directions.
  if (format === 'mp4' && (args.width % 2 !== 0 || args.height % 2 !== 0)) {
    throw new Failure(`${args.width}x${args.height}: an .mp4 needs an even width and height`);
  }
  return args;
}

function ffmpegArguments({ format, fps }, partial) {
  const input = ['-hide_banner', '-loglevel', 'error', '-y',
    '-f', 'image2pipe', '-framerate', String(fps), '-c:v', 'png', '-i', '-'];
  if (format === 'mp4') {
    // yuv420p and faststart (the index first): plays in every browser and slide program, and
    // starts before it has all downloaded.
    return [...input, '-c:v', 'libx264', '-preset', 'medium', '-crf', '18', '-pix_fmt', 'yuv420p',
      '-movflags', '+faststart', '-f', 'mp4', partial];
  }
  // One palette for the whole GIF, made from every frame (palettegen) and applied to each
  // (paletteuse), in one graph so the frames are decoded once. Ordered dithering and only the
  // changed rectangle per frame keep a mostly white scene small.
  return [...input, '-vf',
    'split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle',
    '-loop', '0', '-f', 'gif', partial];
}

// ffmpeg with PNGs on its stdin; its last message is kept for the report.
async function startEncoder(args, partial) {
  const program = process.env.TUMBLE_FFMPEG ?? 'ffmpeg';
  const child = spawn(program, ffmpegArguments(args, partial), { stdio: ['pipe', 'ignore', 'pipe'] });
  let log = '';
  child.stderr.setEncoding('utf8');
  child.stderr.on('data', (text) => { log = (log + text).slice(-8000); });
  // EPIPE if ffmpeg quits early: its exit status and message say why.
  child.stdin.on('error', () => {});
  try {
    await once(child, 'spawn');
  } catch (e) {
    throw new Failure(e.code === 'ENOENT'
      ? `ffmpeg not found (${program}): install it (Debian: apt-get install ffmpeg, or ` +
        'scripts/setup.sh) or set TUMBLE_FFMPEG'
      : `cannot run ${program}: ${e.message}`);
  }
  const exited = new Promise((done) => child.on('close', (code, signal) => done({ code, signal })));
  const why = ({ code, signal }) => {
    const last = log.trim().split('\n').at(-1) ?? '';
    return `ffmpeg failed (${signal ? `signal ${signal}` : `exit status ${code}`})` +
      (last ? `: ${last}` : '');
  };
  let ended = null;
  exited.then((r) => { ended = r; });
  return {
    child,
    exited,
    async write(png) {
      if (ended) throw new Failure(why(ended));
      if (child.stdin.write(png)) return;
      // A write error (EPIPE) means ffmpeg has quit: its exit says why.
      const drained = once(child.stdin, 'drain').then(() => null, () => exited);
      const r = await Promise.race([drained, exited]);
      if (r) throw new Failure(why(r));
    },
    async finish() {
      child.stdin.end();
      const r = await exited;
      if (r.code !== 0) throw new Failure(why(r));
    },
  };
}

// Chromium's processes for this render, by their process groups. Playwright starts the browser as
// the leader of a group of its own, which its helpers (zygote, renderers, GPU process, crash
// handler) join; the browser is found by its command line, whose --user-data-dir is in SCRATCH.
// Linux's /proc; elsewhere nothing is found and the browser is left to Playwright alone.
function processIds() {
  try {
    return readdirSync('/proc').filter((name) => /^[0-9]+$/.test(name));
  } catch {
    return [];
  }
}

// A process's state letter and group from /proc/PID/stat ("PID (COMM) STATE PPID PGRP ..."; COMM
// may hold spaces and parentheses, so the fields are counted from its last ')').
function processStat(pid) {
  try {
    const stat = readFileSync(`/proc/${pid}/stat`, 'latin1');
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return { state: fields[0], group: Number(fields[2]) };
  } catch {
    return null;  // gone
  }
}

function browserGroups(scratch, groups) {
  const own = processStat(process.pid)?.group;
  for (const pid of processIds()) {
    let commandLine;
    try {
      commandLine = readFileSync(`/proc/${pid}/cmdline`, 'latin1');
    } catch {
      continue;
    }
    if (!commandLine.includes(`${scratch}/`)) continue;
    const group = processStat(pid)?.group;
    if (group > 1 && group !== own) groups.add(group);
  }
  return groups;
}

// Processes of GROUPS still running (a zombie writes nothing, and one whose parent is gone may
// never be reaped in a container whose init does not reap).
function runningIn(groups) {
  return processIds().filter((pid) => {
    const stat = processStat(pid);
    return stat && groups.has(stat.group) && stat.state !== 'Z' && stat.state !== 'X';
  }).length;
}

// Ends whatever of the browser still runs and waits until none of it does (at most 10 s), so that
// nothing writes into SCRATCH once it is removed: a helper still ending after the browser's
// close(), or a browser whose close timed out, would otherwise recreate its profile there.
async function endBrowser(scratch, groups) {
  const deadline = Date.now() + 10000;
  for (;;) {
    browserGroups(scratch, groups);
    if (runningIn(groups) === 0 || Date.now() > deadline) return;
    for (const group of groups) {
      try {
        process.kill(-group, 'SIGKILL');
      } catch {
        // already gone
      }
    }
    await new Promise((done) => setTimeout(done, 20));
  }
}

async function render(args, partial, held) {
  if (!existsSync(args.chromium)) {
    throw new Failure(`Chromium not found at ${args.chromium}: install it (Debian: apt-get ` +
      'install chromium, or scripts/setup.sh) or set TUMBLE_CHROMIUM');
  }
  if (!existsSync(args.page)) throw new Failure(`no page at ${args.page}`);
  if (existsSync(args.output) && statSync(args.output).isDirectory()) {
    throw new Failure(`${args.output} is a directory`);
  }
  const encoder = held.encoder = await startEncoder(args, partial);

  // The flags of the browser test (tests/browser/animation.test.mjs): software WebGL, and no
  // traffic of Chromium's own.
  // Held while it starts too: a signal then must wait for the launch to close the browser.
  held.launching = chromium.launch({
    executablePath: args.chromium,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-frame-rate-limit', '--disable-gpu-vsync'],
  });
  const browser = held.browser = await held.launching;
  browserGroups(held.scratch, held.groups);  // known while it runs: its helpers may outlive it
  const context = await browser.newContext({
    viewport: { width: args.width, height: args.height }, deviceScaleFactor: 1,
  });
  // The page is self-contained: anything it would fetch is refused and reported.
  const refused = [];
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:') || url.startsWith('data:')) return route.continue();
    refused.push(url);
    return route.abort();
  });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e.message ?? e).split('\n')[0]));
  const check = () => {
    if (errors.length) throw new Failure(`the page failed: ${errors[0]}`);
    if (refused.length) throw new Failure(`the page tried to fetch ${refused[0]} (refused)`);
  };

  await page.goto(pathToFileURL(args.page).href);
  try {
    await page.waitForFunction(() => window.tumble?.videoMode !== undefined, null,
      { timeout: 10000 });
  } catch {
    check();
    throw new Failure(`${args.page} did not start as a tumble animation page within 10 s`);
  }
  const { start, end } = await page.evaluate(() => {
    window.tumble.videoMode();
    return { start: window.tumble.start, end: window.tumble.end };
  });
  check();
  const step = args.speed / args.fps;
  // The last frame's time may not pass the last row (a rounding's worth of slack).
  if ((args.frames - 1) * step > (end - start) * (1 + 1e-9) + 1e-12) {
    throw new Failure(`${args.frames} frames at ${args.fps} fps and speed ${args.speed} run ` +
      `past the page's last row (t = ${start} to ${end} s)`);
  }

  // tumble killed on its own (not with its process group) must not have its video appear later.
  const parent = process.ppid;
  const parentGone = () => {
    try {
      process.kill(parent, 0);
      return false;
    } catch (e) {
      return e.code === 'ESRCH';
    }
  };
  for (let k = 0; k < args.frames; ++k) {
    if (parentGone()) throw new Failure(`the process that asked for the video (${parent}) is gone`);
    await page.evaluate((t) => window.tumble.seek(t), Math.min(start + k * step, end));
    const png = await page.screenshot({ type: 'png' });
    if (k === 0) {
      const w = png.readUInt32BE(16), h = png.readUInt32BE(20);  // the PNG's IHDR
      if (w !== args.width || h !== args.height) {
        throw new Failure(`the browser drew ${w}x${h} pixels, not ${args.width}x${args.height}`);
      }
    }
    check();
    await encoder.write(png);
  }
  await encoder.finish();
  if (!existsSync(partial) || statSync(partial).size === 0) {
    throw new Failure('ffmpeg wrote nothing');
  }
  renameSync(partial, args.output);
}

async function main() {
  let args;
  try {
    args = parseArguments(process.argv.slice(2));
  } catch (e) {
    console.error(`render_video: ${e.message}`);
    return 2;
  }
  // Beside OUTPUT, so that the rename stays on one file system and is atomic.
  const partial = `${args.output}.partial-${process.pid}`;
  // Playwright's and Chromium's temporary files (the profile, artifacts, Chromium's own scoped
  // directories) all go in one directory of ours, removed however the render ends: a browser
  // stopped while it starts may not remove its own.
  const scratch = mkdtempSync(join(tmpdir(), 'tumble-video-'));
  process.env.TMPDIR = scratch;
  const held = { scratch, groups: new Set() };
  // The browser is closed (at most 5 s), then whatever of it still runs is killed and waited for;
  // only then do the scratch directory and the partial video go. A removal may still meet a file
  // being written by a process just ending (ENOTEMPTY at its rmdir): it tries again for a while,
  // and a failure is reported, not thrown (from a signal's handler, before the exit). Once only:
  // a signal during the clean-up of a render that ended waits for the same one.
  let cleaning = null;
  const cleanUp = () => (cleaning ??= (async () => {
    held.encoder?.child.kill('SIGKILL');
    // A browser still starting (a signal soon after the launch began) is closed once it runs.
    const closing = (async () => {
      const browser = held.browser ?? await held.launching?.catch(() => undefined);
      await browser?.close().catch(() => {});
    })();
    let timer;
    await Promise.race([closing, new Promise((done) => { timer = setTimeout(done, 5000); })]);
    clearTimeout(timer);
    await endBrowser(scratch, held.groups);
    await held.encoder?.exited;  // killed above: gone at once, and then writes nothing more
    rmSync(partial, { force: true });
    try {
      rmSync(scratch, { recursive: true, force: true, maxRetries: 20, retryDelay: 50 });
    } catch (e) {
      console.error(`render_video: could not remove ${scratch}: ${e.message}`);
    }
  })());
  // Stopped: the clean-up, then the exit status of the signal. `on`, not `once`: Ctrl-C reaches
  // this process twice, from the terminal and from tumble.
  const abandon = async (status) => {
    await cleanUp();
    process.exit(status);
  };
  process.on('SIGINT', () => abandon(130));
  process.on('SIGTERM', () => abandon(143));
  process.on('SIGHUP', () => abandon(129));
  try {
    await render(args, partial, held);
    return 0;
  } catch (e) {
    const message = e instanceof Failure ? e.message : String(e?.message ?? e).split('\n')[0];
    console.error(`render_video: ${message}`);
    return 1;
  } finally {
    await cleanUp();
  }
}

process.exitCode = await main();
