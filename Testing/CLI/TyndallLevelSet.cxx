// An OpenVDB level set for the tyndall-render tests: a sphere of radius 5
// voxels of 0.1 (narrow band 3 voxels), written with OpenVDB itself.
#include "TyndallTestData.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace tyndall_test_data
{
bool WriteLevelSetSphere(const std::string& path)
{
  openvdb::initialize();
  openvdb::FloatGrid::Ptr sphere =
    openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.5f, openvdb::Vec3f(0.0f), 0.05f);
  sphere->setName("surface");
  try
  {
    openvdb::io::File file(path);
    file.write({ sphere });
    file.close();
  }
  catch (const openvdb::Exception&)
  {
    return false;
  }
  return true;
}
}
