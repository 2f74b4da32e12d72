// Just enough PNG decoding for the engines runner to look at a screenshot: 8-bit RGB or RGBA, not interlaced (what
// Chromium, Firefox and WebKitGTK write). No dependency: the chunks, zlib's inflate and the five row filters.
import { inflateSync } from 'node:zlib';

const paeth = (a, b, c) => {
  const p = a + b - c;
  const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
};

/** { width, height, channels, data } of a PNG file (data: the unfiltered samples, row after row). */
export function decodePng(buffer) {
  const bytes = Buffer.from(buffer);
  let offset = 8; // the signature
  let header;
  const idat = [];
  while (offset < bytes.length) {
    const length = bytes.readUInt32BE(offset);
    const type = bytes.toString('latin1', offset + 4, offset + 8);
    const body = bytes.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') header = { width: body.readUInt32BE(0), height: body.readUInt32BE(4), depth: body[8] };
    if (type === 'IHDR') Object.assign(header, { colour: body[9], interlace: body[12] });
    if (type === 'IDAT') idat.push(body);
    offset += 12 + length;
  }
  const channels = { 2: 3, 6: 4 }[header.colour];
  if (header.depth !== 8 || !channels || header.interlace) throw new Error('decodePng: 8-bit RGB(A) only');
  const raw = inflateSync(Buffer.concat(idat));
  const stride = header.width * channels;
  const data = new Uint8Array(stride * header.height);
  for (let y = 0; y < header.height; y++) {
    const filter = raw[y * (stride + 1)];
    const src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const row = y * stride;
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? data[row + x - channels] : 0;
      const b = y > 0 ? data[row - stride + x] : 0;
      const c = x >= channels && y > 0 ? data[row - stride + x - channels] : 0;
      const predictor = [0, a, b, (a + b) >> 1, paeth(a, b, c)][filter];
      data[row + x] = (src[x] + predictor) & 255;
    }
  }
  return { width: header.width, height: header.height, channels, data };
}

/** Distinct colours among every 7th pixel of a PNG: a canvas that drew something has more than a few. */
export function distinctColours(buffer) {
  const { data, channels } = decodePng(buffer);
  const seen = new Set();
  for (let i = 0; i < data.length; i += channels * 7) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
  return seen.size;
}
