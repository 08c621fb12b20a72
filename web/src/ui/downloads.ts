/** Saving files from the page: bytes or a canvas picture handed to the browser as a download. */

export function saveFile(name: string, data: BlobPart, type: string): void {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  // The browser has started reading the blob by the time the click returns; a later revoke is safe.
  setTimeout(() => URL.revokeObjectURL(url), 30_000);
}

/** The canvas as PNG (it keeps its drawing buffer, so what is shown is what is saved). */
export function canvasPng(canvas: HTMLCanvasElement): Promise<Blob> {
  return new Promise((resolve, reject) => canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the canvas could not be encoded'))), 'image/png'));
}

/** "spot.ply" -> "spot". */
export const baseName = (fileName: string) => fileName.replace(/\.[^.]*$/, '') || 'mesh';
