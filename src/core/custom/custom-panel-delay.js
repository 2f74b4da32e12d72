// @ts-check
// How long after the last keystroke an edit in a custom term's editor is run: typing is not compiled key by key.
// Its own module so that the bench (Node) reads it without the GPU code around the panel.
export const EDIT_DELAY_MS = 250;
