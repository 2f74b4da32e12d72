// Where the MaterialX Python package is: the venv .ci/run makes (scripts/materialx-venv.sh), or the Python that
// MATERIALX_PYTHON names. The tests that need it skip, and say why, when neither has it.
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { homedir } from 'node:os';
import { join } from 'node:path';

/** The venv .ci/run installs MaterialX into. */
export const MATERIALX_VENV = join(
  process.env.XDG_CACHE_HOME ?? join(homedir(), '.cache'),
  'shading-lab',
  'materialx-venv',
);

export const MATERIALX_MISSING =
  `the MaterialX Python package is not installed (run scripts/materialx-venv.sh, or .ci/run, to put it in ` +
  `${MATERIALX_VENV}; or set MATERIALX_PYTHON to a Python that has \`materialx\` 1.39.5)`;

/** The path of a Python that imports MaterialX, or null. */
export function materialxPython() {
  const python = process.env.MATERIALX_PYTHON ?? join(MATERIALX_VENV, 'bin', 'python');
  if (!existsSync(python)) return null;
  try {
    execFileSync(python, ['-c', 'import MaterialX'], { stdio: 'ignore' });
    return python;
  } catch {
    return null;
  }
}
