// A seeded generator for the Node tests that draw their own inputs, so a failure repeats.

/** A seeded generator (mulberry32): numbers in [0, 1), so a failure repeats. */
export function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * `n` small quadrilaterals whose corners have 12 digits, in rows across the unit square with its
 * top-right corner left free: a scenario of 70,000 is 8.3 MB as written, 21 MB pretty-printed.
 */
export function smallQuads(n) {
  const obstacles = [];
  const d = (v) => Number(v.toFixed(10));
  for (let k = 0; obstacles.length < n; k++) {
    const x = 0.05 + 0.0034 * (k % 265) + 1.23e-7, y = 0.05 + 0.0034 * Math.floor(k / 265) + 4.56e-7;
    if (x > 0.85 && y > 0.85) continue;
    obstacles.push({ polygon: [[d(x), d(y + 0.0011)], [d(x + 0.0011), d(y)], [d(x + 0.0022), d(y + 0.0011)], [d(x + 0.0011), d(y + 0.0022)]] });
  }
  return obstacles;
}
