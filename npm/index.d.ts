// Types of the npm package breakshot (docs/js.md). Checked with
// `tsc --strict --noEmit` against npm/examples/*.ts (npm/tests/run.mjs).

/** The engine's version, the package's ("0.1.0"). */
export const version: string;
/** The AI levels, weakest first: "beginner", "amateur", "club", "expert", "champion". */
export const levels: readonly string[];
/** The games a Game plays. */
export const games: readonly GameName[];
/** The computer players a seat of `game` may be (AI levels, and "baseline" where it plays). */
export function players(game: GameName): string[];

/** The motion states' names (the result file's "state"), by the codes of States.motion. */
export const motions: readonly MotionName[];
export type MotionName =
  | 'stationary' | 'moving' | 'sliding' | 'rolling' | 'spinning' | 'pocketed' | 'airborne' | 'off_table';
export type GameName = 'eight_ball' | 'nine_ball' | 'ten_ball' | 'snooker' | 'three_cushion';

/** Anything JSON: the engine reads objects as their JSON text. */
export type Json = null | boolean | number | string | Json[] | { [key: string]: Json | undefined };

/**
 * A scenario of the scenario format (docs/contract.md): physics, table,
 * balls or rack, cue, until, max_events. The engine checks every field and
 * names the one it refuses.
 */
export interface Scenario {
  physics?: { [key: string]: Json | undefined };
  table?: { [key: string]: Json | undefined };
  balls?: Array<{ [key: string]: Json | undefined }>;
  rack?: { game: string; seed?: number | string; [key: string]: Json | undefined };
  cue?: { ball: string; speed: number; phi: number; theta?: number; a?: number; b?: number; [key: string]: Json | undefined };
  [key: string]: Json | undefined;
}

/** An event of a result file: cue_strike, ball_ball, ball_cushion, ball_pocket, state_change, ball_slate, ball_off_table. */
export interface SimEvent {
  time: number;
  type: string;
  balls: string[];
  cushion?: string;
  pocket?: string;
  from?: string;
  to?: string;
  [key: string]: unknown;
}

export interface FinalBall {
  id: string;
  position: [number, number];
  velocity: [number, number];
  spin: [number, number, number];
  state: string;
  [key: string]: unknown;
}

/** The result file (docs/contract.md), as `breakshot simulate` writes it. */
export interface Result {
  complete: boolean;
  events: SimEvent[];
  final: { time: number; balls: FinalBall[] };
  samples?: Json[];
  [key: string]: unknown;
}

/** A frame for drawing (the page's): per ball [x, y, on_table, vx, vy, energy, px, py] and, when a ball is off the cloth, z and place. */
export interface Frame {
  t: number;
  balls: number[][];
  energy: number;
  momentum: [number, number];
  events: number;
  at_rest: boolean;
  complete: boolean;
}

/** The balls' states at a time as typed arrays, in the scenario's order. */
export interface States {
  t: number;
  /** Events so far. */
  events: number;
  atRest: boolean;
  complete: boolean;
  /** Total kinetic energy (J) and momentum (kg m/s). */
  energy: number;
  momentum: [number, number];
  /** The number of balls. */
  count: number;
  /** x0, y0, x1, y1, ... (m). */
  position: Float64Array;
  /** vx0, vy0, ... (m/s). */
  velocity: Float64Array;
  /** wx0, wy0, wz0, ... (rad/s). */
  spin: Float64Array;
  /** The centre's height above its resting height (m). */
  height: Float64Array;
  /** 1 on the table, 0 in a pocket or off the table. */
  onTable: Uint8Array;
  /** 0 on the cloth or in a pocket, 1 in flight, 2 off the table. */
  place: Uint8Array;
  /** Each ball's motion state, an index of `motions`: 0 stationary, 1 moving, 2 sliding,
   *  3 rolling, 4 spinning, 5 pocketed, 6 airborne, 7 off the table. */
  motion: Uint8Array;
  ballEnergy: Float64Array;
  ballMomentum: Float64Array;
}

/** A shot played back: the exact state of every ball at any time. Free it. */
export class Playback {
  protected constructor();
  /** The states at time t; fills `into` when it has the same number of balls. */
  states(t: number, into?: States): States;
  /** The frame at time t for drawing. */
  frame(t: number): Frame;
  /** The events played back so far (up to the last frame), from index `from`. */
  playedEvents(from?: number): SimEvent[];
  /** A three-cushion shot's count up to the last frame. */
  caromCount(): { cushions: number; hit: number[]; done: boolean; made: boolean };
  /** Releases the engine memory; later calls throw. */
  free(): void;
}

