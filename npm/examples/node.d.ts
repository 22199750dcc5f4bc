// The few node APIs the examples use (console, process, node:fs), declared here: the tests install
// TypeScript and nothing else (no @types/node).
declare const console: { log(...values: unknown[]): void };
declare const process: {
  argv: string[];
  stdout: { write(text: string): boolean };
};
declare module 'node:fs' {
  export function readFileSync(path: string, encoding: 'utf8'): string;
}
