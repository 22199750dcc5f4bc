// The balls' colours and names: pool's numbered balls, snooker's reds
// and colours, three-cushion's white, yellow and red. No drawing, no DOM
// (node imports it for the page's unit tests).

export const BALL_COLOURS = [
  '#f6f3ea',  // 0 cue ball
  '#f2bd14',  // 1 yellow
  '#1d49b0',  // 2 blue
  '#d2242b',  // 3 red
  '#54318f',  // 4 purple
  '#f06a1c',  // 5 orange
  '#12804a',  // 6 green
  '#7d1d24',  // 7 maroon
  '#151515',  // 8 black
];

export function ballColour(n) {
  if (n <= 8) return BALL_COLOURS[n];
  return BALL_COLOURS[n - 8];
}

// Snooker's balls by number (game.hpp): 0 the white cue ball, 1-15 the
// reds, 16-21 yellow, green, brown, blue, pink, black.
export const SNOOKER_COLOURS = {
  0: '#f6f3ea',
  red: '#c8141e',
  16: '#f2c81a',
  17: '#0e7a3a',
  18: '#7a4a1c',
  19: '#1c4fc4',
  20: '#f08cb0',
  21: '#141414',
};
export const SNOOKER_NAMES = {
  16: 'yellow', 17: 'green', 18: 'brown', 19: 'blue', 20: 'pink', 21: 'black',
};

export function snookerColour(n) {
  if (n >= 1 && n <= 15) return SNOOKER_COLOURS.red;
  return SNOOKER_COLOURS[n] || '#888';
}

/** A snooker ball's name: "cue ball", "red", "yellow", ... */
export function snookerName(n) {
  if (n === 0) return 'cue ball';
  if (n >= 1 && n <= 15) return 'red';
  return SNOOKER_NAMES[n] || `ball ${n}`;
}

// Three-cushion's balls by number (docs/rules.md): 0 the white (the
// breaker's cue ball), 1 the yellow (the other player's), 2 the red.
export const CAROM_COLOURS = ['#f6f3ea', '#f2c81a', '#c8141e'];
export const CAROM_NAMES = ['white', 'yellow', 'red'];

export function caromColour(n) { return CAROM_COLOURS[n] || '#888'; }

/** A carom ball's name: "white", "yellow", "red". */
export function caromName(n) { return CAROM_NAMES[n] || `ball ${n}`; }
