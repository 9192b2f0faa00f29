// Make a MediaRecorder WebM seekable. The browser writes it as a live stream: the Segment and each
// Cluster have an unknown size, the Segment Info has no Duration (players show Infinity) and there
// are no Cues (players cannot seek). fixWebm() rewrites the EBML: known sizes everywhere, a
// Duration in the Info, a SeekHead and Cues (one cue per cluster that starts with a key frame of
// the video track). The frames themselves are copied byte for byte. Pure: bytes in, bytes out, so
// Node tests use it directly.

/** @type {Readonly<Record<string, number>>} */
const ID = Object.freeze({
  EBML: 0x1a45dfa3, Segment: 0x18538067, SeekHead: 0x114d9b74, Seek: 0x4dbb, SeekID: 0x53ab,
  SeekPosition: 0x53ac, Info: 0x1549a966, TimecodeScale: 0x2ad7b1, Duration: 0x4489,
  Tracks: 0x1654ae6b, TrackEntry: 0xae, TrackNumber: 0xd7, TrackType: 0x83, Video: 0xe0,
  PixelWidth: 0xb0, PixelHeight: 0xba, Cluster: 0x1f43b675, Timecode: 0xe7, SimpleBlock: 0xa3,
  BlockGroup: 0xa0, Block: 0xa1, Cues: 0x1c53bb6b, CuePoint: 0xbb, CueTime: 0xb3,
  CueTrackPositions: 0xb7, CueTrack: 0xf7, CueClusterPosition: 0xf1, Void: 0xec,
});
export const WEBM_IDS = ID;

// What may be inside a Cluster: an unknown-size cluster ends at the first element that is not one.
const CLUSTER_CHILDREN = new Set([ID.Timecode, ID.SimpleBlock, ID.BlockGroup, 0xa7, 0xab, 0x5854, ID.Void, 0xbf]);

/** The element id at `pos` (with its marker bits, as the spec writes ids) and its length. */
function readId(b, pos) {
  const first = b[pos];
  if (first === undefined) throw new Error(`WebM: no element id at byte ${pos}`);
  const len = first >= 0x80 ? 1 : first >= 0x40 ? 2 : first >= 0x20 ? 3 : first >= 0x10 ? 4 : 0;
  if (!len || pos + len > b.length) throw new Error(`WebM: bad element id at byte ${pos}`);
  let id = 0;
  for (let i = 0; i < len; i++) id = id * 256 + b[pos + i];
  return { id, len };
}

/** The variable-length size at `pos`: {size (null when unknown), len}. */
function readSize(b, pos) {
  const first = b[pos];
  if (first === undefined || first === 0) throw new Error(`WebM: bad element size at byte ${pos}`);
  let len = 1;
  while (!(first & (0x80 >> (len - 1)))) len++;
  if (pos + len > b.length) throw new Error(`WebM: element size cut off at byte ${pos}`);
  let value = first & (0xff >> len);
  let allOnes = value === 0xff >> len;
  for (let i = 1; i < len; i++) {
    value = value * 256 + b[pos + i];
    if (b[pos + i] !== 0xff) allOnes = false;
  }
  return { size: allOnes ? null : value, len };
}

/**
 * The elements of `b` in [start, end), one level: [{id, start, dataStart, end, unknown}]. An
 * unknown-size Segment runs to `end`; an unknown-size Cluster to its last cluster child.
 */
export function readElements(b, start = 0, end = b.length) {
  const out = [];
  let pos = start;
  while (pos < end) {
    const { id, len } = readId(b, pos);
    const s = readSize(b, pos + len);
    const dataStart = pos + len + s.len;
    let stop;
    if (s.size !== null) stop = dataStart + s.size;
    else if (id === ID.Cluster) {
      stop = dataStart;
      while (stop < end) {
        const child = readId(b, stop);
        if (!CLUSTER_CHILDREN.has(child.id)) break;
        const cs = readSize(b, stop + child.len);
        if (cs.size === null) throw new Error('WebM: an unknown-size element inside a cluster');
        stop += child.len + cs.len + cs.size;
      }
    } else stop = end;
    if (stop > end) stop = end; // a cut-off last element: keep what there is
    out.push({ id, start: pos, dataStart, end: stop, unknown: s.size === null });
    pos = stop;
  }
  return out;
}

function readUint(b, e) {
  let v = 0;
  for (let i = e.dataStart; i < e.end; i++) v = v * 256 + b[i];
  return v;
}

function readFloat(b, e) {
  const view = new DataView(b.buffer, b.byteOffset + e.dataStart, e.end - e.dataStart);
  return e.end - e.dataStart === 4 ? view.getFloat32(0) : view.getFloat64(0);
}

const child = (b, e, id) => readElements(b, e.dataStart, e.end).find((c) => c.id === id);

function idBytes(id) {
  const out = [];
  for (let v = id; v > 0; v = Math.floor(v / 256)) out.unshift(v % 256);
  return out;
}

