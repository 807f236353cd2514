#!/usr/bin/env bash
# Renders the motion model's SVG output in a headless browser, to check by eye that it reads
# well (doc/motion.md, "Output"): the demo program's path and timeline, and the example cell's
# (examples/weldcell.mod). Needs chromium (apt-get install -y chromium); not part of
# `make test`. Usage: bench/motion-screenshot.sh [OUTDIR]   (default _build/motion-demo)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-_build/motion-demo}
mkdir -p "$out"
dune build ./bench/motion_demo.exe ./bin/main.exe
./_build/default/bench/motion_demo.exe "$out"
./_build/default/bin/main.exe motion --io examples/weldcell.io examples/weldcell.mod \
  --svg "$out/weldcell-path.svg" --timeline "$out/weldcell-timeline.svg" >/dev/null
shot() { # FILE WIDTH HEIGHT
  chromium --headless --no-sandbox --disable-gpu --screenshot="$out/$1.png" \
    --window-size="$2,$3" "file://$(realpath "$out/$1.svg")" 2>/dev/null
}
shot path 1400 600
shot timeline 1000 480
shot weldcell-path 1400 600
shot weldcell-timeline 1000 480
echo "wrote $out/path.png, timeline.png, weldcell-path.png and weldcell-timeline.png"
