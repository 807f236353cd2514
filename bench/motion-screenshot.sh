#!/usr/bin/env bash
# Renders the motion model's SVG output in a headless browser, to check by eye that it reads
# well (doc/motion.md, "Output"). Needs chromium (apt-get install -y chromium); not part of
# `make test`. Usage: bench/motion-screenshot.sh [OUTDIR]   (default _build/motion-demo)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-_build/motion-demo}
mkdir -p "$out"
dune build ./bench/motion_demo.exe
./_build/default/bench/motion_demo.exe "$out"
for f in path timeline; do
  chromium --headless --no-sandbox --disable-gpu --screenshot="$out/$f.png" \
    --window-size=1000,800 "file://$(realpath "$out/$f.svg")" 2>/dev/null
done
echo "wrote $out/path.png and $out/timeline.png"
