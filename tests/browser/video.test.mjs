// `tumble run --video`: the built tumble renders the animation page into an .mp4 and a .gif
// (headless Chromium and ffmpeg, web/render_video.mjs), and ffprobe checks what came out: the
// frame count the trajectory's time span calls for (docs/video.md), the size, the frame rate and
// the duration; the picture moves; bad requests fail cleanly and leave nothing behind.
//   TUMBLE_EXE=build/release/tumble node --test tests/browser/
// Environment: TUMBLE_EXE (default build/release/tumble); tumble itself reads TUMBLE_CHROMIUM,
// TUMBLE_NODE and TUMBLE_FFMPEG.
import { describe, test, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFile, execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const tumble = resolve(root, process.env.TUMBLE_EXE ?? 'build/release/tumble');
const scenario = join(root, 'examples', 'spinning_projectile.yaml');
const work = mkdtempSync(join(tmpdir(), 'tumble-video-test-'));
after(() => rmSync(work, { recursive: true, force: true }));

const width = 320, height = 240, fps = 12, speed = 2;

// tumble with TMPDIR of its own, so that a temporary page left behind would show. Asynchronous,
// so that the tests below run side by side: each waits mostly for Chromium to start.
function run(out, args, env = {}) {
  const scratch = join(out, 'tmp');
  mkdirSync(scratch, { recursive: true });
  return new Promise((done) => {
    const child = execFile(tumble, ['run', scenario, '--out', out, ...args],
      { encoding: 'utf8', env: { ...process.env, TMPDIR: scratch, ...env } },
      (_error, stdout, stderr) => done({ status: child.exitCode, stdout, stderr, scratch }));
  });
}

// The expected frame count from the CSV's first and last t (docs/video.md): frame k shows
// t0 + k * speed / fps, for every k up to the last row.
function expectedFrames(csv) {
  const lines = readFileSync(csv, 'utf8').trim().split('\n');
  const t = (line) => Number(line.split(',')[0]);
  const span = t(lines.at(-1)) - t(lines[1]);
  return Math.floor(span * fps / speed + 1e-9) + 1;
}

function probe(video) {
  return JSON.parse(execFileSync('ffprobe', ['-v', 'error', '-count_frames',
    '-select_streams', 'v:0', '-show_entries', 'stream=width,height,nb_read_frames,r_frame_rate',
    '-show_entries', 'format=duration', '-of', 'json', video], { encoding: 'utf8' }));
}

// Frame n as raw RGB bytes.
function frame(video, n) {
  return execFileSync('ffmpeg', ['-v', 'error', '-i', video, '-vf', `select=eq(n\\,${n})`,
    '-frames:v', '1', '-f', 'rawvideo', '-pix_fmt', 'rgb24', '-'], { maxBuffer: 1 << 26 });
}

// The share of pixels below the overlay (the top quarter: name and time) that changed clearly,
// more than compression noise, between two frames.
function movedShare(a, b) {
  let moved = 0, total = 0;
  for (let y = Math.floor(height / 4); y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      const i = 3 * (y * width + x);
      ++total;
      if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]),
        Math.abs(a[i + 2] - b[i + 2])) > 48) ++moved;
    }
  }
  return moved / total;
}

function checkVideo(out, name, { durationTolerance }) {
  const video = join(out, name);
  const frames = expectedFrames(join(out, 'spinning_projectile.csv'));
  assert.equal(frames, 11, '1.8 s at 2x and 12 fps: t = 0, 1/6, ..., 10/6 s');
  const info = probe(video);
  const stream = info.streams[0];
  console.log(`${name}: ${JSON.stringify({ ...stream, duration: info.format.duration })}`);
  assert.equal(Number(stream.nb_read_frames), frames);
  assert.equal(stream.width, width);
  assert.equal(stream.height, height);
  assert.equal(stream.r_frame_rate, `${fps}/1`);
  const duration = Number(info.format.duration);
  assert.ok(Math.abs(duration - frames / fps) <= durationTolerance,
    `duration ${duration} s, expected ${frames / fps} s`);
  const share = movedShare(frame(video, 0), frame(video, frames - 1));
  assert.ok(share > 0.002, `only ${share} of the picture changed from the first frame to the last`);
  return frames;
}

