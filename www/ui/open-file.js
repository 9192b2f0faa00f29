// Open file on the playground: a scenario JSON (or any file the core imports), or an occupancy map:
// a map_server YAML with its image (chosen together), or an image alone (a plain image: dark is
// occupied); the core decodes them in the worker. The files are read here and handed to the page's
// `load`, which sends them to the worker (its `load` or `import` message). What is chosen is opened
// as chosen or refused with a message: a YAML whose image is not among the files, several images
// without a YAML, or several scenarios never open another file in their place.

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
    const yamls = files.filter((f) => MAP_YAML.test(f.name));
    const images = files.filter((f) => MAP_IMAGE.test(f.name));
    const names = (list) => list.map((f) => `"${f.name}"`).join(', ');
    if (yamls.length || images.length) {
      // Never another file than the one meant: a YAML's image is the one it names (by base name),
      // a plain image is opened alone, and anything else chosen with them is named, not dropped.
      const others = files.filter((f) => !MAP_YAML.test(f.name) && !MAP_IMAGE.test(f.name));
      if (others.length || yamls.length > 1) {
        showError(`Open file… reads one scenario, one image, or one map_server YAML with its image; ${names(files)} were chosen together, so none was opened.`);
        return;
      }
      const yaml = yamls[0] ?? null;
      let yamlText = null;
      try { yamlText = yaml ? await yaml.text() : null; } catch (e) { showError(`Could not read ${yaml.name}: ${e.message}`); return; }
      const named = yamlText?.match(/^\s*image\s*:\s*["']?([^"'#\r\n]*?)["']?\s*(#.*)?$/m)?.[1].split(/[\\/]/).pop() || null;
      let image = null;
      if (!yaml && images.length > 1) {
        showError(`${names(images)} were chosen together: open one image at a time, or a map_server YAML with the image it names.`);
        return;
      } else if (yaml && named && images.length) {
        image = images.find((f) => f.name === named) ?? null;
        if (!image) {
          showError(`${yaml.name} names its image "${named}", which is not among the files chosen (${names(images)}): choose ${yaml.name} and ${named} together.`);
          return;
        }
      } else if (yaml && !named && images.length > 1) {
        showError(`${yaml.name} names no image (its image: line), and ${names(images)} were chosen: choose it with one image.`);
        return;
      } else image = images[0] ?? null; // a plain image; or the YAML alone (the core names the image it needs)
      let bytes = null;
      try { bytes = image ? await image.arrayBuffer() : null; } catch (e) { showError(`Could not read ${image.name}: ${e.message}`); return; }
      const name = yaml ? yaml.name : image.name;
      markCustom(`File: ${name}`);
      load('', true, { course: 'Opened file', file: image ? image.name : name, map: { bytes, yaml: yamlText, yamlName: yaml?.name ?? null }, source: { custom: true } });
      return;
    }
    if (files.length > 1) {
      showError(`Open file… reads one scenario at a time; ${names(files)} were chosen, so none was opened.`);
      return;
    }
    const file = files[0];
    let text;
    try { text = await file.text(); } catch (e) { showError(`Could not read ${file.name}: ${e.message}`); return; }
    markCustom(`File: ${file.name}`);
    load(text, true, { course: 'Opened file', file: file.name, source: { custom: true } });
  });
}
