// The page learns what a planner or robot can do from the core's registry, never by comparing names:
// this check fails when a JavaScript file of www/ (outside the capabilities adapter,
// www/draw/capabilities.js, and the generated www/pkg/) compares or lists a registered planner name
// or robot kind. The names come from the core itself (the wasm build's `planners()` and
// `robot_kinds()`), so a planner added to the registry is covered without editing this file.
//
// Flagged: a string literal equal to a name (any quotes; a template without `${}`)
//   - compared: `x === 'rrt'`, `'rrt' !== x` (==, !=, ===, !==);
//   - a switch case: `case 'rrt':`;
//   - an object key: `{'rrt-star': …}`, or an index: `table['rrt-star']`;
//   - an item of an array literal: `new Set(['prm', …])`, `['rrt', …].includes(x)`.
// Not flagged: a name as a value (a default set-up, `{planner: 'rrt-connect'}`), in a comment, or
// compared with a `task` (the registry's task kinds, 'goal' | 'inspection', are another vocabulary).
// Bare identifier keys (`{rrt: …}`) are not flagged: scenario keys (`inspection`) share the spelling.
//
// Usage: node scripts/check-names.mjs [files…]   (default: every .js/.mjs of www/); needs the wasm
// build (www/pkg). Exit 1 with each finding as file:line.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const ADAPTER = 'www/draw/capabilities.js';

/** The registered planner names and robot kinds, read from the core (wasm build in Node). */
export async function registeredNames() {
  const pkg = await import(join(root, 'www/pkg/planarium.js'));
  pkg.initSync({ module: readFileSync(join(root, 'www/pkg/planarium_bg.wasm')) });
  const planners = JSON.parse(pkg.planners()).planners.map((p) => p.name);
  const kinds = JSON.parse(pkg.robot_kinds()).map((k) => k.name);
  return { planners, kinds };
}

/**
 * The tokens of JavaScript source `text`: {t: 'str' | 'id' | 'p' (punctuation), v, line}; comments
 * dropped; a template literal with `${…}` is one opaque token. Regular expression literals are
 * skipped where a value may start.
 */
export function tokens(text) {
  const out = [];
  let i = 0;
  let line = 1;
  const n = text.length;
  const valueMayStart = () => {
    const last = out[out.length - 1];
    return !last || (last.t === 'p' && !/^[)\]}]$/.test(last.v)) || (last.t === 'id' && /^(return|typeof|case|in|of|new|delete|void|throw|else|do|yield|await)$/.test(last.v));
  };
  while (i < n) {
    const c = text[i];
    if (c === '\n') { line++; i++; continue; }
    if (/\s/.test(c)) { i++; continue; }
    if (c === '/' && text[i + 1] === '/') { while (i < n && text[i] !== '\n') i++; continue; }
    if (c === '/' && text[i + 1] === '*') {
      const end = text.indexOf('*/', i + 2);
      const stop = end < 0 ? n : end + 2;
      for (let k = i; k < stop; k++) if (text[k] === '\n') line++;
      i = stop;
      continue;
    }
    if (c === '\'' || c === '"' || c === '`') {
      const start = line;
      let v = '';
      let opaque = false;
      let depth = 0;
      i++;
      while (i < n) {
        const d = text[i];
        if (d === '\\') { v += text[i + 1] ?? ''; i += 2; continue; }
        if (d === '\n') line++;
        if (c === '`' && d === '$' && text[i + 1] === '{') { opaque = true; depth++; i += 2; continue; }
        if (c === '`' && depth > 0) {
          if (d === '{') depth++;
          else if (d === '}') depth--;
          i++;
          continue;
        }
        if (d === c) { i++; break; }
        v += d;
        i++;
      }
      out.push(opaque ? { t: 'p', v: 'template', line: start } : { t: 'str', v, line: start });
      continue;
    }
    if (c === '/' && valueMayStart()) { // a regular expression literal
      i++;
      let cls = false;
      while (i < n && text[i] !== '\n') {
        const d = text[i];
        if (d === '\\') { i += 2; continue; }
        if (d === '[') cls = true;
        else if (d === ']') cls = false;
        else if (d === '/' && !cls) { i++; break; }
        i++;
      }
      while (i < n && /[a-z]/.test(text[i])) i++;
      out.push({ t: 'p', v: 'regex', line });
      continue;
    }
    const id = /^[A-Za-z_$][\w$]*/.exec(text.slice(i, i + 200));
    if (id) { out.push({ t: 'id', v: id[0], line }); i += id[0].length; continue; }
    const num = /^\d[\w.]*/.exec(text.slice(i, i + 100));
    if (num) { out.push({ t: 'num', v: num[0], line }); i += num[0].length; continue; }
    const op = /^(===|!==|==|!=|=>|\?\?|\?\.|&&|\|\||\.\.\.|[^\s])/.exec(text.slice(i, i + 3));
    out.push({ t: 'p', v: op[0], line });
    i += op[0].length;
  }
  return out;
}

