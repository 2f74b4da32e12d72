// Hands a file to the reader: a blob saved under `filename` through a temporary link. Here in the framework, below
// the UI pieces, because the framework's save-a-view button (save-view.js) and the UI's exports (ui/export.js) both
// use it.
export function download(filename, blob) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