describe('tumble run --video', { concurrency: true }, () => {
test('an .mp4 has the frames, size, rate and duration asked for, and moves', async () => {
  const out = join(work, 'mp4 dir');
  const r = await run(out, ['--video', join(out, 'clip.mp4'), '--video-size', `${width}x${height}`,
    '--video-fps', String(fps), '--video-speed', String(speed)]);
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stdout, /video +.*clip\.mp4 \(11 frames, 320x240, 12 fps\)/);
  // The mp4 muxer stores times in its own units (the movie header counts milliseconds): half a
  // frame (42 ms here) tells a right duration from one a frame too long or short, and is far
  // above that rounding.
  checkVideo(out, 'clip.mp4', { durationTolerance: 0.5 / fps });
  // The page made for the video alone went with its temporary directory; no partial file stays.
  assert.deepEqual(readdirSync(r.scratch), []);
  assert.deepEqual(readdirSync(out).sort(), ['clip.mp4', 'spinning_projectile.csv', 'tmp']);
});

test('a .gif beside the kept page has the frames, size and duration asked for', async () => {
  const out = join(work, 'gif');
  const r = await run(out, ['--animate', '--video', join(out, 'clip.gif'), '--video-size',
    `${width}x${height}`, '--video-fps', String(fps), '--video-speed', String(speed)]);
  assert.equal(r.status, 0, r.stderr);
  // GIF delays are whole centiseconds (1/12 s is 8.33): ffmpeg rounds each frame's start time to
  // a centisecond, so the total is off by less than two, far under a frame.
  checkVideo(out, 'clip.gif', { durationTolerance: 0.02 });
  assert.deepEqual(readdirSync(out).sort(),
    ['clip.gif', 'spinning_projectile.csv', 'spinning_projectile.html', 'tmp']);
});

test('bad requests exit 2 before running; a failed render exits 5; nothing is left behind',
  async () => {
  const out = join(work, 'bad');
  for (const [args, message] of [
    [['--video', join(out, 'x.avi')], /must end in \.mp4 or \.gif/],
    [['--video', join(out, 'x.mp4'), '--video-size', '321x240'], /even width and height/],
    [['--video', join(out, 'x.gif'), '--video-size', '320'], /WIDTHxHEIGHT/],
    [['--video', join(out, 'x.gif'), '--video-fps', '0'], /--video-fps/],
    [['--video', join(out, 'x.gif'), '--video-speed', '0'], /--video-speed/],
    [['--video-fps', '10'], /requires --video/],
  ]) {
    const r = await run(out, args);
    assert.equal(r.status, 2, `${args.join(' ')}: ${r.stderr}`);
    assert.match(r.stderr, message);
    assert.deepEqual(readdirSync(out), ['tmp'], `${args.join(' ')} ran anyway`);
  }

  // A renderer that cannot run: the CSV stays, the video and the temporary page do not.
  const r = await run(out, ['--video', join(out, 'x.mp4'), '--video-size', '320x240'],
    { TUMBLE_FFMPEG: join(out, 'no-ffmpeg-here') });
  assert.equal(r.status, 5, r.stderr);
  assert.match(r.stderr, /no video written to .*x\.mp4: ffmpeg not found/);
  assert.equal(r.stderr.trim().split('\n').length, 1, r.stderr);
  assert.deepEqual(readdirSync(out).sort(), ['spinning_projectile.csv', 'tmp']);
  assert.deepEqual(readdirSync(r.scratch), []);
});
});

test('SIGTERM while the video renders ends tumble by the signal and leaves nothing behind',
  async () => {
  const out = join(work, 'stopped');
  const scratch = join(out, 'tmp');
  mkdirSync(scratch, { recursive: true });
  const child = execFile(tumble, ['run', scenario, '--out', out, '--video', join(out, 'x.mp4'),
    '--video-size', '320x240'], { env: { ...process.env, TMPDIR: scratch } });
  const ended = new Promise((done) => child.on('exit', (code, signal) => done({ code, signal })));
  // Stopped once Chromium starts: its profile directory is in the renderer's own directory in
  // TMPDIR (tumble-video-*).
  const starting = () => readdirSync(scratch).some((d) => d.startsWith('tumble-video-') &&
    readdirSync(join(scratch, d)).some((n) => n.startsWith('playwright')));
  for (let k = 0; k < 600 && !starting(); ++k) {
    await new Promise((done) => setTimeout(done, 50));
  }
  assert.ok(starting(), 'Chromium never started');
  child.kill('SIGTERM');
  const { code, signal } = await ended;
  assert.equal(signal, 'SIGTERM', `exit status ${code} instead of the signal`);
  assert.deepEqual(readdirSync(scratch, { recursive: true }), [],
    'Chromium\'s or tumble\'s temporary files were left');
  assert.deepEqual(readdirSync(out).sort(), ['spinning_projectile.csv', 'tmp']);
});
