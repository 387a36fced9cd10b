#!/bin/bash
# shadowlab view under a virtual display (run through xvfb-run): a script
# changes the technique and a bias through the panel's own path (override
# lines); the screenshots match `shadowlab render` with the same settings
# pixel for pixel right of the panel, and differ from each other where the
# bias moves the shadows. The viewer's comparison (traced on a worker
# thread) equals `shadowlab compare`'s. Then resizing, minimising, a broken
# scene file and its repair: no crash.
set -u
tool=$1; src=$2; diff=$3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; cd "$work"
panel=340  # ViewerPanel.cpp: kPanelWidth
cat > steps.txt <<'SCRIPT'
set lights[0].shadow.technique="map"
wait 2
screenshot a.png
set lights[0].shadow.map.constantBias=0.1
wait 2
screenshot b.png
save saved.json
uploads
set camera.fovY=50
uploads
quit
SCRIPT
"$tool" view "$src/scenes/two-boxes-sun.json" --width 960 --height 540 --script steps.txt >out.txt 2>err.txt || { echo "view failed: $(cat err.txt)"; exit 1; }
[[ -s a.png && -s b.png ]] || { echo "no screenshots: $(cat out.txt err.txt)"; exit 1; }
"$tool" render "$src/scenes/two-boxes-sun.json" --width 960 --height 540 --set 'lights[0].shadow.technique="map"' -o ra.png >/dev/null || exit 1
"$tool" render "$src/scenes/two-boxes-sun.json" --width 960 --height 540 --set 'lights[0].shadow.technique="map"' --set lights[0].shadow.map.constantBias=0.1 -o rb.png >/dev/null || exit 1
[[ $("$diff" a.png ra.png --from-x $panel) == 0 ]] || { echo "view and render differ right of the panel: $("$diff" a.png ra.png --from-x $panel) pixels"; exit 1; }
[[ $("$diff" b.png rb.png --from-x $panel) == 0 ]] || { echo "view and render differ with the bias: $("$diff" b.png rb.png --from-x $panel) pixels"; exit 1; }
# The two light settings were applied to the lights alone: the scene was read
# whole and uploaded once, at the start; a camera setting reads it again.
[[ "$(grep '^uploads:' out.txt | tr '\n' ' ')" == "uploads: 1 uploads: 2 " ]] || { echo "scene uploads: $(cat out.txt)"; exit 1; }
changed=$("$diff" a.png b.png --from-x $panel)
(( changed > 100 )) || { echo "a constant bias of 0.1 moved only $changed pixels"; exit 1; }
# "save" wrote the scene with both settings in it: it renders as render with the two --set lines.
"$tool" render saved.json --width 960 --height 540 -o rs.png >/dev/null || { echo "the saved scene does not load"; exit 1; }
cmp -s rs.png rb.png || { echo "the saved scene renders differently from the --set lines"; exit 1; }
# The comparison traced off the window's thread: the script waits for it,
# and its error image is the command line's, pixel for pixel, at the window's size.
mkdir cmp
printf 'set lights[0].shadow.technique="map"\ncompare cmp\nshow-density\nshow-light\nwait 6\nscreenshot e.png\nquit\n' > steps4.txt
"$tool" view "$src/scenes/spot-objects.json" --width 640 --height 360 --script steps4.txt >out4.txt 2>err.txt || { echo "compare in the viewer: $(cat err.txt)"; exit 1; }
grep -q "^compare: light 0 " out4.txt && [[ -s cmp/error-0.png && -s e.png ]] || { echo "no comparison from the viewer: $(cat out4.txt err.txt)"; exit 1; }
"$tool" compare "$src/scenes/spot-objects.json" --width 640 --height 360 --set 'lights[0].shadow.technique="map"' -o cli >/dev/null || exit 1
cmp -s cmp/error-0.png cli/error-0.png || { echo "the viewer's error image differs from compare's"; exit 1; }
# A `set` then `compare` measures the changed frame (issue 59: the
# comparison started from the frame drawn before the set): technique none
# shadows nothing, its error image is compare's with technique none.
mkdir cmp3
printf 'wait 2\nset lights[0].shadow.technique="none"\ncompare cmp3\nquit\n' > steps6.txt
"$tool" view "$src/scenes/spot-objects.json" --width 320 --height 180 --script steps6.txt >out6.txt 2>err.txt || { echo "set then compare in the viewer: $(cat err.txt)"; exit 1; }
"$tool" compare "$src/scenes/spot-objects.json" --width 320 --height 180 --set 'lights[0].shadow.technique="none"' -o cli3 >/dev/null || exit 1
cmp -s cmp3/error-0.png cli3/error-0.png || { echo "set then compare: the viewer measured another frame than the one the set made: $(cat out6.txt)"; exit 1; }
# The debug views turn off again (issue 59: a script could turn them on
# only): after show-density, show-light and their hide-, the frame right
# of the panel is render's again.
printf 'set lights[0].shadow.technique="map"\nshow-density\nshow-light\nwait 2\nscreenshot on.png\nhide-density\nhide-light\nwait 2\nscreenshot off.png\nquit\n' > steps7.txt
"$tool" view "$src/scenes/spot-objects.json" --width 640 --height 360 --script steps7.txt >out7.txt 2>err.txt || { echo "hide in the viewer: $(cat err.txt)"; exit 1; }
"$tool" render "$src/scenes/spot-objects.json" --width 640 --height 360 --set 'lights[0].shadow.technique="map"' -o re0.png >/dev/null || exit 1
(( $("$diff" on.png re0.png --from-x $panel) > 10000 )) || { echo "show-density and show-light changed too little"; exit 1; }
[[ $("$diff" off.png re0.png --from-x $panel) == 0 ]] || { echo "after hide-density and hide-light the view differs from render: $("$diff" off.png re0.png --from-x $panel) pixels"; exit 1; }
# --frames ends the run only once the comparison the script asked for is written.
mkdir cmp2
printf 'compare cmp2\n' > steps5.txt
"$tool" view "$src/scenes/spot-objects.json" --width 320 --height 180 --frames 1 --script steps5.txt >out5.txt 2>err.txt || { echo "compare before --frames: $(cat err.txt)"; exit 1; }
[[ -s cmp2/error-0.png ]] || { echo "--frames 1 dropped the script's comparison: $(cat out5.txt err.txt)"; exit 1; }
# The texel-density tint and the frustums change the picture right of the panel.
"$tool" render "$src/scenes/spot-objects.json" --width 640 --height 360 --set 'lights[0].shadow.technique="map"' -o re.png >/dev/null || exit 1
tinted=$("$diff" e.png re.png --from-x $panel)
(( tinted > 10000 )) || { echo "the texel-density tint changed only $tinted pixels"; exit 1; }
# The panel a newcomer can read (issue 62), at 1280x720: the shadow-map
# window lies on screen; a point light's cascade options are disabled (a
# sun's are not); a preset's values are marked; the panel collapses and the
# maps window stays. `layout FILE` writes what the frame showed.
printf 'set lights[0].shadow.map.preset="lecture"\nshow-maps\nwait 3\nlayout point.json\nscreenshot panel.png\nquit\n' > steps8.txt
"$tool" view "$src/scenes/learnopengl-point-shadows.json" --width 1280 --height 720 --script steps8.txt >out8.txt 2>err.txt || { echo "layout in the viewer: $(cat err.txt)"; exit 1; }
printf 'show-maps\nwait 3\nlayout sun.json\ncollapse-panel\nwait 2\nlayout collapsed.json\nquit\n' > steps9.txt
"$tool" view "$src/scenes/cascades-field.json" --width 1280 --height 720 --script steps9.txt >out9.txt 2>err.txt || { echo "layout in the viewer: $(cat err.txt)"; exit 1; }
python3 - point.json sun.json collapsed.json <<'CHECK' || exit 1
import json, sys
point, sun, collapsed = (json.load(open(f)) for f in sys.argv[1:4])
def window(layout, name):
    w = [w for w in layout["windows"] if w["name"] == name]
    assert w, f"no window {name!r}: {layout['windows']}"
    return w[0]
