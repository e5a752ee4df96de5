// The installed version of a package, read from node_modules (some packages do not export their package.json).
import { readFileSync } from 'node:fs';

const root = new URL('../../../', import.meta.url);

export const installedVersion = (name) => JSON.parse(readFileSync(new URL(`node_modules/${name}/package.json`, root), 'utf8')).version;
