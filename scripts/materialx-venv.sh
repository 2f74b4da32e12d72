#!/usr/bin/env bash
# The MaterialX Python package (PyPI `materialx`, pinned) in a venv of its own, for the tests that run MaterialX
# (tests/browser/materialx.test.js, tests/unit/mtlx-materialx.test.js): its shader generator and its validate().
# Idempotent: when the venv already has that version it returns at once. The tests find it at the same path
# (tests/support/materialx-python.js).
set -euo pipefail
VERSION=1.39.5
VENV="${XDG_CACHE_HOME:-$HOME/.cache}/shading-lab/materialx-venv"
if "$VENV/bin/python" -c "import MaterialX, sys; sys.exit(MaterialX.getVersionString() != '$VERSION')" 2>/dev/null; then
  exit 0
fi
PYTHON="${PYTHON:-python3}"
echo "materialx: installing materialx==$VERSION into $VENV"
"$PYTHON" -m venv "$VENV"
"$VENV/bin/pip" install --quiet --disable-pip-version-check "materialx==$VERSION"
