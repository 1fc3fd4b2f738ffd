#!/usr/bin/env bash
# Regenerates the pictures under Documentation/images from a build of
# Tyndall (default: ./build). Every picture in the documentation comes from
# here; run it after a change that alters them, look at them, commit them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TYNDALL_BUILD_DIR:-$root/build}"
images="$root/Documentation/images"
mkdir -p "$images"
run() { xvfb-run -a -s "-screen 0 1280x1024x24" "$@"; }

# The README's picture: the built-in default scene.
run "$build/bin/tyndall-render" -o "$images/tyndall-cloud.png" -s 384 384

# The method gallery: every method beside the CPU reference, cloud and dense.
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/method_gallery.py" "$images"

# Clipping respected by the light: GPU | CPU reference | CPU reference with
# the light ignoring the clipping (rendering-model.md).
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/clipping_pictures.py" "$images"

# Fire: black-body emission from a temperature array (rendering-model.md).
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/fire_picture.py" "$images"

# Coloured extinction: grey | blue densest | red densest (rendering-model.md).
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/chromatic_picture.py" "$images"

# Gradient shading of VTK's CT head beside VTK 9.1's, with and without shadows (mapper.md).
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/shaded_ct_picture.py" "$images"

# A shaded CT path traced: the map-based frame | the GPU's paths | the CPU tracer's; and lit
# by a sky alone: the map-based frame with the sky's mean | its 4 lights | the paths (rendering-model.md).
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/shaded_ct_paths_picture.py" "$images"

# A cloud's shadow on the ground (vtkVolumeShadowReceiverPass, rendering-model.md).
run "$build/bin/tyndall-render" --ground --camera-position 0 2.2 4.5 --focal-point 0 -0.7 0 \
  --light-direction -0.4 -1 -0.5 --light-intensity 0.8 -s 480 320 -o "$images/ground-shadow.png"

# The transfer-function presets, each on data it is meant for (needs
# ../shared/data; Documentation/io.md shows them).
data="$root/../shared/data"
if [ -d "$data" ]; then
  render="$build/bin/tyndall-render"
  run "$render" "$data/volumes/headsq/quarter.nhdr" --preset CT -s 192 192 -o "$images/preset-ct.png"
  run "$render" "$data/volumes/HeadMRVolume.mhd" --preset MR -s 192 192 -o "$images/preset-mr.png"
  run "$render" "$data/vdb/wdas_cloud_sixteenth.vdb" --preset Cloud -s 192 192 -o "$images/preset-cloud.png"
  run "$render" "$data/vdb/smoke.vdb" --preset Smoke -s 192 192 -o "$images/preset-smoke.png"
  run "$render" "$data/vdb/smoke.vdb" --preset DenseSmoke -s 192 192 -o "$images/preset-densesmoke.png"
fi

# Multiple scattering: path tracer | single scattering | octaves, for the dense
# medium, the thick cloud and the built-in cloud (rendering-model.md; a few
# minutes: the path tracer).
pictures="$(mktemp -d)"
run "$build/bin/BenchMultipleScattering" --size 96 --spp 1024 --no-gpu --pictures "$pictures"
# Bottom to top: the built-in cloud, the thick cloud, the dense medium.
/usr/bin/python3 "$root/Documentation/scripts/append_pictures.py" 1 2 \
  "$images/multiple-scattering.png" "$pictures"/multiple-scattering-{cloud,thick,dense}.png
rm -rf "$pictures"

# The path-traced picture's denoiser on the default scene: 16 samples per
# pixel as the paths' mean | the same 16 denoised | 1024, the mean
# (rendering-model.md, "Denoising"; about 7 minutes: the 1024 samples of the
# default scene's procedural detail).
pictures="$(mktemp -d)"
common=(-s 320 240 --tone-curve aces --srgb)
run "$build/bin/tyndall-render" "${common[@]}" --path-trace 16 -o "$pictures/mean.png"
run "$build/bin/tyndall-render" "${common[@]}" --path-trace 16 --path-denoise -o "$pictures/denoised.png"
run "$build/bin/tyndall-render" "${common[@]}" --path-trace 1024 -o "$pictures/converged.png"
/usr/bin/python3 "$root/Documentation/scripts/append_pictures.py" 0 1 \
  "$images/path-denoise.png" "$pictures"/{mean,denoised,converged}.png
rm -rf "$pictures"

# Light from the sky alone on the default scene (its sun off): the map-based
# frame with the sky's mean as ambient light (--sky-lights 0) | with the
# sky's 4 lights (the default) | 128 paths per pixel, under a gradient sky
# (top row) and under the tests' image sky (bottom row: TyndallCLICheck's
# sky.hdr, a sun of 40 behind the cloud, right of the view, 22-34 degrees up)
# (rendering-model.md, "Light from the sky"; about 5 minutes).
pictures="$(mktemp -d)"
run "$build/bin/TyndallCLICheck" make-data "$pictures/data" > /dev/null
common=(-s 320 240 --tone-curve aces --srgb --light-direction 0 -1 0 --light-intensity 0)
gradient=(--sky 0.03 0.03 0.03 --sky-top 0.5 0.65 1.0)
image=(--sky-image "$pictures/data/sky.hdr")
for sky in gradient image; do
  declare -n options="$sky"
  run "$build/bin/tyndall-render" "${common[@]}" "${options[@]}" --sky-lights 0 \
    -o "$pictures/$sky-mean.png"
  run "$build/bin/tyndall-render" "${common[@]}" "${options[@]}" -o "$pictures/$sky-lights.png"
  run "$build/bin/tyndall-render" "${common[@]}" "${options[@]}" --path-trace 128 \
    -o "$pictures/$sky-paths.png"
  unset -n options
done
/usr/bin/python3 "$root/Documentation/scripts/append_pictures.py" 0 1 "$pictures/top.png" \
  "$pictures"/gradient-{mean,lights,paths}.png
/usr/bin/python3 "$root/Documentation/scripts/append_pictures.py" 0 1 "$pictures/bottom.png" \
  "$pictures"/image-{mean,lights,paths}.png
/usr/bin/python3 "$root/Documentation/scripts/append_pictures.py" 1 1 "$images/path-sky.png" \
  "$pictures"/{bottom,top}.png
rm -rf "$pictures"
