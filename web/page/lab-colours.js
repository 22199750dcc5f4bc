// The lab's colours: the table's, the system's gold, and one colour per ball.

const NAMED_COLOURS = {
  white: '#f4f4ef', cue: '#f4f4ef', black: '#1c1c1c', red: '#d7263d',
  blue: '#2a6fdb', green: '#1f9d55', yellow: '#f2c230', orange: '#f0872a',
  purple: '#7f3fc6', violet: '#7f3fc6', pink: '#f46fae', brown: '#8d5a2e',
  maroon: '#8a1c1c', cyan: '#1bb5c8', magenta: '#d035c0', grey: '#9aa0a6',
  gray: '#9aa0a6', gold: '#d4a11a', silver: '#c3c6c9', navy: '#26418f',
  teal: '#138a86', lime: '#7ccf3a',
};
export const FELT = '#4f6b7a';
export const RAIL = '#2b3036';
export const TOTAL_COLOUR = '#e0b24a';   // the system's things (total energy, momentum) are gold
export const GRAPH_BG = '#1b2026';

function hslHex(h, s, l) {
  s /= 100; l /= 100;
  const f = (n) => {
    const k = (n + h / 30) % 12;
    const c = l - s * Math.min(l, 1 - l) * Math.max(-1, Math.min(k - 3, 9 - k, 1));
    return Math.round(255 * c).toString(16).padStart(2, '0');
  };
  return `#${f(0)}${f(8)}${f(4)}`;
}

export function luminance(hex) {
  const n = parseInt(hex.slice(1), 16);
  const c = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((v) => {
    v /= 255;
    return v <= 0.03928 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
  });
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// Colours: an id that names a colour gets it; the others take hues a golden
// angle apart. Many balls share 8 colours so they can be drawn in batches.
export function ballColours(balls) {
  const n = balls.length;
  const out = new Array(n);
  let k = 0;
  for (let i = 0; i < n; i++) {
    const id = String(balls[i].id ?? '').toLowerCase();
    if (n <= 200 && NAMED_COLOURS[id]) { out[i] = NAMED_COLOURS[id]; continue; }
    const j = n > 200 ? i % 8 : k++;
    out[i] = hslHex((j * 137.508 + 15) % 360, 68, j % 2 ? 42 : 55);
  }
  return out;
}
