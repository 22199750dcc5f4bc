// The engine's module factory as engine.js imports it ('./breakshot.js',
// default export createBreakshot): in the npm package the wasm is a file
// of its own (breakshot-wasm.wasm, next to emscripten's loader
// breakshot-wasm.js; web/CMakeLists.txt, target breakshot_wasm_npm),
// where the page's breakshot.js carries it inside. In a browser or a
// worker the loader fetches it (new URL('breakshot-wasm.wasm',
// import.meta.url), a pattern bundlers follow; served as application/wasm
// it compiles while it downloads). Node's fetch does not read file: URLs,
// so in node the bytes are read here, once per thread, and handed over.
import createCore from './breakshot-wasm.js';

const isNode = typeof process !== 'undefined' && process.versions != null &&
  typeof process.versions.node === 'string' && typeof window === 'undefined';

let bytes = null;

export default async function createBreakshot(options = {}) {
  if (isNode && !options.wasmBinary) {
    if (!bytes) {
      bytes = import('node:fs/promises').then(({ readFile }) => readFile(new URL('./breakshot-wasm.wasm', import.meta.url)));
    }
    return createCore({ ...options, wasmBinary: await bytes });
  }
  return createCore(options);
}
