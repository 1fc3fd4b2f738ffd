"""PNG pixels as lists, with whichever VTK imports this module (the system
VTK 9.1 or ParaView's 9.2): shared by Tyndall's ParaView tests."""

from vtkmodules.util import numpy_support
from vtkmodules.vtkIOImage import vtkPNGReader


def rgb(path):
    """The RGB values of a PNG file, row by row, and its (width, height)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    dims = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    if scalars is None or dims[0] * dims[1] == 0:
        raise RuntimeError("cannot read %s" % path)
    values = numpy_support.vtk_to_numpy(scalars)
    return values.reshape(-1, scalars.GetNumberOfComponents())[:, :3].ravel().tolist(), dims[:2]
