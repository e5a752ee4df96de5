// Writes docs/elements.md, the reference of every element, from custom-elements.json (the manifest `npm run analyze`
// makes from the sources' JSDoc), so the reference cannot drift from the code. The output depends only on the
// manifest: no dates, no paths of this machine, elements in a fixed order.
//
//   node scripts/docs-elements.mjs          rewrites docs/elements.md
//   node scripts/docs-elements.mjs --check  rewrites it too, and exits 1 if it had been out of date (npm test)
//
// What is documented: the public API of each tag (attributes, properties, methods, events, CSS parts and custom
// properties, slots). Private and protected members are left out, and so are methods without a JSDoc description
// (element plumbing such as `describe()`, or DOM overrides such as `addEventListener`). What a tag inherits unchanged
// from another tag, or from a shared base class such as the body element's, is written once, where it is declared.
import { readFileSync, writeFileSync, existsSync, mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
const manifestPath = root + 'custom-elements.json';
const outPath = root + 'docs/elements.md';

/** The element families, named by the class every member of a family derives from. */
const FAMILIES = {
  PhysicsSceneElement: {
    title: 'Scenes',
    intro: 'A scene simulates and draws its child elements. The presets are scenes that make their own bodies.',
  },
  PhysicsBodyElement: { title: 'Bodies', common: 'every body', intro: 'Children of a scene that declare a body.' },
  PhysicsLinkElement: { title: 'Links', common: 'every link', intro: 'Children of a scene that join bodies, named by their `id`.' },
};

export function generate(manifest) {
  const classes = new Map();
  for (const mod of manifest.modules ?? []) {
    for (const decl of mod.declarations ?? []) {
      if (decl.kind === 'class') classes.set(decl.name, { ...decl, modulePath: mod.path });
    }
  }
  const superOf = (decl) => (decl.superclass && classes.get(decl.superclass.name)) || null;
  /** The topmost class of the manifest an element derives from: it names the element's family. */
  const familyOf = (decl) => {
    let top = decl;
    for (let up = superOf(decl); up; up = superOf(up)) top = up;
    return top;
  };

  const tags = [...classes.values()].filter((c) => c.tagName);
  const families = new Map();
  for (const tag of tags) {
    const family = familyOf(tag);
    if (!families.has(family.name)) families.set(family.name, { base: family, tags: [] });
    families.get(family.name).tags.push(tag);
  }
  const familyOrder = Object.keys(FAMILIES);
  const rank = (name) => (familyOrder.includes(name) ? familyOrder.indexOf(name) : familyOrder.length);
  const orderedFamilies = [...families.values()].sort(
    (a, b) => rank(a.base.name) - rank(b.base.name) || byCodePoint(a.base.name, b.base.name),
  );
  for (const family of orderedFamilies) {
    // The family's own tag first (<physics-scene> before its presets), then by tag name.
    family.tags.sort((a, b) => Number(b === family.base) - Number(a === family.base) || byCodePoint(a.tagName, b.tagName));
  }

  const out = [];
  out.push('# Elements');
  out.push('');
  out.push('<!-- Generated from custom-elements.json by scripts/docs-elements.mjs. Do not edit: change the JSDoc in the');
  out.push('     sources, then `npm run analyze` and `node scripts/docs-elements.mjs` (npm test fails when this is stale). -->');
  out.push('');
  out.push('The reference of every tag, generated from the manifest the sources\' documentation comments produce.');
  out.push('For how the elements behave on a page (sizing, visibility, reduced motion, errors, builds, CSP) see');
  out.push('[embedding.md](embedding.md). Positions and sizes are in world units: a scene\'s `width` × `height` is the visible');
  out.push('box, its origin the top-left corner, y grows downward; angles in markup are degrees, clockwise on screen.');
  out.push('');
  const about = (family) => FAMILIES[family.base.name] ?? { title: family.base.name, common: family.base.name };
  for (const family of orderedFamilies) {
    out.push(`- ${about(family).title}: ${family.tags.map((t) => `[\`<${t.tagName}>\`](#${t.tagName})`).join(', ')}`);
  }
  out.push('');

  for (const family of orderedFamilies) {
    const { title, intro, common } = about(family);
    out.push(`## ${title}`);
    out.push('');
    if (intro) {
      out.push(intro);
      out.push('');
    }
    if (!family.base.tagName) {
      out.push(`### Common to ${common}`);
      out.push('');
      out.push(...describeApi(family.base, classes, { inheritedNote: null }));
    }
    // Shared base classes between the family's base and its tags (the shapes' one: boxes, polygons and balls), each
    // written once, under the tags that share it.
    const ancestors = (decl) => {
      const list = [];
      for (let up = superOf(decl); up && up !== family.base; up = superOf(up)) list.push(up);
      return list;
    };
    const shared = new Map();
    for (const tag of family.tags) for (const up of ancestors(tag)) if (!up.tagName) shared.set(up.name, up);
    const sharedBy = (decl) => family.tags.filter((t) => ancestors(t).includes(decl));
    const tagList = (list) => {
      const names = list.map((t) => `\`<${t.tagName}>\``);
      return names.length > 1 ? `${names.slice(0, -1).join(', ')} and ${names.at(-1)}` : names.join('');
    };
    const sharedOrder = [...shared.values()].sort((a, b) => byCodePoint(a.name, b.name));
    for (const tag of family.tags) {
      // A shared base's section comes just before the first tag that shares it.
      for (const decl of sharedOrder.filter((d) => sharedBy(d)[0] === tag)) {
        out.push(`### Common to ${tagList(sharedBy(decl))}`);
        out.push('');
        out.push(...describeApi(decl, classes, { inheritedNote: null }));
      }
      out.push(`<a id="${tag.tagName}"></a>`);
      out.push('');
      out.push(`### \`<${tag.tagName}>\``);
      out.push('');
      const from = tag.modulePath ? `Source: [\`${tag.modulePath}\`](../${tag.modulePath}).` : '';
      out.push(...wrap(`${oneLine(tag.description ?? tag.summary ?? '')} ${from}`.trim()));
      out.push('');
      const parentTag = nearestTagAncestor(tag, classes);
      let inheritedNote = null;
      const sharedBases = ancestors(tag).filter((up) => !up.tagName);
      if (parentTag) {
        const shared = sharedBases.map((up) => `, and what is common to ${tagList(sharedBy(up))} (above)`).join('');
        inheritedNote = `Also every attribute, property, method, event and CSS part of [\`<${parentTag.tagName}>\`](#${parentTag.tagName})${shared}, except where listed here.`;
      } else if (!family.base.tagName && tag !== family.base) {
        const also = sharedBases.map((up) => ` and to ${tagList(sharedBy(up))}`).join('');
        inheritedNote = `Also the attributes, properties and methods common to ${common}${also} (above).`;
      }
      out.push(...describeApi(tag, classes, { inheritedNote }));
    }
  }
  return out.join('\n').replace(/\n{3,}/g, '\n\n').trimEnd() + '\n';
}

function nearestTagAncestor(decl, classes) {
  for (let up = decl.superclass && classes.get(decl.superclass.name); up; up = up.superclass && classes.get(up.superclass.name)) {
    if (up.tagName) return up;
  }
  return null;
}

/**
 * Whether an inherited entry (attribute, member, event, part) is worth listing on this class: inherited entries are
 * written where they are declared, unless this class changes them (a preset's own default width, say).
 */
function isOwn(entry, kind, classes) {
  if (!entry.inheritedFrom) return true;
  const origin = classes.get(entry.inheritedFrom.name);
  const original = origin?.[kind]?.find((e) => e.name === entry.name);
  if (!original) return true;
  // A shadow part or CSS property belongs to the template that declares it: a subclass re-describing it adds nothing.
  if (kind === 'cssParts' || kind === 'cssProperties') return false;
  const signature = (e) => JSON.stringify([e.type?.text, e.default, oneLine(e.description ?? ''), e.attribute, e.fieldName]);
  return signature(original) !== signature(entry);
}

/** Locale-independent order, so every machine writes the same file. */
const byCodePoint = (a, b) => (a < b ? -1 : a > b ? 1 : 0);

const isPublic = (m) => !m.privacy && !/^[_#]/.test(m.name);

function describeApi(decl, classes, { inheritedNote }) {
  const out = [];
  const members = decl.members ?? [];
  const memberByName = new Map(members.map((m) => [m.name, m]));
  const attributes = (decl.attributes ?? []).filter((a) => isOwn(a, 'attributes', classes));
  const attributeFields = new Set((decl.attributes ?? []).map((a) => a.fieldName).filter(Boolean));
  // A getter and setter pair comes as two fields of one name: one row, the documented one.
  const fieldByKey = new Map();
  for (const m of members) {
    if (m.kind !== 'field' || !isPublic(m) || attributeFields.has(m.name) || m.attribute || !isOwn(m, 'members', classes)) continue;
    const key = `${m.static ? 'static ' : ''}${m.name}`;
    if (!fieldByKey.has(key) || (!fieldByKey.get(key).description && m.description)) fieldByKey.set(key, m);
  }
  const properties = [...fieldByKey.values()];
  const methods = members.filter((m) => m.kind === 'method' && isPublic(m) && m.description && isOwn(m, 'members', classes));
  const events = (decl.events ?? []).filter((e) => e.name && isOwn(e, 'events', classes));
  const parts = (decl.cssParts ?? []).filter((p) => isOwn(p, 'cssParts', classes));
  const cssProperties = (decl.cssProperties ?? []).filter((p) => isOwn(p, 'cssProperties', classes));
  const slots = (decl.slots ?? []).filter((s) => isOwn(s, 'slots', classes));

  if (attributes.length) {
    out.push('| attribute | property | type | default | description |');
    out.push('| --- | --- | --- | --- | --- |');
    for (const a of attributes) {
      const field = a.fieldName ? memberByName.get(a.fieldName) : undefined;
      const type = a.type?.text ?? field?.type?.text;
      const description = a.description ?? field?.description ?? '';
      out.push(row([code(a.name), a.fieldName ? code(a.fieldName) : '', type ? code(type) : '', a.default !== undefined ? code(a.default) : '', cell(description)]));
    }
    out.push('');
  }
  if (properties.length) {
    out.push('| property | type | description |');
    out.push('| --- | --- | --- |');
    for (const p of properties) {
      const flags = [p.static ? 'static' : '', p.readonly ? 'read-only' : ''].filter(Boolean).join(', ');
      const name = code(p.static ? `${decl.name}.${p.name}` : p.name) + (flags ? ` (${flags})` : '');
      out.push(row([name, p.type?.text ? code(p.type.text) : '', cell(p.description ?? '')]));
    }
    out.push('');
  }
  if (methods.length) {
    out.push('| method | description |');
    out.push('| --- | --- |');
    for (const m of methods) out.push(row([code(signature(m)), cell(m.description)]));
    out.push('');
  }
  if (events.length) {
    out.push('| event | description |');
    out.push('| --- | --- |');
    for (const e of events) out.push(row([code(e.name), cell(e.description ?? '')]));
    out.push('');
  }
  if (slots.length) {
    out.push('| slot | description |');
    out.push('| --- | --- |');
    for (const s of slots) out.push(row([s.name ? code(s.name) : '(default)', cell(s.description ?? '')]));
    out.push('');
  }
  if (parts.length) {
    out.push('| CSS part | description |');
    out.push('| --- | --- |');
    for (const p of parts) out.push(row([code(p.name), cell(p.description ?? '')]));
    out.push('');
  }
  if (cssProperties.length) {
    out.push('| CSS custom property | description |');
    out.push('| --- | --- |');
    for (const p of cssProperties) out.push(row([code(p.name), cell(p.description ?? '') + (p.default ? ` Default ${code(p.default)}.` : '')]));
    out.push('');
  }
  if (inheritedNote) {
    out.push(inheritedNote);
    out.push('');
  }
  return out;
}

function signature(method) {
  const params = (method.parameters ?? []).map((p) => {
    let s = p.rest ? `...${p.name}` : p.name;
    if (p.optional) s += '?';
    if (p.type?.text) s += `: ${p.type.text}`;
    if (p.default !== undefined) s += ` = ${p.default}`;
    return s;
  });
  const ret = method.return?.type?.text;
  return `${method.static ? 'static ' : ''}${method.name}(${params.join(', ')})${ret ? `: ${ret}` : ''}`;
}

const oneLine = (text) => text.replace(/\s*\n\s*/g, ' ').trim();
const cell = (text) => oneLine(text).replace(/\|/g, '\\|');
/** Inline code that may hold `|` (union types) inside a table cell. */
const code = (text) => '`' + String(text).replace(/\|/g, '\\|') + '`';
const row = (cells) => `| ${cells.join(' | ')} |`;

/** Prose lines at most 118 characters, broken at spaces. */
function wrap(text, width = 118) {
  const lines = [];
  let line = '';
  for (const word of text.split(/\s+/).filter(Boolean)) {
    if (line && line.length + 1 + word.length > width) {
      lines.push(line);
      line = word;
    } else line = line ? `${line} ${word}` : word;
  }
  if (line) lines.push(line);
  return lines;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const check = process.argv.includes('--check');
  const text = generate(JSON.parse(readFileSync(manifestPath, 'utf8')));
  const before = existsSync(outPath) ? readFileSync(outPath, 'utf8') : null;
  if (before !== text) {
    mkdirSync(root + 'docs', { recursive: true });
    writeFileSync(outPath, text);
  }
  if (check && before !== text) {
    console.error('docs/elements.md was out of date with custom-elements.json (regenerated now by scripts/docs-elements.mjs): commit it');
    process.exit(1);
  }
  if (!check) console.log(before === text ? 'docs/elements.md is up to date' : 'docs/elements.md written');
}