/** A simulated scenario: its result file and, as a Playback, its states at any time. */
export class Simulation extends Playback {
  /** The result file's text, byte for byte `breakshot simulate`'s. */
  readonly text: string;
  readonly result: Result;
  readonly events: SimEvent[];
  readonly complete: boolean;
  /** The time the run ended (s). */
  readonly duration: number;
  /** The balls' ids in the order of states() and frame(). */
  readonly ids: string[];
}

/** Simulates a scenario (an object or its JSON text). Throws Error naming the refused field. */
export function simulate(scenario: Scenario | string): Simulation;

export interface GameConfig {
  game: GameName;
  /** Each seat "human" or a computer player: "club", "champion@0.5x", "baseline" (snooker, three-cushion). */
  players: [string, string];
  /** The table's size: "7ft", "8ft", "9ft" (pool), "12ft" (snooker), ... */
  table?: string;
  seed?: number | string;
  breaker?: 0 | 1;
  physics?: { airborne?: boolean };
  /** three_cushion only. */
  carom?: { target?: number; innings_limit?: number; equalizing_inning?: boolean };
  /** Simulations per AI decision, overriding the levels' budgets. */
  ai_budget?: number;
}

export interface Strike {
  speed: number;
  phi: number;
  theta: number;
  a: number;
  b: number;
}

export interface PlaceCueBall {
  type: 'place_cue_ball';
  position: [number, number];
}

export interface Shoot {
  type: 'shoot';
  strike: Strike;
  call: { ball: number; pocket: string } | null;
  safety: boolean;
  push_out: boolean;
  /** snooker: the colour nominated. */
  nominate?: number;
  /** three_cushion: the cue ball (0 or 1). */
  cue_ball?: number;
}

export interface Decide {
  type: 'decide';
  choice: string;
}

/** An action in the records' form, every field given. */
export type Action = PlaceCueBall | Shoot | Decide;

export interface LegalActions {
  place: string;
  must_place: boolean;
  shoot: boolean;
  push_out: boolean;
  call: boolean;
  targets: number[];
  choices: string[];
  nominate?: number[];
  must_nominate?: boolean;
}

export interface GameState {
  game: GameName;
  phase: string;
  player: number;
  breaker: number;
  winner: number;
  shots: number;
  position: Array<[number, number]>;
  /** 1 on the table, 0 not. */
  on_table: number[];
  players: [string, string];
  actions: number;
  legal: LegalActions;
  [key: string]: unknown;
}

export interface Turn {
  /** The seat to act next, -1 once the game is over. */
  next: number;
  why: 'continues' | 'passes' | 'foul' | 'decides' | 'breaks' | 'game_over';
}

export interface ActReply {
  index: number;
  player: number;
  kind: 'place' | 'shoot' | 'decide';
  executed: Action;
  intended?: Strike;
  numbers?: number[];
  ruling: { fouls: string[]; turn_continues: boolean; text: string; [key: string]: unknown };
  turn: Turn;
  facts: { [key: string]: unknown };
  state: GameState;
}

/** A game between two seats. Free it. */
export class Game {
  constructor(config: GameConfig | string);
  /** The game of a link (game.link()'s text). */
  static fromLink(link: string): Game;
  state(): GameState;
  legalActions(): LegalActions;
  /** The number of actions played. */
  readonly actions: number;
  table(): { [key: string]: unknown };
  checkPlacement(x: number, y: number): { ok: boolean; reason?: string };
  /** Plays an action of the seat to act. Throws when the rules refuse it. */
  act(action: Action | string): ActReply;
  /** The AI's decision in this thread (blocking): the seat's own level, or `level`. */
  aiAction(level?: string): Action;
  /** Takes back the last n actions (default 1); returns the state. */
  undo(n?: number): GameState;
  /** Keeps the first n actions; returns the state. */
  undoTo(n: number): GameState;
  /** The playback of the shot of action `index`. */
  shot(index: number): Playback;
  link(): string;
  record(): { [key: string]: unknown };
  recordText(): string;
  turns(): Turn[];
  /** Releases the engine memory; later calls throw. */
  free(): void;
}

export interface PlayerOptions {
  /** Decide in the calling thread instead of a worker. */
  inline?: boolean;
}

/** An AI player: its decisions run in a worker (a Web Worker, or a node worker_thread). */
export class Player {
  constructor(level: string, options?: PlayerOptions);
  readonly level: string;
  readonly inline: boolean;
  /** The action for the seat to act in `game` (a Game or its link). */
  decide(game: Game | string): Promise<Action>;
  /** Stops the worker; pending decisions reject. */
  close(): void;
}

/** The engine.js API the classes are built on (docs/web.md, "The JS API"). */
export const engine: { [key: string]: unknown };
