#!/usr/bin/env bash
# Checks that `import vibro` works in a fresh shell under PYTHON, with no environment variable set
# and from a directory of no consequence, and that it is the package built in PACKAGE_DIR (what
# scripts/setup.sh installs). Usage: installed.sh PYTHON PACKAGE_DIR
set -euo pipefail
python="$1"
built="$2"
cd /
installed=$(env -i "$python" -c 'import os, vibro; print(os.path.dirname(vibro.__file__))') || {
  echo "installed.sh: '$python -c \"import vibro\"' fails in a fresh shell: run scripts/setup.sh"
  exit 1
}
for f in "$built"/__init__.py "$built"/_vibro*.so; do
  if ! cmp -s "$f" "$installed/$(basename "$f")"; then
    echo "installed.sh: $installed/$(basename "$f") is not this build's $f: run scripts/setup.sh"
    exit 1
  fi
done
echo "installed.sh: import vibro gives $installed, this build's package"