const COMPARE = new Set(['===', '!==', '==', '!=']);

/** The findings in source `text`: [{line, name, how}] for each name in `names` compared or listed. */
export function findNames(text, names) {
  const toks = tokens(text);
  const set = new Set(names);
  const found = [];
  /** @type {string[]} the open brackets */
  const stack = [];
  toks.forEach((tk, k) => {
    if (tk.t === 'p' && '([{'.includes(tk.v)) stack.push(tk.v);
    if (tk.t === 'p' && ')]}'.includes(tk.v)) stack.pop();
    if (tk.t !== 'str' || !set.has(tk.v)) return;
    const prev = toks[k - 1];
    const next = toks[k + 1];
    let how = null;
    const task = (from, to) => toks.slice(Math.max(0, from), to).some((t) => t.t === 'id' && t.v === 'task');
    if (prev && COMPARE.has(prev.v)) how = task(k - 7, k - 1) ? null : 'compared';
    else if (next && COMPARE.has(next.v)) how = task(k + 2, k + 6) ? null : 'compared';
    else if (prev?.v === 'case') how = 'a switch case';
    else if (next?.v === ':' && (prev?.v === '{' || prev?.v === ',')) how = 'an object key';
    else if (prev?.v === '[' && next?.v === ']' && toks[k - 2] && (toks[k - 2].t === 'id' || toks[k - 2].v === ')' || toks[k - 2].v === ']')) how = 'an index';
    else if (stack[stack.length - 1] === '[' && (prev?.v === '[' || prev?.v === ',')) how = 'listed';
    if (how) found.push({ line: tk.line, name: tk.v, how });
  });
  return found;
}

/** Every .js and .mjs file under `dir` (relative to the root), but www/pkg and the adapter. */
function files(dir) {
  const out = [];
  for (const e of readdirSync(join(root, dir))) {
    const rel = `${dir}/${e}`;
    if (rel === 'www/pkg' || rel === ADAPTER || e === 'node_modules') continue;
    if (statSync(join(root, rel)).isDirectory()) out.push(...files(rel));
    else if (/\.m?js$/.test(e)) out.push(rel);
  }
  return out;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const { planners, kinds } = await registeredNames();
  const list = process.argv.length > 2 ? process.argv.slice(2).map((f) => relative(root, resolve(f))) : files('www');
  const problems = [];
  for (const f of list) {
    for (const { line, name, how } of findNames(readFileSync(join(root, f), 'utf8'), [...planners, ...kinds])) {
      problems.push(`${f}:${line}: "${name}" ${how} (${planners.includes(name) ? 'a planner' : 'a robot kind'}: key it on the registry's capabilities, ${ADAPTER})`);
    }
  }
  if (problems.length) {
    console.error(`[check-names] ${problems.length} name(s) compared or listed in www/:\n${problems.map((p) => `  ${p}`).join('\n')}`);
    process.exit(1);
  }
  console.log(`[check-names] ${list.length} files of www/ compare or list none of ${planners.length} planner names and ${kinds.length} robot kinds`);
}
