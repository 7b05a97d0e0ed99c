/** Offers a blob to the user as a file download named `name`. */
export function downloadBlob(blob: Blob, name: string): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  // The browser has started the download once click() returns; the URL is freed a little later for slow browsers.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** A file-name-safe local timestamp, `2025-06-01T14-03-09`. */
export function fileTimestamp(date = new Date()): string {
  const p = (n: number): string => String(n).padStart(2, '0');
  const day = `${date.getFullYear()}-${p(date.getMonth() + 1)}-${p(date.getDate())}`;
  return `${day}T${p(date.getHours())}-${p(date.getMinutes())}-${p(date.getSeconds())}`;
}
