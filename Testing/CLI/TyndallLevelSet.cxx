// OpenVDB inputs of the tests, written with OpenVDB itself: a level set (a
// sphere of radius 5 voxels of 0.1, narrow band 3 voxels) and a fog volume
// (a Gaussian blob) for time series.
#include "TyndallTestData.h"

#include "vtkOpenVDBInternals.h" // tyndall_io::NewGrid

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>

namespace
{
// `grid` as the one grid of a .vdb file at `path`; false when OpenVDB cannot write it.
bool WriteGrid(const std::string& path, openvdb::GridBase::Ptr grid)
{
  try
  {
    openvdb::io::File file(path);
    file.write({ grid });
    file.close();
  }
  catch (const openvdb::Exception&)
  {
    return false;
  }
  return true;
}
}

namespace tyndall_test_data
{
bool WriteLevelSetSphere(const std::string& path)
{
  openvdb::initialize();
  openvdb::FloatGrid::Ptr sphere =
    openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.5f, openvdb::Vec3f(0.0f), 0.05f);
  sphere->setName("surface");
  return WriteGrid(path, sphere);
}

bool WriteDensityBlob(const std::string& path, double shift)
{
  openvdb::initialize();
  openvdb::FloatGrid::Ptr grid = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
  grid->setName("density");
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  openvdb::FloatGrid::Accessor voxels = grid->getAccessor();
  for (int k = 0; k < 16; ++k)
  {
    for (int j = 0; j < 20; ++j)
    {
      for (int i = 0; i < 24; ++i)
      {
        const double x = (i - 8.5 - shift) / 5.0, y = (j - 9.5) / 5.0, z = (k - 7.5) / 4.0;
        const double value = 100.0 * std::exp(-2.0 * (x * x + y * y + z * z));
        if (value > 1.0e-3)
        {
          voxels.setValue(openvdb::Coord(i, j, k), static_cast<float>(value));
        }
      }
    }
  }
  return WriteGrid(path, grid);
}
}
