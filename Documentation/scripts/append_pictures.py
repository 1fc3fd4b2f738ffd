"""Appends PNG pictures into one: append_pictures.py AXIS FACTOR OUT IN...
(AXIS 0: left to right, 1: bottom to top; each input magnified FACTOR
times first). Used by Documentation/make-pictures.sh."""

import sys

from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkImageResize
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter


def main(argv):
    if len(argv) < 5:
        print(__doc__, file=sys.stderr)
        return 2
    axis, factor, output, inputs = int(argv[1]), int(argv[2]), argv[3], argv[4:]
    append = vtkImageAppend()
    append.SetAppendAxis(axis)
    for name in inputs:
        reader = vtkPNGReader()
        reader.SetFileName(name)
        resize = vtkImageResize()
        resize.SetInputConnection(reader.GetOutputPort())
        resize.SetResizeMethodToMagnificationFactors()
        resize.SetMagnificationFactors(factor, factor, 1)
        append.AddInputConnection(resize.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetInputConnection(append.GetOutputPort())
    writer.SetFileName(output)
    writer.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
