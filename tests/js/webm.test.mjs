// www/ui/webm.js in Node: a synthetic live-stream WebM (as MediaRecorder writes it: unknown-size
// Segment and Clusters, no Duration, no Cues) made seekable. The checks read the bytes directly
// where they can (the Duration float, the Segment size, the frames copied), not only through the
// module's own reader.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { fixWebm, webmInfo } from '../../www/ui/webm.js';

const UNKNOWN = [0x01, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff];
const id = (n) => { const o = []; for (let v = n; v > 0; v = Math.floor(v / 256)) o.unshift(v % 256); return o; };
const size = (n) => { if (n < 127) return [0x80 | n]; return [0x40 | (n >> 8), n & 0xff]; };
const el = (i, payload) => [...id(i), ...size(payload.length), ...payload];
const uint = (n, len = 1) => { const o = []; for (let k = 0; k < len; k++) o.unshift((n >> (8 * k)) & 0xff); return o; };
const str = (s) => [...Buffer.from(s)];

/** 2 clusters × 15 frames at 33 ms; frame k's payload is 20 bytes of value k. */
function liveWebm() {
  const frames = [];
  const cluster = (tc, first) => {
    const blocks = [];
    for (let k = 0; k < 15; k++) {
      const n = first + k;
      const payload = new Array(20).fill(n);
      frames.push(payload);
      blocks.push(...el(0xa3, [0x81, ...uint(k * 33, 2), k === 0 ? 0x80 : 0x00, ...payload]));
    }
    return [...id(0x1f43b675), ...UNKNOWN, ...el(0xe7, uint(tc, 2)), ...blocks];
  };
  const header = el(0x1a45dfa3, [...el(0x4282, str('webm')), ...el(0x4287, [4]), ...el(0x4285, [2])]);
  const info = el(0x1549a966, [...el(0x2ad7b1, uint(1e6, 3)), ...el(0x4d80, str('test')), ...el(0x5741, str('test'))]);
  const tracks = el(0x1654ae6b, el(0xae, [...el(0xd7, [1]), ...el(0x83, [1]), ...el(0x86, str('V_VP8')),
    ...el(0xe0, [...el(0xb0, uint(640, 2)), ...el(0xba, uint(360, 2))])]));
  const bytes = [...header, ...id(0x18538067), ...UNKNOWN, ...info, ...tracks, ...cluster(0, 0), ...cluster(495, 15)];
  return { bytes: Uint8Array.from(bytes), frames };
}

/** The Duration element's float64 (id 44 89, size 88), found in the raw bytes. */
function rawDuration(b) {
  for (let i = 0; i + 11 <= b.length; i++) {
    if (b[i] === 0x44 && b[i + 1] === 0x89 && b[i + 2] === 0x88) return Buffer.from(b).readDoubleBE(i + 3);
  }
  return null;
}

test('a live WebM gets a Duration, known sizes and cues; the frames are copied unchanged', () => {
  const { bytes, frames } = liveWebm();
  const before = webmInfo(bytes);
  assert.equal(before.duration, null, 'no Duration before');
  assert.equal(before.segmentKnown, false);
  assert.deepEqual(before.clusters.map((c) => c.known), [false, false]);
  assert.equal(before.cues.length, 0);

  const out = fixWebm(bytes);
  assert.equal(rawDuration(bytes), null);
  const d = rawDuration(out);
  assert.ok(d !== null, 'a Duration element in the output');
  assert.ok(Math.abs(d - (957 + 33)) < 1e-6, `duration ${d} ms: the last frame (957 ms) plus one interval`);
  // the Segment's size, read by hand: id 18 53 80 67, then an 8-byte size = the rest of the file
  const seg = Buffer.from(out).indexOf(Buffer.from([0x18, 0x53, 0x80, 0x67]));
  assert.equal(out[seg + 4], 0x01, '8-byte size');
  const segSize = Number(Buffer.from(out).readBigUInt64BE(seg + 4) & 0x00ffffffffffffffn);
  assert.equal(segSize, out.length - (seg + 12), 'the Segment size covers the rest of the file');
  // every frame's payload, in order, byte for byte
  const payloads = [];
  const buf = Buffer.from(out);
  for (let i = buf.indexOf(0xa3); i >= 0; i = buf.indexOf(0xa3, i + 1)) {
    if (buf[i + 1] === 0x80 + 24 && buf[i + 2] === 0x81) { payloads.push([...buf.subarray(i + 6, i + 26)]); i += 25; }
  }
  assert.deepEqual(payloads, frames);

  const after = webmInfo(out);
  assert.equal(after.segmentKnown, true);
  assert.deepEqual(after.clusters.map((c) => [c.time, c.known, c.blocks]), [[0, true, 15], [495, true, 15]]);
  assert.equal(after.width, 640);
  assert.equal(after.height, 360);
  assert.deepEqual(after.cues.map((c) => c.time), [0, 495]);
  const segData = seg + 12;
  for (const c of after.cues) {
    assert.deepEqual([...out.subarray(segData + c.position, segData + c.position + 4)], [0x1f, 0x43, 0xb6, 0x75], 'a cue points at a Cluster');
  }
  // a SeekHead naming the Cues' position
  const cuesAt = buf.lastIndexOf(Buffer.from([0x1c, 0x53, 0xbb, 0x6b])); // the Cues are last (the SeekHead names their id first)
  const seekCues = buf.indexOf(Buffer.from([0x53, 0xab, 0x84, 0x1c, 0x53, 0xbb, 0x6b]));
  assert.ok(seekCues > 0 && seekCues < cuesAt);
  assert.equal(Number(buf.readBigUInt64BE(seekCues + 7 + 3)), cuesAt - segData, 'SeekPosition of the Cues');

  // again: the same file
  assert.deepEqual([...fixWebm(out)], [...out], 'fixing a fixed file changes nothing');
  assert.equal(rawDuration(fixWebm(bytes, 2500)), 2500, 'an explicit duration in ms');
});

test('not a WebM: an error that says so', () => {
  assert.throws(() => fixWebm(Uint8Array.from([1, 2, 3, 4])), /WebM/);
  assert.throws(() => fixWebm(new Uint8Array(0)), /WebM/);
  assert.throws(() => fixWebm(Uint8Array.from(Buffer.from('<svg>not a video</svg>'))), /WebM/);
});