/** `n` as an EBML size of `len` bytes (the smallest that holds it when `len` is not given). */
function sizeBytes(n, len = 0) {
  if (!len) { len = 1; while (n >= 2 ** (7 * len) - 1) len++; }
  const out = new Array(len);
  let v = n;
  for (let i = len - 1; i >= 0; i--) { out[i] = v % 256; v = Math.floor(v / 256); }
  out[0] |= 0x80 >> (len - 1);
  return out;
}

function uintBytes(n, len = 0) {
  const out = [];
  for (let v = n; v > 0 || out.length === 0; v = Math.floor(v / 256)) out.unshift(v % 256);
  while (out.length < len) out.unshift(0);
  return out;
}

/** Concatenate byte arrays / Uint8Arrays. */
function concat(parts) {
  const out = new Uint8Array(parts.reduce((s, p) => s + p.length, 0));
  let at = 0;
  for (const p of parts) { out.set(p, at); at += p.length; }
  return out;
}

/** An element: id, size, payload (parts). */
function element(id, payload, sizeLen = 0) {
  const body = concat(payload);
  return concat([idBytes(id), sizeBytes(body.length, sizeLen), body]);
}

/** The blocks of a cluster: [{track, time (cluster-relative), key}]. */
function blocksOf(b, cluster) {
  const out = [];
  for (const e of readElements(b, cluster.dataStart, cluster.end)) {
    let blk = null, key = false;
    if (e.id === ID.SimpleBlock) { blk = e; }
    else if (e.id === ID.BlockGroup) { blk = child(b, e, ID.Block); key = true; } // a Block has no key flag: take it as one
    if (!blk) continue;
    const tn = readSize(b, blk.dataStart);
    const at = blk.dataStart + tn.len;
    const rel = (b[at] << 24 >> 16) | b[at + 1]; // int16, big-endian
    if (blk.id === ID.SimpleBlock) key = (b[at + 2] & 0x80) !== 0;
    out.push({ track: tn.size, time: rel, key });
  }
  return out;
}

/**
 * What a WebM says about itself: {timecodeScale (ns), duration (ms, or null), width, height,
 * segmentKnown, clusters: [{time (ms), position, known, blocks}], cues: [{time (ms), position}],
 * lastBlock (ms)}. Positions are relative to the Segment's data, as Cues and SeekHead write them.
 */
export function webmInfo(bytes) {
  const b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const top = readElements(b);
  const seg = top.find((e) => e.id === ID.Segment);
  if (!seg) throw new Error('WebM: no Segment');
  const kids = readElements(b, seg.dataStart, seg.end);
  const info = kids.find((e) => e.id === ID.Info);
  const ts = info && child(b, info, ID.TimecodeScale);
  const scale = ts ? readUint(b, ts) : 1e6;
  const dur = info && child(b, info, ID.Duration);
  const ms = (v) => (v * scale) / 1e6;
  let width = null, height = null;
  const tracks = kids.find((e) => e.id === ID.Tracks);
  for (const t of tracks ? readElements(b, tracks.dataStart, tracks.end) : []) {
    const v = t.id === ID.TrackEntry && child(b, t, ID.Video);
    if (!v) continue;
    const w = child(b, v, ID.PixelWidth), h = child(b, v, ID.PixelHeight);
    if (w && width === null) { width = readUint(b, w); height = h ? readUint(b, h) : null; }
  }
  let lastBlock = 0;
  const clusters = kids.filter((e) => e.id === ID.Cluster).map((c) => {
    const tc = child(b, c, ID.Timecode);
    const time = tc ? readUint(b, tc) : 0;
    const blocks = blocksOf(b, c);
    for (const k of blocks) lastBlock = Math.max(lastBlock, ms(time + k.time));
    return { time: ms(time), position: c.start - seg.dataStart, known: !c.unknown, blocks: blocks.length };
  });
  const cuesEl = kids.find((e) => e.id === ID.Cues);
  const cues = [];
  for (const p of cuesEl ? readElements(b, cuesEl.dataStart, cuesEl.end) : []) {
    if (p.id !== ID.CuePoint) continue;
    const t = child(b, p, ID.CueTime), tp = child(b, p, ID.CueTrackPositions);
    const pos = tp && child(b, tp, ID.CueClusterPosition);
    cues.push({ time: t ? ms(readUint(b, t)) : 0, position: pos ? readUint(b, pos) : -1 });
  }
  return { timecodeScale: scale, duration: dur ? ms(readFloat(b, dur)) : null, width, height,
    segmentKnown: !seg.unknown && seg.end === b.length, clusters, cues, lastBlock };
}

/**
 * A seekable copy of MediaRecorder WebM `bytes` (Uint8Array or ArrayBuffer): the Segment and
 * Clusters with known sizes, the Info with a Duration, a SeekHead and Cues. The duration is
 * `durationMs` when given, else the last frame's time plus the mean frame interval of the video
 * track (what a player shows). Throws (naming what) when the bytes are not WebM.
 */
