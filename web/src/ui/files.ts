/** Getting mesh files from the user: a file-picker button and drag-and-drop anywhere on the window. */

export interface FileSources {
  button: HTMLButtonElement;
  input: HTMLInputElement;
  overlay: HTMLElement;
  /** Accepted extensions such as '.ply' (the picker's filter; the parser has the last word). */
  extensions: readonly string[];
  onFile(file: File): void;
}

export function installFileSources({ button, input, overlay, extensions, onFile }: FileSources): void {
  input.accept = extensions.join(',');
  button.addEventListener('click', () => input.click());
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    input.value = ''; // picking the same file again still fires 'change'
    if (file) onFile(file);
  });

  const hasFiles = (e: DragEvent) => !!e.dataTransfer && [...e.dataTransfer.types].includes('Files');
  window.addEventListener('dragover', (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    e.dataTransfer!.dropEffect = 'copy';
    overlay.hidden = false;
  });
  window.addEventListener('dragleave', (e) => {
    if (e.relatedTarget === null) overlay.hidden = true; // left the window
  });
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    overlay.hidden = true;
    const file = e.dataTransfer?.files[0];
    if (file) onFile(file);
  });
}
