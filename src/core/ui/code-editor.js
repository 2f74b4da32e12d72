// @ts-check
// A GLSL code editor (CodeMirror 6): highlighting (the legacy `shader` mode of clike), line numbers, undo/redo,
// bracket matching, and diagnostics on the user's own lines. Keyboard: Tab indents, and, as CodeMirror documents
// (https://codemirror.net/examples/tab/), Escape then Tab leaves the editor (Ctrl-M turns Tab-moves-focus on for
// good). Pages load this module with a dynamic import only when a custom term is chosen.
import { EditorState, Annotation } from '@codemirror/state';
import { EditorView, keymap, lineNumbers, highlightActiveLine, drawSelection } from '@codemirror/view';
import { defaultKeymap, history, historyKeymap, indentWithTab } from '@codemirror/commands';
import { StreamLanguage, bracketMatching, indentOnInput, syntaxHighlighting } from '@codemirror/language';
import { defaultHighlightStyle } from '@codemirror/language';
import { setDiagnostics, lintGutter } from '@codemirror/lint';
import { shader } from '@codemirror/legacy-modes/mode/clike';

/** Marks a change made by `value = …` (not the user's), so that onChange stays quiet. */
const fromProgram = Annotation.define();

const KEYS_HINT = 'Tab indents; Escape then Tab moves on to the next control.';

/**
 * @typedef {object} CodeEditor
 * @property {string} value  the text; setting it replaces the text without calling onChange (undo keeps it)
 * @property {(problems: { line: number, message: string }[]) => void} setDiagnostics  marks the user's lines
 *   (1-based; a line past the end marks the last)
 * @property {() => void} focus
 * @property {() => void} destroy
 */

/**
 * @param {HTMLElement} parent
 * @param {{ doc?: string, label: string, onChange?: (text: string) => void }} options
 * @returns {CodeEditor}
 */
export function createCodeEditor(parent, { doc = '', label, onChange }) {
  const hint = document.createElement('p');
  hint.className = 'code-editor-keys';
  hint.id = `code-editor-keys-${Math.random().toString(36).slice(2, 10)}`;
  hint.textContent = KEYS_HINT;
  const view = new EditorView({
    parent,
    state: EditorState.create({
      doc,
      extensions: [
        lineNumbers(),
        highlightActiveLine(),
        drawSelection(),
        history(),
        indentOnInput(),
        bracketMatching(),
        StreamLanguage.define(shader),
        syntaxHighlighting(defaultHighlightStyle),
        lintGutter(),
        EditorView.lineWrapping, // a narrow panel (an embed, a phone) wraps long comments instead of hiding them
        keymap.of([...defaultKeymap, ...historyKeymap, indentWithTab]),
        EditorView.contentAttributes.of({ 'aria-label': label, 'aria-describedby': hint.id }),
        EditorView.updateListener.of((u) => {
          if (u.docChanged && !u.transactions.some((t) => t.annotation(fromProgram)))
            onChange?.(u.state.doc.toString());
        }),
      ],
    }),
  });
  parent.append(hint);

  return {
    get value() {
      return view.state.doc.toString();
    },
    set value(text) {
      if (text === view.state.doc.toString()) return;
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text }, annotations: fromProgram.of(1) });
    },
    setDiagnostics(problems) {
      const { doc: text } = view.state;
      const diagnostics = problems.map(({ line, message }) => {
        const at = text.line(Math.min(Math.max(Math.round(line) || 1, 1), text.lines));
        return {
          from: at.from,
          to: at.to,
          severity: /** @type {const} */ ('error'),
          message: `Line ${line}: ${message}`,
        };
      });
      view.dispatch(setDiagnostics(view.state, diagnostics));
    },
    focus: () => view.focus(),
    destroy() {
      view.destroy();
      hint.remove();
    },
  };
}
