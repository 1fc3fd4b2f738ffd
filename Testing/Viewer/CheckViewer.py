#!/usr/bin/env python3
"""Runs tyndall-viewer and checks it (the tests in Testing/Viewer/CMakeLists.txt).

  CheckViewer.py scripted --viewer EXE --script FILE --baseline PNG --output PNG
                          [--size W H] [--min-psnr DB]
      Runs the viewer on a script in a real GLFW window (the test runs under
      xvfb-run), then checks that it exited with 0, that no navigation frame
      (orbit, pan, zoom, or a drag that is not a light drag) rebuilt the
      transmittance maps while a light move did, and that its screenshot
      matches the baseline with a PSNR floor.

  CheckViewer.py sequence --viewer EXE --render EXE --input PATTERN --first N --last N
                          --output-dir DIR [--size W H] [--min-psnr DB]
      A time series (--sequence): the viewer steps through the frames with
      the arrow keys (looping both ways) and plays them with Space; each
      frame it shows must match tyndall-render's picture of that frame, each
      frame played must be the next one with the maps rebuilt once, and a
      frame that cannot be read (LAST + 1, which must not exist) is skipped
      with a warning.

  CheckViewer.py slice --viewer EXE --render EXE --input FILE --output-dir DIR
                       [--size W H] [--min-psnr DB]
      The slice blend mode: the viewer's plane at start and after five
      presses of ']' must match tyndall-render's pictures at --slice-offset
      0 and 0.1, and the two must differ.

  CheckViewer.py failures --viewer EXE
      Checks that the viewer fails cleanly (non-zero exit, a message, no
      crash) without an X display, with a bad script and with a bad input.

Needs /usr/bin/python3 with Debian's VTK bindings (vtkPNGReader); no numpy.
"""
import argparse
import math
import os
import subprocess
import sys

# Commands that only move the camera: they must never rebuild a map.
NAVIGATION = ("orbit", "pan", "zoom")

# The transmittance cache of the modes that compare the viewer with
# tyndall-render, both given it: 32 texels on the box's longest side instead
# of the default 256, which llvmpipe takes about 2 s to build for each map
# build (the CLI tests do the same: Testing/CLI/CMakeLists.txt).
CACHE = ["--cache-size", "32"]


def run(command, env=None, timeout=600):
    print("running:", " ".join(command), flush=True)
    try:
        result = subprocess.run(command, env=env, timeout=timeout,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                universal_newlines=True)
    except subprocess.TimeoutExpired:
        print("FAIL: the viewer did not finish within %d s" % timeout)
        sys.exit(1)
    sys.stdout.write(result.stdout)
    sys.stdout.write("--- stderr ---\n" + result.stderr + "--------------\n")
    sys.stdout.flush()
    return result