def option(layout, key):
    o = [o for o in layout["options"] if o["light"] == 0 and o["key"] == key]
    assert o, f"no option {key!r} shown for light 0"
    return o[0]
for layout in (point, sun):
    m = window(layout, "shadow maps")
    assert m["x"] >= 0 and m["y"] >= 0 and m["x"] + m["width"] <= 1280 and m["y"] + m["height"] <= 720, f"the maps window is off screen: {m}"
    # 200 x 300 px: room for a map image a few hundred texels across and its name (the window asks for 300 x the frame's height).
    assert m["width"] >= 200 and m["height"] >= 300, f"the maps window is too small to see a map: {m}"
for key in ("cascades", "cascadeLambda", "stabilize", "warp", "representation"):
    o = option(point, key)
    assert not o["enabled"] and o["unused"], f"{key} is enabled for a point light: {o}"
for key in ("faceCulling", "diskRadius"):
    assert option(point, key)["enabled"], f"{key} is disabled for a point light's cube"
assert option(sun, "cascades")["enabled"] and option(sun, "cascadeLambda")["enabled"], "a sun's cascade options are disabled"
assert not option(sun, "faceCulling")["enabled"], "faceCulling is enabled for a sun"
marked = [o["key"] for o in point["options"] if o["light"] == 0 and o["preset"]]
assert "filter" in marked and "constantBias" in marked, f"preset lecture's values on a cube not marked: {marked}"
assert not any(o["preset"] for o in sun["options"]), "options marked as a preset's without a preset"
panel, folded = window(sun, "shadowlab"), window(collapsed, "shadowlab")
# Open, the panel spans the 720-px frame; collapsed, only its title bar (one
# line of ImGui's default 13-px font, about 19 px) is left: under 60 px either way.
assert panel["height"] >= 600 and folded["height"] < 60, f"the panel did not collapse: {panel} then {folded}"
assert not collapsed["options"], "a collapsed panel still lists options"
window(collapsed, "shadow maps")
print("layout: maps window", window(point, "shadow maps"), "; preset keys", marked)
CHECK
# Resize, minimise, restore.
printf 'show-maps\nshow-light\ncompare\nwait 12\nresize 500 300\nwait 3\nminimize\nwait 3\nrestore\nwait 12\nscreenshot c.png\nquit\n' > steps2.txt
"$tool" view "$src/scenes/torus-floating.json" --width 640 --height 360 --set 'lights[0].shadow.technique="map"' --set lights[0].shadow.map.size=256 --script steps2.txt >/dev/null 2>err.txt || { echo "resize/minimise: $(cat err.txt)"; exit 1; }
[[ -s c.png ]] || { echo "no screenshot after resize"; exit 1; }
# A broken scene file while the viewer runs, then repaired: no crash, the error shown, the scene back.
cp "$src/scenes/torus-floating.json" live.json
printf 'wait 150\nscreenshot d.png\nquit\n' > steps3.txt
"$tool" view live.json --width 640 --height 360 --script steps3.txt >/dev/null 2>err.txt &
viewer=$!
sleep 1; echo '{ "nodes": [ broken' > live.json
sleep 1; cp "$src/scenes/torus-floating.json" live.json; touch live.json
wait $viewer || { echo "the viewer died on a broken scene file: $(cat err.txt)"; exit 1; }
[[ -s d.png ]] || { echo "no screenshot after the repair"; exit 1; }
# An error raised once the scene is drawn names where its value came from, as render's does.
if "$tool" view --frames 2 --set lights[0].shadow.technique=planar --set lights[0].shadow.planar.receivers=nope >/dev/null 2>err.txt; then echo "a missing planar receiver accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q -- "--set lights\[0\].shadow.planar.receivers=nope: lights\[0\].shadow.planar.receivers: no node named 'nope'" err.txt || { echo "viewer error without its source: $(cat err.txt)"; exit 1; }
# A script's set that a later frame finds wrong (the maps past their budget) is named by its line.
printf '{"lights":[{"type":"directional","shadow":{"technique":"map","map":{"size":8192,"cascades":2}}}],"nodes":[{"shape":{"type":"box"}}]}' > fits.json
printf 'set lights[0].shadow.map.cascades=8\nwait 2\nquit\n' > budget.txt
if "$tool" view fits.json --width 320 --height 180 --script budget.txt >/dev/null 2>err.txt; then echo "a script's set past the budget accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "budget.txt:1: set lights\[0\].shadow.map.cascades=8: lights\[0\].shadow.map: the shadow maps" err.txt || { echo "the script's set not named: $(cat err.txt)"; exit 1; }
# SIGTERM and SIGINT stop the viewer at its next frame: one line naming
# the signal, exit 1, and the script's screenshot taken before it not kept.
printf 'screenshot early.png\nwait 100000\n' > long.txt
# The waits are long for a loaded machine or a sanitizer build, where the
# viewer took over 30 s to draw its first frame; a quick one breaks out at once.
for sig in TERM INT; do
  timeout 300 "$tool" view --width 320 --height 180 --script long.txt >/dev/null 2>err.txt &
  viewer=$!
  for _ in $(seq 2400); do [[ -n "$(pgrep -P "$viewer" shadowlab)" ]] && [[ -n "$(compgen -G 'early.png.pending-*')" ]] && break; sleep 0.1; done
  pkill -"$sig" -P "$viewer" shadowlab
  wait "$viewer"
  code=$?
  (( code == 1 )) && [[ $(wc -l <err.txt) -eq 1 ]] && grep -q "interrupted (SIG$sig)" err.txt || { echo "the viewer on SIG$sig: exit $code, $(cat err.txt)"; exit 1; }
  [[ ! -e early.png && -z "$(compgen -G 'early.png.pending-*')" ]] || { echo "the viewer on SIG$sig left its screenshot"; exit 1; }
