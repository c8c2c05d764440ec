#!/usr/bin/env bash
# Regenerates Scripts/examples/paraview_gui.png, the screenshot in README.md:
# the real ParaView GUI (Debian's paraview 5.11, `paraview --script=...`) in a
# virtual X server, after it has run the trace example mesh_in_paraview.py
# (the four filters on Data/bracket.stl, K = 4, a crinkle clip coloured by
# SubdomainId). The whole screen is captured with ImageMagick's `import`.
#
#   bash Scripts/examples/gui_screenshot.sh [OUT.png]
#
# Needs the build tree's plugin (bash Scripts/test.sh or a manual build) and
# installs Xvfb, x11-apps, imagemagick and xdotool if they are missing. Not
# part of the test suite (the example itself is tested under pvbatch).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$(realpath -m "${1:-Scripts/examples/paraview_gui.png}")
plugin=${PTM_PLUGIN:-$PWD/build/lib/paraview-plugins/ParallelTetMesher/ParallelTetMesher.so}
[ -f "$plugin" ] || { echo "gui_screenshot: no plugin at $plugin; build first" >&2; exit 1; }

missing=()
for p in xvfb x11-apps imagemagick xdotool; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

work=$(mktemp -d)
cleanup() {
  [ -n "${gui:-}" ] && kill "$gui" 2>/dev/null || true
  [ -n "${xvfb:-}" ] && kill "$xvfb" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# Xvfb picks a free display and writes its number once it listens
exec 3> "$work/display"
Xvfb -displayfd 3 -screen 0 1600x1000x24 -noreset -nolisten tcp > /dev/null 2>&1 &
xvfb=$!
exec 3>&-
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(cat "$work/display")"

# a fresh ParaView profile, so no user settings get in the way, without
# the welcome dialog (Qt settings of paraview 5.11.0)
export HOME="$work/home"
mkdir -p "$HOME/.config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\n' > "$HOME/.config/ParaView/ParaView5.11.0.ini"
PTM_PLUGIN="$plugin" PTM_SCREENSHOT="$work/view.png" \
  paraview --script="$PWD/Scripts/examples/mesh_in_paraview.py" > "$work/paraview.log" 2>&1 &
gui=$!

# the script ends by saving the view; then the GUI is ready
for _ in $(seq 600); do
  [ -s "$work/view.png" ] && break
  kill -0 "$gui" 2>/dev/null || { cat "$work/paraview.log"; echo "gui_screenshot: paraview exited" >&2; exit 1; }
  sleep 0.5
done
[ -s "$work/view.png" ] || { cat "$work/paraview.log"; echo "gui_screenshot: the script did not finish" >&2; exit 1; }
window=$(xdotool search --sync --onlyvisible --name "ParaView" | head -n 1)
xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1000
sleep 5 # let the GUI lay itself out and render again at the new size
import -window root "$out"
echo "gui_screenshot: wrote $out"