def read_png(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        return None
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    dims = image.GetDimensions()
    components = scalars.GetNumberOfComponents()
    try:
        data = bytes(memoryview(scalars))
    except TypeError:
        data = bytes(int(scalars.GetValue(i)) for i in range(scalars.GetNumberOfValues()))
    return dims[0], dims[1], components, data


def psnr(a, b):
    """PSNR in dB over the first three components; None when sizes differ."""
    (wa, ha, ca, da), (wb, hb, cb, db) = a, b
    if (wa, ha) != (wb, hb) or ca < 3 or cb < 3:
        return None
    total = 0
    for c in range(3):
        for x, y in zip(da[c::ca], db[c::cb]):
            total += (x - y) * (x - y)
    mse = total / (3.0 * wa * ha)
    return math.inf if mse == 0 else 10.0 * math.log10(255.0 * 255.0 / mse)


def parse_frames(stdout):
    """The viewer's per-frame lines: frame N render-ms T map-builds B ... path-samples P
    command TEXT."""
    frames = []
    for line in stdout.splitlines():
        words = line.split()
        if len(words) < 12 or words[0] != "frame" or "command" not in words:
            continue
        at = words.index("command")
        samples = words.index("path-samples") if "path-samples" in words[:at] else -1
        frames.append({
            "number": int(words[1]),
            "ms": float(words[3]),
            "builds": int(words[5]),
            "paths": int(words[samples + 1]) if samples >= 0 else None,
            "command": words[at + 1:],
        })
    return frames


def is_navigation(command):
    if not command:
        return False
    if command[0] in NAVIGATION:
        return True
    # A drag is navigation unless it moves the light (ctrl or L held).
    return command[0] == "drag" and "+ctrl" not in command[1] and "+l" not in command[1]


def is_light(command):
    return bool(command) and (command[0] == "light" or (
        command[0] == "drag" and ("+ctrl" in command[1] or "+l" in command[1])))


def scripted(args):
    if os.path.exists(args.output):
        os.remove(args.output)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    result = run([args.viewer, "--size", str(args.size[0]), str(args.size[1]),
                  "--script", args.script,
                  "--events", "screenshot %s; quit" % args.output])
    failures = []
    if result.returncode != 0:
        failures.append("the viewer exited with %d" % result.returncode)

    frames = parse_frames(result.stdout)
    if not frames:
        failures.append("the viewer printed no frame lines")
    navigation, rebuilt_by_light = [], 0
    for previous, frame in zip(frames, frames[1:]):
        grew = frame["builds"] - previous["builds"]
        if is_navigation(frame["command"]):
            navigation.append(frame)
            if grew:
                failures.append("frame %d ('%s') rebuilt the maps %d time(s): camera moves "
                                "must reuse them" % (frame["number"],
                                                     " ".join(frame["command"]), grew))
        elif is_light(frame["command"]) and grew > 0:
            rebuilt_by_light += 1
    if len(navigation) < 3:
        failures.append("the script has %d navigation frames after the first; it needs 3 or "
                        "more for the map-reuse check" % len(navigation))
    if frames and rebuilt_by_light == 0:
        failures.append("no light move rebuilt the maps: the build count is not live")
    if navigation:
        times = sorted(f["ms"] for f in navigation)
        print("navigation frames: %d, render ms median %.1f, min %.1f, max %.1f, map builds "
              "%d at the last" % (len(times), times[len(times) // 2], times[0], times[-1],
                                     navigation[-1]["builds"]))

    if not os.path.exists(args.output):
        failures.append("no screenshot at %s" % args.output)
    elif not os.path.exists(args.baseline):
        failures.append("ImageNotFound: no baseline %s; review the candidate %s and copy it "
                        "there (Documentation/testing.md)" % (args.baseline, args.output))
    else:
        candidate, baseline = read_png(args.output), read_png(args.baseline)
        if candidate is None or baseline is None:
            failures.append("cannot read %s or %s" % (args.output, args.baseline))
        else:
            value = psnr(candidate, baseline)
            if value is None:
                failures.append("the screenshot is %dx%d, the baseline %dx%d" % (
                    candidate[0], candidate[1], baseline[0], baseline[1]))
            else:
                print('<DartMeasurement name="PSNR" type="numeric/double">%s'
                      '</DartMeasurement>' % value)
                print("PSNR against the baseline: %s dB (floor %s dB)" % (value, args.min_psnr))
                if not value >= args.min_psnr:
                    failures.append("Failed Image Test: PSNR %s dB is below %s dB; the candidate "
                                    "is %s" % (value, args.min_psnr, args.output))
    return failures


def sequence_mode(args):
    failures = []
    os.makedirs(args.output_dir, exist_ok=True)
    size = [str(args.size[0]), str(args.size[1])]
    first, last = args.first, args.last
    frames = list(range(first, last + 1))
    out = lambda name: os.path.join(args.output_dir, name)
    for f in frames:
        for name in ("render_%d.png" % f, "viewer_%d.png" % f):
            if os.path.exists(out(name)):
                os.remove(out(name))
    result = run([args.render, "-q", "-s"] + size + CACHE + ["--sequence", str(first), str(last),
                  "-o", out("render_%d.png"), args.input])
    if result.returncode != 0:
        return ["tyndall-render exited with %d" % result.returncode]

    # Step forward through every frame and once more (back to FIRST), back
    # once (to LAST), then play len(frames) + 1 frames and pause.
    events = ["hud off", "screenshot " + out("viewer_%d.png" % first)]
    for f in frames[1:]:
        events += ["key right", "screenshot " + out("viewer_%d.png" % f)]
    events += ["key right", "screenshot " + out("viewer_wrapped.png"),
               "key left", "screenshot " + out("viewer_back.png"),
               "key space", "frames %d" % (len(frames) + 1), "key space", "quit"]
    result = run([args.viewer, "-s"] + size + CACHE + ["--sequence", str(first), str(last),
                  args.input, "--events", "; ".join(events)])
    if result.returncode != 0:
        failures.append("the viewer exited with %d" % result.returncode)
    pairs = [("viewer_%d.png" % f, "render_%d.png" % f) for f in frames]
    pairs += [("viewer_wrapped.png", "render_%d.png" % first),
              ("viewer_back.png", "render_%d.png" % last)]
    for shown, rendered in pairs:
        a, b = read_png(out(shown)), read_png(out(rendered))
        if a is None or b is None:
            failures.append("cannot read %s or %s" % (shown, rendered))
            continue
        value = psnr(a, b)
        print("%s against %s: %s dB (floor %s dB)" % (shown, rendered, value, args.min_psnr))
        if value is None or not value >= args.min_psnr:
            failures.append("%s is not tyndall-render's %s (%s dB)" % (shown, rendered, value))

    # Playing: each frame the next one (looping), the maps rebuilt once each.
    log = [line.split() for line in result.stdout.splitlines() if line.startswith("frame ")]
    played = [w for w in log if "command" in w and w[w.index("command") + 1] == "frames"]
    if len(played) != len(frames) + 1:
        failures.append("%d frames played, expected %d" % (len(played), len(frames) + 1))
    shown = [int(w[w.index("sequence-frame") + 1]) for w in played]
    builds = [int(w[w.index("map-builds") + 1]) for w in played]
    start = last  # playing starts where "key left" left it
    expected = [frames[(frames.index(start) + 1 + i) % len(frames)] for i in range(len(played))]
    print("played frames %s (expected %s), map builds %s" % (shown, expected, builds))
    if shown != expected:
        failures.append("played frames %s, expected %s" % (shown, expected))
    if any(b - a != 1 for a, b in zip(builds, builds[1:])):
        failures.append("map builds while playing %s: one per frame expected" % builds)

    # A frame that cannot be read: skipped with a warning, the one before shown.
    missing = last + 1
    result = run([args.viewer, "-s"] + size + CACHE + ["--sequence", str(first), str(missing),
                  args.input, "--events", "hud off; key left; quit"])
    log = [line.split() for line in result.stdout.splitlines() if line.startswith("frame ")]
    if result.returncode != 0:
        failures.append("with a missing frame the viewer exited with %d" % result.returncode)
    if "warning: skipped frame %d" % missing not in result.stderr:
        failures.append("no warning naming the missing frame %d" % missing)
    after = [int(w[w.index("sequence-frame") + 1]) for w in log if "left" in w]
    if after != [last]:
        failures.append("after the missing frame the viewer showed %s, expected [%d]" % (
            after, last))
    return failures


def key_against_render(args, common, values, key, presses, what):
    """The viewer's picture at start and after `presses` presses of `key`
    against tyndall-render's pictures with the options values["start"] and
    values["moved"] (both with the options `common`); the two must differ."""
    failures = []
    os.makedirs(args.output_dir, exist_ok=True)
    size = [str(args.size[0]), str(args.size[1])]
    common = CACHE + common
    out = lambda name: os.path.join(args.output_dir, name)
    for state in values:
        for name in ("render_%s.png" % state, "viewer_%s.png" % state):
            if os.path.exists(out(name)):
                os.remove(out(name))
    for state, options in values.items():
        result = run([args.render, "-q", "-s"] + size + common + options + ["-o",
                      out("render_%s.png" % state), args.input])
        if result.returncode != 0:
            return ["tyndall-render exited with %d" % result.returncode]
    events = ["hud off", "screenshot " + out("viewer_start.png")] + ["key " + key] * presses
    events += ["screenshot " + out("viewer_moved.png"), "quit"]
    result = run([args.viewer, "-s"] + size + common + [args.input, "--events",
                  "; ".join(events)])
    if result.returncode != 0:
        failures.append("the viewer exited with %d" % result.returncode)
    pictures = {}
    for name in ("viewer_start", "viewer_moved", "render_start", "render_moved"):
        pictures[name] = read_png(out(name + ".png"))
        if pictures[name] is None:
            return failures + ["cannot read %s.png" % name]
    for state in values:
        value = psnr(pictures["viewer_" + state], pictures["render_" + state])
        print("viewer_%s against render_%s: %s dB (floor %s dB)" % (state, state, value,
                                                                   args.min_psnr))
        if value is None or not value >= args.min_psnr:
            failures.append("the viewer's %s %s is not tyndall-render's (%s dB)" % (state, what,
                                                                                  value))
    value = psnr(pictures["viewer_start"], pictures["viewer_moved"])
    print("viewer_start against viewer_moved: %s dB (they must differ: below 35 dB)" % value)
    if value is None or value >= 35.0:
        failures.append("the key '%s' did not change the %s (%s dB)" % (key, what, value))
    return failures


def slice_mode(args):
    """The slice blend mode: the viewer's plane at start and after five
    presses of "]" (--slice-offset +0.02 each) against tyndall-render's
    pictures at --slice-offset 0 and 0.1."""
    return key_against_render(args, ["--blend-mode", "slice"],
                              {"start": ["--slice-offset", "0"],
                               "moved": ["--slice-offset", "0.1"]}, "]", 5, "slice")


def exposure_mode(args):
    """The display transform: the viewer's picture with the ACES curve and
    sRGB at start and after three presses of "e" (--exposure +0.5 each)
    against tyndall-render's pictures at --exposure 0 and 1.5."""
    return key_against_render(args, ["--tone-curve", "aces", "--srgb"],
                              {"start": ["--exposure", "0"], "moved": ["--exposure", "1.5"]},
                              "e", 3, "exposure")


def property_mode(args):
    """The kind of property: the viewer's shaded CT as a medium at start and
    after the key "k" (--vtk-property: a plain vtkVolumeProperty, VTK's
    gradient shading) against tyndall-render's pictures of both; then, with
    --vtk-property, a key that changes nothing of the property (j, the
    jitter) rebuilds no map (the plain copy is kept while its medium is
    unchanged), and a key of the medium's (a, the anisotropy) is ignored
    with a message."""
    failures = key_against_render(args, ["--shade"], {"start": [], "moved": ["--vtk-property"]},
                                  "k", 1, "property")
    events = "frames 2; key j; frames 2; key a; frames 2; quit"
    result = run([args.viewer, "-s", "32", "32"] + CACHE +
                 ["--shade", "--vtk-property", args.input, "--events", events])
    frames = parse_frames(result.stdout)
    builds = [f["builds"] for f in frames]
    print("map builds per frame with --vtk-property, j then a pressed: %s" % builds)
    if result.returncode != 0 or len(builds) < 6:
        failures.append("the viewer's run with --vtk-property failed (%d)" % result.returncode)
    elif builds[-1] != builds[1]:
        failures.append("the keys j and a rebuilt the maps of a plain property (%s)" % builds)
    if "sets the medium's --anisotropy" not in result.stderr:
        failures.append("the key a was not refused with --vtk-property")
    return failures


def paths_mode(args):
    """The path-traced mode while the user drags (--path-trace): still
    frames refine the picture (its samples per pixel grow), every frame of a
    drag is the map-based frame (0 samples: no frame while dragging is
    noisier than it), and the paths start again after the drag."""
    events = ["frames 4"] + ["drag left -8 3"] * 4 + ["frames 4", "quit"]
    result = run([args.viewer, "-s", "64", "64", "-r", "32", "--no-detail", "--path-trace",
                  "64", "--events", "; ".join(events)])
    if result.returncode != 0:
        return ["the viewer exited with %d" % result.returncode]
    frames = parse_frames(result.stdout)
    if len(frames) < 12 or any(f["paths"] is None for f in frames):
        return ["the viewer printed %d frame lines with path samples" % len(frames)]
    for f in frames:
        print("frame %d: %s samples per pixel (%s)" % (f["number"], f["paths"],
                                                      " ".join(f["command"]) or "-"))
    failures = []
    drags = [f for f in frames if f["command"][:1] == ["drag"]]
    still = [f for f in frames if f["command"][:1] == ["frames"]]
    if len(drags) != 4 or any(f["paths"] != 0 for f in drags):
        failures.append("a frame while dragging was not the map-based frame: %s"
                        % [f["paths"] for f in drags])
    before = [f["paths"] for f in still[:4]]
    after = [f["paths"] for f in still[4:8]]
    grows = lambda samples: all(b > a for a, b in zip(samples, samples[1:]))
    # The first frame is the map-based one; the paths refine the next.
    if len(before) != 4 or before[0] != 0 or not grows(before):
        failures.append("the still frames before the drag did not refine the picture: %s" % before)
    # The drag's last frame drew the map-based frame of the view they show:
    # the paths start again from their first frame.
    if len(after) != 4 or not grows(after) or not 0 < after[0] < before[-1]:
        failures.append("the paths did not start again after the drag: %s" % after)
    return failures


def denoise_mode(args):
    """The key "x" (--path-denoise) on a finished path-traced picture (8
    samples per pixel, after frames of 1, 2, 4 and 1: the mapper's ramp, the
    last trimmed): the picture shown denoised (it differs), then the mean
    again (the same picture), its samples kept throughout."""
    os.makedirs(args.output_dir, exist_ok=True)
    shots = [os.path.join(args.output_dir, "denoise_%s.png" % k) for k in ("off", "on", "again")]
    for shot in shots:
        if os.path.exists(shot):
            os.remove(shot)
    events = ["hud off", "frames 5", "screenshot " + shots[0], "key x", "screenshot " + shots[1],
              "key x", "screenshot " + shots[2], "quit"]
    result = run([args.viewer, "-s", "64", "64", "-r", "32", "--no-detail", "--path-trace", "8",
                  "--events", "; ".join(events)])
    if result.returncode != 0:
        return ["the viewer exited with %d" % result.returncode]
    frames = parse_frames(result.stdout)
    samples = [f["paths"] for f in frames]
    print("samples per pixel per frame: %s" % samples)
    failures = []
    if len(samples) < 8 or samples[:5] != [0, 1, 3, 7, 8] or any(n != 8 for n in samples[4:]):
        failures.append("the picture did not finish at 8 samples and keep them: %s" % samples)
    pictures = [read_png(shot) for shot in shots]
    if any(p is None for p in pictures):
        return failures + ["cannot read the screenshots"]
    toggled = psnr(pictures[0], pictures[1])
    again = psnr(pictures[0], pictures[2])
    print("the mean against the denoised picture: %s dB (below 40); against the mean again: %s dB"
          % (toggled, again))
    if toggled is None or toggled >= 40.0:
        failures.append("the key 'x' did not denoise the picture (%s dB)" % toggled)
    if again != math.inf:
        failures.append("the key 'x' again did not give the mean back (%s dB)" % again)
    return failures


def failures_mode(args):
    failures = []

    def expect_clean_failure(name, command, env, words, code=None):
        result = run(command, env=env, timeout=120)
        rc = result.returncode
        if rc == 0:
            failures.append("%s: the viewer exited with 0" % name)
        elif rc < 0 or rc >= 128:
            failures.append("%s: the viewer crashed (exit status %d)" % (name, rc))
        elif code is not None and rc != code:
            failures.append("%s: exit status %d, expected %d" % (name, rc, code))
        for word in words:
            if word not in result.stderr:
                failures.append("%s: no '%s' in the message" % (name, word))

    no_display = dict(os.environ)
    no_display.pop("DISPLAY", None)
    no_display.pop("WAYLAND_DISPLAY", None)
    expect_clean_failure("no display", [args.viewer, "--events", "quit"], no_display,
                         ["cannot initialise GLFW", "DISPLAY", "xvfb-run"], 1)
    expect_clean_failure("bad script", [args.viewer, "--events", "orbit 30 10; spin 3"],
                         None, ["command 2", "unknown command"], 2)
    expect_clean_failure("bad argument", [args.viewer, "--events", "zoom -1"],
                         None, ["zoom -1", "above 0"], 2)
    missing = os.path.join(os.path.dirname(os.path.abspath(__file__)), "no-such-volume.vti")
    expect_clean_failure("missing input", [args.viewer, missing, "--events", "quit"],
                         None, ["no-such-volume.vti"], 1)
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="mode", required=True)
    s = sub.add_parser("scripted")
    s.add_argument("--viewer", required=True)
    s.add_argument("--script", required=True)
    s.add_argument("--baseline", required=True)
    s.add_argument("--output", required=True)
    s.add_argument("--size", nargs=2, type=int, default=[256, 256])
    s.add_argument("--min-psnr", type=float, default=45.0)
    # The modes that compare the viewer with tyndall-render.
    q = sub.add_parser("sequence")
    c = sub.add_parser("slice")
    e = sub.add_parser("exposure")
    k = sub.add_parser("property")
    for p in (q, c, e, k):
        p.add_argument("--viewer", required=True)
        p.add_argument("--render", required=True)
        p.add_argument("--input", required=True)
        p.add_argument("--output-dir", required=True)
        p.add_argument("--size", nargs=2, type=int, default=[64, 64])
        p.add_argument("--min-psnr", type=float, default=45.0)
    q.add_argument("--first", type=int, required=True)
    q.add_argument("--last", type=int, required=True)
    f = sub.add_parser("failures")
    f.add_argument("--viewer", required=True)
    t = sub.add_parser("denoise")
    t.add_argument("--viewer", required=True)
    t.add_argument("--output-dir", required=True)
    t = sub.add_parser("paths")
    t.add_argument("--viewer", required=True)
    args = parser.parse_args()

    modes = {"scripted": scripted, "sequence": sequence_mode, "slice": slice_mode,
             "exposure": exposure_mode, "property": property_mode, "paths": paths_mode,
             "denoise": denoise_mode, "failures": failures_mode}
    failures = modes[args.mode](args)
    for message in failures:
        print("FAIL:", message)
    if failures:
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
