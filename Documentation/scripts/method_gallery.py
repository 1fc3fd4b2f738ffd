"""Renders the documentation's method gallery: every transmittance method of
vtkTransmittanceVolumeMapper beside the CPU reference, on the built-in cloud
and on a dense medium, with the PSNR of each against the reference.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        Documentation/scripts/method_gallery.py Documentation/images
"""

import math
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkTextActor, vtkVolume
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from doc_scene import cloud_medium, grab, window_around

from tyndall import (vtkCosineNoiseSource, vtkSingleScatteringReference,
                     vtkTransmittanceVolumeMapper)

SIZE = 192
METHODS = ["None", "BruteForce", "TFM", "AdaptiveTFM", "ETM", "AdaptiveETM"]


def medium(dense):
    source = vtkCosineNoiseSource()
    source.SetWholeExtent(0, 63, 0, 63, 0, 63)
    source.SetSpacing(2 / 63, 2 / 63, 2 / 63)
    if dense:
        source.SetEnvelopeTypeToSphere()
        source.SetEnvelopeRadius(0.85)
        source.SetEnvelopeFalloff(0.15)
        source.GetNoise().SetNumberOfOctaves(3)
        source.GetNoise().SetOffset(12.0)
    source.Update()
    return source.GetOutput()


def psnr(a, b):
    sa, sb = a.GetPointData().GetScalars(), b.GetPointData().GetScalars()
    total = 0.0
    for i in range(sa.GetNumberOfTuples()):
        for c in range(3):
            d = sa.GetComponent(i, c) - sb.GetComponent(i, c)
            total += d * d
    mse = total / (3 * sa.GetNumberOfTuples())
    return float("inf") if mse == 0 else 10 * math.log10(255 ** 2 / mse)


def label(image, text):
    """Draws `text` on a copy of `image` through a tiny render window."""
    from vtkmodules.vtkRenderingCore import vtkImageActor
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(SIZE, SIZE)
    renderer = vtkRenderer()
    actor = vtkImageActor()
    actor.GetMapper().SetInputData(image)
    renderer.AddActor(actor)
    caption = vtkTextActor()
    caption.SetInput(text)
    caption.GetTextProperty().SetFontSize(13)
    caption.SetPosition(4, 4)
    renderer.AddActor2D(caption)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(SIZE / 2)
    return grab(window)


def row(dense):
    data = medium(dense)
    prop = cloud_medium(0.9 if dense else 0.5, 0.9, 0.1)
    mapper = vtkTransmittanceVolumeMapper()
    mapper.SetInputData(data)
    mapper.JitterOff()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    window, renderer = window_around(volume, SIZE, (0.2, 0.3, 0.45), (1, 0.5, 0.3), 1.0)
    window.Render()
    reference = vtkSingleScatteringReference()
    reference.Render(renderer, volume, SIZE, SIZE)
    cpu = vtkImageData()
    cpu.DeepCopy(reference.Composite())
    tiles = [label(cpu, "CPU reference")]
    for index, name in enumerate(METHODS):
        mapper.SetTransmittanceMethod(index)
        image = grab(window)
        tiles.append(label(image, "%s %.1f dB" % (name, psnr(image, cpu))))
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    for tile in tiles:
        append.AddInputData(tile)
    append.Update()
    return append.GetOutput()


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    for dense, name in ((False, "methods-cloud.png"), (True, "methods-dense.png")):
        writer = vtkPNGWriter()
        writer.SetInputData(row(dense))
        writer.SetFileName(out + "/" + name)
        writer.Write()
        print(out + "/" + name)


main()
