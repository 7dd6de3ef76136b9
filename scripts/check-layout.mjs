#!/usr/bin/env node
// Fails when the README's Layout leaves out a module: every file of www/js and core/src must be
// named in its paragraph (www/ or core/). A file at the top names itself by its stem (`main` for
// main.js), a folder by `name/`, and a file in a folder by its stem after that folder's first
// mention (live/ ... drivetrain). mod.rs and lib.rs name nothing. Usage: node scripts/check-layout.mjs
import { readFileSync, readdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const readme = readFileSync(join(root, 'README.md'), 'utf8');
const layout = (readme.split(/^## Layout$/m)[1] || '').split(/^```$/m)[1] || '';

// The paragraph of a top-level entry: from its line to the next line that starts another entry.
function paragraph(entry) {
  const m = layout.match(new RegExp(`^${entry}\\s[\\s\\S]*?(?=^\\S|$(?![\\s\\S]))`, 'm'));
  return m ? m[0] : '';
}

const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
const names = (text, word) => new RegExp(`(?<![\\w-])${escape(word)}(?![\\w-]|/)`).test(text);

// The files and folders under dir, as paths relative to it.
function walk(dir, rel = '') {
  return readdirSync(join(dir, rel), { withFileTypes: true })
    .filter((e) => !e.name.startsWith('.'))
    .flatMap((e) => {
      const p = rel ? `${rel}/${e.name}` : e.name;
      return e.isDirectory() ? [`${p}/`, ...walk(dir, p)] : [p];
    });
}

// What of dir its paragraph leaves out.
function missing(entry, dir) {
  const text = paragraph(entry);
  if (!text) return [`(no "${entry}" paragraph in the README's Layout)`];
  return walk(join(root, dir)).filter((p) => {
    const parts = p.replace(/\/$/, '').split('/');
    const name = parts.pop();
    const parent = parts.length ? `${parts[parts.length - 1]}/` : null;
    const at = parent ? text.search(new RegExp(`(?<![\\w-])${escape(parent)}`)) : 0;
    if (at < 0) return false; // its folder is reported on its own
    const after = text.slice(at);
    if (p.endsWith('/')) return !new RegExp(`(?<![\\w-])${escape(name)}/`).test(after);
    if (name === 'mod.rs' || name === 'lib.rs') return false;
    return !names(after, name.replace(/\.[^.]+$/, ''));
  }).map((p) => `${dir}/${p}`);
}

const out = [...missing('www/', 'www/js'), ...missing('core/', 'core/src')];
if (out.length) {
  console.error(`README.md's Layout does not name ${out.length} module(s):\n  ${out.join('\n  ')}`);
  process.exit(1);
}
console.log('README.md\'s Layout names every module of www/js and core/src');
