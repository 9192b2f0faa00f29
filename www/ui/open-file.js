// Open file on the playground: a scenario JSON (or any file the core imports), or an occupancy map
// (issue 17): a map_server YAML with its image (chosen together), or an image alone (a plain image:
// dark is occupied); the core decodes them in the worker. The files are read here and handed to the
// page's `load`, which sends them to the worker (its `load` or `import` message).

import { MAX_FILE_BYTES } from '../run/limits.js';

const MAP_IMAGE = /\.(pgm|png)$/i;
const MAP_YAML = /\.ya?ml$/i;

/**
 * Wire the file input. `markCustom(label)`: the picker's entry for the opened file; `load(text,
 * defaults, options)`: pages/main.js `load`.
 * @param {{input: HTMLInputElement, clearError: () => void, showError: (text: string) => void,
 *   markCustom: (label: string) => void, load: (text: string, defaults: boolean, options: any) => void}} options
 */
export function wireOpenFile({ input, clearError, showError, markCustom, load }) {
  input.addEventListener('change', async () => {
    const files = [...input.files];
    input.value = ''; // the same file can be opened again
    if (!files.length) return;
    clearError();
    const big = files.find((f) => f.size > MAX_FILE_BYTES);
    if (big) {
      showError(`${big.name} is ${big.size.toLocaleString('en')} bytes; the limit is ${MAX_FILE_BYTES.toLocaleString('en')} bytes (16 MiB), so it was not read.`);
      return;
    }
    const yaml = files.find((f) => MAP_YAML.test(f.name));
    const images = files.filter((f) => MAP_IMAGE.test(f.name));
    if (yaml || images.length) {
      // The image the YAML names (by its base name) when several were chosen, else the only one.
      let yamlText = null;
      try { yamlText = yaml ? await yaml.text() : null; } catch (e) { showError(`Could not read ${yaml.name}: ${e.message}`); return; }
      const named = yamlText?.match(/^\s*image\s*:\s*["']?([^"'#\r\n]*?)["']?\s*(#.*)?$/m)?.[1].split(/[\\/]/).pop();
      const image = images.find((f) => f.name === named) ?? images[0] ?? null;
      let bytes = null;
      try { bytes = image ? await image.arrayBuffer() : null; } catch (e) { showError(`Could not read ${image.name}: ${e.message}`); return; }
      const name = yaml ? yaml.name : image.name;
      markCustom(`File: ${name}`);
      load('', true, { course: 'Opened file', file: image ? image.name : name, map: { bytes, yaml: yamlText, yamlName: yaml?.name ?? null }, source: { custom: true } });
      return;
    }
    const file = files[0];
    let text;
    try { text = await file.text(); } catch (e) { showError(`Could not read ${file.name}: ${e.message}`); return; }
    markCustom(`File: ${file.name}`);
    load(text, true, { course: 'Opened file', file: file.name, source: { custom: true } });
  });
}
