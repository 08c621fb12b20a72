/** What the page lends its two controllers (SingleSource, WholeShape), and the options they send. */
import { defaultOptions, type RunSettings } from '../../lib/core/options.ts';
import type { Options } from '../../lib/core/types.ts';
import type { Viewer } from './viewer/viewer.ts';
import type { GeometryClient } from './worker/client.ts';

/** The viewer, the worker, the options and run settings, and the busy state. */
export interface StudioContext {
  viewer: Viewer;
  client: GeometryClient;
  /** Colours of the layers, for the layer list. */
  layerColors: Map<string, string>;
  options(): Options;
  settings(): RunSettings;
  /** A computation starts / ends (page state, busy status). */
  begin(status: string): void;
  end(): void;
  /** Shows an error box. */
  fail(title: string, error: unknown): void;
  /** The controller's data changed: the page redraws the stage shown. */
  changed(): void;
  /** A run progressed (no new picture): the page updates the timeline only. */
  progressed(): void;
}

/** Only the options that differ from the defaults travel to the worker. */
export function changedOptions(options: Options): Partial<Options> {
  return Object.fromEntries(
    (Object.keys(options) as Array<keyof Options>).filter((k) => options[k] !== defaultOptions[k]).map((k) => [k, options[k]]),
  ) as Partial<Options>;
}
