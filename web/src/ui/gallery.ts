/** The sample meshes shipped in public/samples/ (provenance and licences: public/samples/README.md). */

export interface Sample {
  /** The name in links (`#mesh=bob`). */
  name: string;
  file: string;
  label: string;
  /** What it shows off. */
  note: string;
}

export const SAMPLES: readonly Sample[] = [
  { name: 'spot', file: 'spot.ply', label: 'Spot', note: 'genus 0 · 5.9K faces · a cow: horns, ears, legs' },
  { name: 'bob', file: 'bob.ply', label: 'Bob', note: 'genus 1 · 11K faces · a handle: one skeleton cycle' },
  { name: 'fertility', file: 'fertility_9k.ply', label: 'Fertility', note: 'genus 4 · 9K faces · four cycles' },
  { name: 'hand', file: 'hand.ply', label: 'Hand', note: 'genus 0 · 21K faces · five fingers' },
  { name: 'wolf', file: 'wolf.ply', label: 'Wolf', note: 'genus 0 · 6.5K faces · legs, tail, ears' },
];

export const DEFAULT_SAMPLE = SAMPLES[0];

export const sampleByName = (name: string | null): Sample | undefined => SAMPLES.find((s) => s.name === name);

/** One button per sample; `onPick` opens it. */
export function installGallery(root: HTMLElement, onPick: (sample: Sample) => void): void {
  root.replaceChildren(
    ...SAMPLES.map((sample) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'sample';
      button.dataset.testid = `sample-${sample.name}`;
      button.textContent = sample.label;
      button.title = `${sample.label}: ${sample.note}`;
      button.addEventListener('click', () => onPick(sample));
      return button;
    }),
  );
}

/** Marks the open sample (none for a file the user opened). */
export function markSample(root: HTMLElement, name: string | null): void {
  for (const button of root.querySelectorAll<HTMLButtonElement>('.sample')) {
    button.classList.toggle('current', button.dataset.testid === `sample-${name}`);
  }
}
