// One JS style, checked by `npm test` (scripts/test.mjs): ESLint's recommended rules over the page,
// the workers, the scripts and the JS tests. wasm-pack's generated glue (www/pkg) is not ours.
import js from '@eslint/js';
import globals from 'globals';

export default [
  { ignores: ['www/pkg/**', 'node_modules/**', 'dist/**', 'target/**', 'fuzz/**'] },
  js.configs.recommended,
  {
    files: ['www/**/*.js'],
    languageOptions: { ecmaVersion: 2024, sourceType: 'module', globals: { ...globals.browser, ...globals.worker } },
  },
  {
    files: ['scripts/**/*.mjs', 'eslint.config.mjs'],
    languageOptions: { ecmaVersion: 2024, sourceType: 'module', globals: { ...globals.node } },
  },
  {
    // It draws the documentation's figures in a page (page.evaluate).
    files: ['scripts/figures.mjs'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
  {
    // The browser tests pass functions to page.evaluate, which run in the page.
    files: ['tests/**/*.mjs'],
    languageOptions: { ecmaVersion: 2024, sourceType: 'module', globals: { ...globals.node, ...globals.browser } },
  },
];
