#!/usr/bin/env bash
# The README's elasticity picture: the real ParaView GUI (/usr/bin/paraview,
# Debian's 5.11) in a virtual X server (xvfb-run), after it has run
# Scripts/solution_gui_screenshot.py on a solution of solve_elasticity.py:
# warped by Displacement, clipped at the centre, coloured by VonMises. The
# whole X screen (the application window: menus, toolbars, Pipeline Browser,
# Properties, the render view) is captured with Pillow's ImageGrab over XCB
# (no ImageMagick or xwd needed), quantized to 256 colours, and then this
# script ends paraview (which it started; `timeout` bounds it in any case).
#
#   bash Scripts/solve_demo.sh            # makes out/ball_solution.pvtu
#   bash Scripts/solution_gui_screenshot.sh [SOLUTION.pvtu] [OUT.png]
#
# Defaults: out/ball_solution.pvtu, Scripts/examples/elastic_ball_gui.png.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${PTM_IN_XVFB:-}" ]; then
  # -a: a free display number; the screen is the size of the picture
  exec env PTM_IN_XVFB=1 xvfb-run -a -s "-screen 0 1600x1000x24 -nolisten tcp" bash "$0" "$@"
fi
solution=$(realpath "${1:-out/ball_solution.pvtu}")
out=$(realpath -m "${2:-Scripts/examples/elastic_ball_gui.png}")
[ -f "$solution" ] || { echo "solution_gui_screenshot: no $solution (run Scripts/solve_demo.sh)" >&2; exit 1; }

work=$(mktemp -d)
gui=""
cleanup() {
  [ -n "$gui" ] && kill "$gui" 2>/dev/null && wait "$gui" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# a fresh ParaView profile, so no user settings get in the way, without the
# welcome dialog (Qt settings of paraview 5.11.0)
export HOME="$work/home"
mkdir -p "$HOME/.config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\n' > "$HOME/.config/ParaView/ParaView5.11.0.ini"

# -qwindowgeometry (a Qt option) fills the screen: there is no window manager
PTM_SOLUTION="$solution" PTM_READY="$work/ready" PYTHONPATH="$PWD/Scripts${PYTHONPATH:+:$PYTHONPATH}" \
  timeout 300 paraview -qwindowgeometry 1600x1000+0+0 \
  --script="$PWD/Scripts/solution_gui_screenshot.py" > "$work/paraview.log" 2>&1 &
gui=$!
for _ in $(seq 480); do
  [ -s "$work/ready" ] && break
  kill -0 "$gui" 2>/dev/null || { cat "$work/paraview.log"; echo "solution_gui_screenshot: paraview exited" >&2; exit 1; }
  sleep 0.5
done
[ -s "$work/ready" ] || { cat "$work/paraview.log"; echo "solution_gui_screenshot: the script did not finish" >&2; exit 1; }
sleep 5 # the script has returned: let the GUI update its panels and render
/usr/bin/python3 - "$out" <<'EOF'
import os, sys
from PIL import Image, ImageGrab
shot = ImageGrab.grab(xdisplay=os.environ["DISPLAY"]).convert("RGB")
shot.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(sys.argv[1], optimize=True)
print(f"solution_gui_screenshot: wrote {sys.argv[1]} ({shot.size[0]}x{shot.size[1]}, {os.path.getsize(sys.argv[1])} bytes)")
EOF
grep "solution_gui_screenshot:" "$work/paraview.log" || true