done
# A bad script is a one-line error before any window.
printf 'jump 3\n' > bad.txt
if "$tool" view --script bad.txt 2>err.txt; then echo "bad script accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "bad.txt:1: unknown action 'jump'" err.txt || { echo "bad script: $(cat err.txt)"; exit 1; }
# Scripts are regular files of at most 1 MiB: a FIFO blocked the viewer, /dev/zero grew without end.
mkfifo script.fifo
for bad in script.fifo /dev/zero .; do
  if timeout 20 "$tool" view --script "$bad" 2>err.txt; then echo "script $bad accepted"; exit 1; fi
  [[ $(wc -l <err.txt) -eq 1 ]] && grep -q -- "--script $bad: not a regular file" err.txt || { echo "script $bad: $(cat err.txt)"; exit 1; }
done
head -c 2000000 /dev/zero | tr '\0' '#' > big.txt
if "$tool" view --script big.txt 2>err.txt; then echo "2 MB script accepted"; exit 1; fi
grep -q -- "--script big.txt: 2000000 bytes, more than the limit of 1 MiB" err.txt || { echo "big script: $(cat err.txt)"; exit 1; }
# A script ending in "compare DIR" finishes the comparison it started (it quit
# with nothing traced); DIR must exist before anything is traced.
mkdir -p endcmp
printf 'wait 1\ncompare endcmp\n' > endcompare.txt
"$tool" view "$src/scenes/two-boxes-sun.json" --width 320 --height 180 --script endcompare.txt >out5.txt 2>err.txt || { echo "script ending in compare: $(cat err.txt)"; exit 1; }
[[ -s endcmp/error-0.png ]] && grep -q "compare: light 0" out5.txt || { echo "script ending in compare traced nothing: $(cat out5.txt err.txt)"; exit 1; }
printf 'compare nodir\n' > nodir.txt
if "$tool" view --script nodir.txt 2>err.txt; then echo "compare into a missing directory accepted"; exit 1; fi
grep -q "nodir.txt:1: compare nodir: not a directory" err.txt || { echo "compare nodir: $(cat err.txt)"; exit 1; }
# Screenshots are PNG files, as render -o's: another extension is refused up front, nothing written.
printf 'wait 1\nscreenshot shot.jpg\nquit\n' > jpg.txt
if "$tool" view --script jpg.txt 2>err.txt; then echo "screenshot .jpg accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 && ! -e shot.jpg ]] && grep -q "jpg.txt:2: screenshot shot.jpg: expected a .png file name" err.txt || { echo "screenshot .jpg: $(cat err.txt)"; exit 1; }
if "$tool" view --frames 1 --screenshot shot.jpg 2>err.txt; then echo "--screenshot .jpg accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 && ! -e shot.jpg ]] && grep -q -- "--screenshot shot.jpg: expected a .png file name" err.txt || { echo "--screenshot .jpg: $(cat err.txt)"; exit 1; }
# A screenshot or a compare's image that cannot be written names the
# script's line (/proc takes no new files; a directory of the compare
# image's name is in the way).
mkdir -p cmpdir/error-0.png
printf 'wait 1\nscreenshot /proc/a.png\nquit\n' > shotdir.txt
if "$tool" view --script shotdir.txt 2>err.txt; then echo "screenshot onto a directory accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "shotdir.txt:2: screenshot: /proc/a.png: cannot write" err.txt || { echo "screenshot onto a directory: $(cat err.txt)"; exit 1; }
printf 'compare cmpdir\nquit\n' > cmpdir.txt
if "$tool" view --width 96 --height 64 --script cmpdir.txt >/dev/null 2>err.txt; then echo "compare onto a directory accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "cmpdir.txt:1: compare cmpdir: cmpdir/error-0.png: cannot write" err.txt || { echo "compare onto a directory: $(cat err.txt)"; exit 1; }
# A script that fails at a later line leaves none of its screenshots (as a
# failed render leaves no frame): the screenshot of line 2 is gone when line
# 3 fails.
printf 'wait 1\nscreenshot early.png\nscreenshot /proc/b.png\nquit\n' > later.txt
if "$tool" view --script later.txt >later-out.txt 2>err.txt; then echo "a failing script exited 0"; exit 1; fi
[[ ! -e early.png && -z $(ls -A | grep pending) ]] || { echo "a failing script left $(ls -A | grep -E 'early|pending')"; exit 1; }
# ... and did not name it as written (issue 59: it printed early.png, then removed it).
! grep -q "early.png" later-out.txt || { echo "a failing script named a screenshot it did not keep: $(cat later-out.txt)"; exit 1; }
# Nor its compare's error images.
mkdir -p latecmp
printf 'compare latecmp
wait 1
screenshot /proc/c.png
quit
' > latecmp.txt
if "$tool" view "$src/scenes/two-boxes-sun.json" --width 160 --height 90 --script latecmp.txt >/dev/null 2>err.txt; then echo "a failing script after compare exited 0"; exit 1; fi
[[ -z $(ls -A latecmp) ]] || { echo "a failing script left its compare's images: $(ls -A latecmp)"; exit 1; }
# "save" into a directory's name, or into a directory that is not there:
# refused before the first frame, in one line, nothing written.
for target in . nowhere/x.json; do
  printf 'wait 1\nsave %s\nquit\n' "$target" > save.txt
  if "$tool" view --script save.txt 2>err.txt; then echo "save $target accepted"; exit 1; fi
  [[ $(wc -l <err.txt) -eq 1 ]] && grep -q "save.txt:2: save $target: " err.txt || { echo "save $target: $(cat err.txt)"; exit 1; }
