"""Tyndall: physically based participating media for VTK.

Every public Tyndall class is importable from this package, for example::

    from tyndall import vtkCosineNoise, vtkCosineNoiseSource

The wrapped VTK modules Tyndall builds on are imported first, so the
classes' VTK base classes are known to Python.  Import VTK itself from
``vtkmodules.<module>`` (``import vtk`` loads every VTK module).
"""

from vtkmodules import vtkCommonCore as _vtkCommonCore  # noqa: F401
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel  # noqa: F401
from vtkmodules import vtkCommonExecutionModel as _vtkCommonExecutionModel  # noqa: F401

from .TyndallCore import *  # noqa: F401,F403

__version__ = "0.1.0"