export function fixWebm(bytes, durationMs = null) {
  const b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const top = readElements(b);
  if (!top.length || top[0].id !== ID.EBML) throw new Error('WebM: no EBML header');
  const seg = top.find((e) => e.id === ID.Segment);
  if (!seg) throw new Error('WebM: no Segment');
  const kids = readElements(b, seg.dataStart, seg.end);
  const info = kids.find((e) => e.id === ID.Info);
  if (!info) throw new Error('WebM: no Segment Info');
  const ts = child(b, info, ID.TimecodeScale);
  const scale = ts ? readUint(b, ts) : 1e6; // ns per tick

  // the video track (else the first), for the cues and the frame interval
  let track = null;
  const tracks = kids.find((e) => e.id === ID.Tracks);
  for (const t of tracks ? readElements(b, tracks.dataStart, tracks.end) : []) {
    if (t.id !== ID.TrackEntry) continue;
    const num = child(b, t, ID.TrackNumber), type = child(b, t, ID.TrackType);
    const n = num ? readUint(b, num) : null;
    if (track === null || (type && readUint(b, type) === 1)) track = n;
    if (type && readUint(b, type) === 1) break;
  }

  const clusters = kids.filter((e) => e.id === ID.Cluster).map((c) => {
    const tc = child(b, c, ID.Timecode);
    const time = tc ? readUint(b, tc) : 0;
    const blocks = blocksOf(b, c).filter((k) => track === null || k.track === track);
    return { el: c, time, blocks };
  });
  const times = clusters.flatMap((c) => c.blocks.map((k) => c.time + k.time)).sort((x, y) => x - y);
  let ticks;
  if (Number.isFinite(durationMs) && durationMs > 0) ticks = (durationMs * 1e6) / scale;
  else if (times.length > 1) ticks = times[times.length - 1] + (times[times.length - 1] - times[0]) / (times.length - 1);
  else ticks = times.length ? times[0] + 1 : 0;

  // the Info again, its Duration set
  const infoKids = readElements(b, info.dataStart, info.end).filter((e) => e.id !== ID.Duration && e.id !== ID.Void);
  const dur = new Uint8Array(8);
  new DataView(dur.buffer).setFloat64(0, ticks);
  const newInfo = element(ID.Info, [...infoKids.map((e) => b.subarray(e.start, e.end)), element(ID.Duration, [dur])]);
  // Clusters with known sizes (8-byte sizes, as libwebm writes them once it knows)
  const newClusters = clusters.map((c) => element(ID.Cluster, [b.subarray(c.el.dataStart, c.el.end)], 8));
  const keep = kids.filter((e) => ![ID.SeekHead, ID.Info, ID.Cluster, ID.Cues, ID.Void].includes(e.id))
    .map((e) => b.subarray(e.start, e.end)); // Tracks, Tags, …

  // layout: SeekHead (fixed size: 8-byte positions), Info, the rest, Clusters, Cues
  const seekHead = (pos) => element(ID.SeekHead, [
    [ID.Info, pos.info], [ID.Tracks, pos.tracks], [ID.Cues, pos.cues],
  ].filter(([, p]) => p !== null).map(([id, p]) => element(ID.Seek, [
    element(ID.SeekID, [idBytes(id)]), element(ID.SeekPosition, [uintBytes(p, 8)]),
  ])));
  const anyKey = clusters.some((c) => c.blocks.some((k) => k.key));
  const headLen = seekHead({ info: 0, tracks: tracks ? 0 : null, cues: anyKey ? 0 : null }).length;
  let at = headLen;
  const infoPos = at;
  at += newInfo.length;
  let tracksPos = null;
  for (const part of keep) {
    if (tracksPos === null && readId(part, 0).id === ID.Tracks) tracksPos = at;
    at += part.length;
  }
  const cuePoints = [];
  for (const [i, c] of clusters.entries()) {
    const key = c.blocks.find((k) => k.key);
    if (key) {
      cuePoints.push(element(ID.CuePoint, [
        element(ID.CueTime, [uintBytes(Math.max(0, c.time + key.time))]),
        element(ID.CueTrackPositions, [element(ID.CueTrack, [uintBytes(track ?? 1)]), element(ID.CueClusterPosition, [uintBytes(at)])]),
      ]));
    }
    at += newClusters[i].length;
  }
  const cues = cuePoints.length ? element(ID.Cues, cuePoints) : null;
  const head = seekHead({ info: infoPos, tracks: tracksPos, cues: cues ? at : null });
  const body = [head, newInfo, ...keep, ...newClusters];
  if (cues) body.push(cues);
  const segment = element(ID.Segment, body, 8);
  const before = top.filter((e) => e.start < seg.start).map((e) => b.subarray(e.start, e.end));
  return concat([...before, segment]);
}
