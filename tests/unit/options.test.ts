// The option specification (lib/core/options.ts) is the one every front end derives from: the core
// declares the same defaults, ranges and auto-N constants, and the docs show the table it generates.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadCoreNode, type Core } from '../../lib/core/node.ts';
import { AUTO_N, defaultCloudOptions, defaultOptions, MESH_OPTIONS, optionRanges, OPTIONS, optionTable, parseOptionText } from '../../lib/core/options.ts';
import { cloudFlagSpecs, cloudOptionsFromFlags, optionFlagSpecs, optionsFromFlags } from '../../cli/commands/separator.ts';
import { readUrl } from '../../web/src/ui/url-state.ts';
import { repoRoot } from '../paths.ts';

let core: Core;
beforeAll(async () => {
  core = await loadCoreNode();
});

describe('the option specification', () => {
  it('has the core’s defaults, ranges and auto-N constants', () => {
    const limits = core.optionLimits();
    expect(limits.defaults).toEqual({ ...defaultOptions, ...defaultCloudOptions });
    expect(limits.ranges).toEqual(Object.fromEntries(Object.entries(optionRanges).map(([k, r]) => [k, [...r]])));
    expect(limits.autoN).toEqual({ ...AUTO_N });
  });

  it('gives every option a CLI flag of its own, kebab-case of its name', () => {
    const flags = Object.keys({ ...optionFlagSpecs(), ...cloudFlagSpecs() });
    expect(flags).toHaveLength(OPTIONS.length);
    for (const o of OPTIONS) expect(o.flag).toBe(o.key.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`));
    expect(flags).toContain('no-sphere');
  });

  it('reads each default back from its text, in the CLI and in the address bar', () => {
    for (const o of OPTIONS) expect(parseOptionText(o, String(o.default))).toBe(o.default);
    expect(optionsFromFlags({})).toEqual({ ...defaultOptions });
    expect(cloudOptionsFromFlags({})).toEqual({ ...defaultCloudOptions });
    expect(cloudOptionsFromFlags({ neighbours: '12' }).neighbours).toBe(12);
    // The page opens meshes only: its address bar holds the mesh options.
    const changed = '#' + MESH_OPTIONS.map((o) => `${o.key}=${o.kind === 'switch' ? !o.default : o.kind === 'choice' ? 'geodesic' : o.kind === 'count' ? 7 : o.range[0] === o.default ? o.range[0] + 1 : o.range[0]}`).join('&');
    const options = readUrl(changed).options;
    for (const o of MESH_OPTIONS) expect(options[o.key], o.key).not.toBe(o.default);
  });

  it('keeps the point-cloud options out of a mesh’s options and the mesh options out of a cloud’s (and so out of their skeleton files)', () => {
    expect(Object.keys(defaultOptions)).not.toContain('neighbours');
    const { stage1Vertices, ...shared } = defaultOptions;
    expect(stage1Vertices).toBe(20000);
    expect(defaultCloudOptions).toEqual({ ...shared, neighbours: 30 });
  });

  it('is the option table of the README and docs/cli.md', () => {
    for (const file of ['README.md', 'docs/cli.md']) expect(readFileSync(path.join(repoRoot, file), 'utf8'), file).toContain(optionTable());
  });
});
