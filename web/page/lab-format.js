// The lab's numbers as text and round numbers: axis ends and ticks, SI
// prefixes, and the rounding of dragged coordinates.

// 1, 2 or 5 times a power of ten, at least x.
export function niceCeil(x) {
  if (!(x > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * p >= x * (1 - 1e-12)) return m * p;
  return 10 * p;
}

// A round axis end at least x, with less headroom than niceCeil.
export function niceAxis(x) {
  if (!(x > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  for (const m of [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * p >= x * (1 - 1e-12)) return m * p;
  return 10 * p;
}

export function niceStep(range, maxTicks) {
  const raw = range / Math.max(1, maxTicks);
  const p = 10 ** Math.floor(Math.log10(raw));
  for (const m of [1, 2, 5, 10]) if (m * p >= raw) return m * p;
  return 10 * p;
}

const PREFIXES = [[1e3, 'k'], [1, ''], [1e-3, 'm'], [1e-6, 'µ'], [1e-9, 'n'], [1e-12, 'p']];
export function prefixFor(maxAbs) {
  for (const [f, p] of PREFIXES) if (maxAbs >= f * 0.9995) return [f, p];
  return PREFIXES[PREFIXES.length - 1];
}

export function tickLabel(v, step) {
  const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return v.toFixed(Math.min(digits, 6));
}

// A number with an SI prefix on its unit: 0.0009 J -> "0.900000 mJ".
export function fmtSI(v, unit, digits = 6) {
  if (!Number.isFinite(v)) return `${v} ${unit}`;
  if (v === 0) return `0 ${unit}`;
  const [f, p] = prefixFor(Math.abs(v));
  return `${(v / f).toPrecision(digits)} ${p}${unit}`;
}

export function fmtNum(v, digits = 5) {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(digits - 1);
  return v.toPrecision(digits);
}

// Rounds a dragged coordinate to a step that suits the table's size.
export function roundTo(v, step) {
  const r = Math.round(v / step) * step;
  const d = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return Number(r.toFixed(Math.min(d, 12)));
}

export function roundSig(v, sig) {
  if (v === 0 || !Number.isFinite(v)) return v;
  return Number(v.toPrecision(sig));
}