done
[[ -z $(ls -A | grep partial) ]] || { echo "save left $(ls -A | grep partial)"; exit 1; }
# A resize holds the script until a frame of that size is drawn: the next
# line's screenshot has the new size (it took the old one), and a resize
# followed by quit still draws that frame (below: it exited 0 without it).
printf 'resize 400 300\nscreenshot resized.png\nquit\n' > resize.txt
"$tool" view --width 320 --height 240 --script resize.txt >/dev/null 2>err.txt || { echo "resize then screenshot: $(cat err.txt)"; exit 1; }
size=$(python3 -c "import struct; d=open('resized.png','rb').read(24); print(*struct.unpack('>II', d[16:24]))")
[[ "$size" == "400 300" ]] || { echo "the screenshot after resize 400 300 is $size"; exit 1; }
# A resize under the memory guard but past what the process may allocate
# (ulimit -v 8 GB; a 14000^2 frame needs about 12 GB): GL_OUT_OF_MEMORY said
# in one line naming the script's line, no GL debug lines before it.
# An AddressSanitizer build reserves terabytes of shadow memory at start,
# which no address-space limit admits: the check is left out there.
if ldd "$tool" | grep -q libasan; then
  echo "resize past the process's memory: skipped, the tool is built with AddressSanitizer (ulimit -v cannot hold its shadow memory)"
else
  printf 'resize 14000 14000\nquit\n' > huge.txt
  if (ulimit -v 8000000; "$tool" view --script huge.txt 2>err.txt); then echo "resize past the process's memory accepted"; exit 1; fi
  [[ $(wc -l <err.txt) -eq 1 ]] && grep -q "huge.txt:1: resize 14000 14000: the GPU ran out of memory making the .* (GL_OUT_OF_MEMORY)" err.txt || { echo "resize past memory: $(cat err.txt)"; exit 1; }
fi
echo ok
