// vtkTransmittanceVolumeMapper::PrepareDistributedMaps() with a
// vtkTransmittanceMapReducer: the ETM maps of pieces of a medium, fitted to
// the whole medium's box and added, are the whole medium's maps. Two halves
// of a cloud stand for two processes, each with its own mapper and window; a
// scripted reducer plays the other process (its box, its vote to rebuild,
// its map). Render() then shades with the added maps without building or
// reducing again; without a reducer of several processes nothing happens;
// other methods are drawn as ETM, said once; a process with nothing to draw
// still takes part, with zeros.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceMapReducer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using tyndall_test::Check;

constexpr int kMapSize = 64;
constexpr int kCoefficients = 8;
// Two RGBA layers of 8 coefficients per texel, one light.
constexpr vtkIdType kMapFloats = 4 * kMapSize * kMapSize * (kCoefficients / 4);

// The other process of two: answers each collective with what that process
// would bring (the max of its box, its vote; the sum with its map) and keeps
// what this one brought.
class vtkScriptedPeer : public vtkTransmittanceMapReducer
{
public:
  static vtkScriptedPeer* New();
  vtkTypeMacro(vtkScriptedPeer, vtkTransmittanceMapReducer);

  int GetNumberOfProcesses() override { return 2; }

  bool AllReduceMax(double* values, int count) override
  {
    // Six values: the box (negated lower corner, upper corner); two: the
    // vote to rebuild and the maps' size.
    const std::vector<double>& peer = count == 6 ? this->PeerBox : this->PeerVote;
    if (static_cast<int>(peer.size()) != count)
    {
      return false;
    }
    for (int i = 0; i < count; ++i)
    {
      values[i] = std::max(values[i], peer[i]);
    }
    return true;
  }

  bool AllReduceSum(float* values, vtkIdType count) override
  {
    this->Brought.assign(values, values + count);
    ++this->Sums;
    if (static_cast<vtkIdType>(this->PeerMap.size()) == count)
    {
      for (vtkIdType i = 0; i < count; ++i)
      {
        values[i] += this->PeerMap[i];
      }
    }
    return true;
  }

  std::vector<double> PeerBox;
  std::vector<double> PeerVote = { 1.0, static_cast<double>(kMapFloats) };
  std::vector<float> PeerMap;
  std::vector<float> Brought;
  int Sums = 0;

protected:
  vtkScriptedPeer() = default;
};
vtkStandardNewMacro(vtkScriptedPeer);

// One "process": a piece of the medium drawn by its own mapper and window.
struct Process
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTest::ErrorObserver> Messages;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;

  explicit Process(vtkImageData* piece)
  {
    this->Mapper->SetInputData(piece);
    this->Mapper->SetTransmittanceMethodToETM();
    this->Mapper->SetNumberOfCoefficients(kCoefficients);
    this->Mapper->SetTransmittanceMapSize(kMapSize);
    this->Mapper->AddObserver(vtkCommand::ErrorEvent, this->Messages);
    this->Mapper->AddObserver(vtkCommand::WarningEvent, this->Messages);
    this->Property = tyndall_test::MakeCloudProperty();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.2));
    tyndall_test::SetTestCamera(this->Renderer);
    this->Window->SetSize(64, 64);
    this->Window->AddRenderer(this->Renderer);
  }

  bool Prepare() { return this->Mapper->PrepareDistributedMaps(this->Renderer, this->Volume); }

  // Light 0's coefficients as the last build left them, texel by texel
  // (vtkTransmittanceVolumeMapper::GetTransmittanceMap()).
  std::vector<float> ReadMaps()
  {
    vtkNew<vtkImageData> map;
    std::vector<float> values;
    vtkDataArray* c = this->Mapper->GetTransmittanceMap(0, map)
      ? map->GetPointData()->GetArray("Coefficients")
      : nullptr;
    for (vtkIdType i = 0; c && i < c->GetNumberOfValues(); ++i)
    {
      values.push_back(static_cast<float>(c->GetVariantValue(i).ToDouble()));
    }
    return values;
  }
};

// Maps as a process brings them to the sum (one light: layer, texel,
// RGBA) as GetTransmittanceMap() gives them (texel, coefficient).
std::vector<float> ByTexel(const std::vector<float>& layers)
{
  const size_t texels = static_cast<size_t>(kMapSize) * kMapSize;
  std::vector<float> values(layers.size());
  for (size_t t = 0; t < texels && static_cast<vtkIdType>(layers.size()) == kMapFloats; ++t)
  {
    for (int j = 0; j < kCoefficients; ++j)
    {
      values[t * kCoefficients + j] = layers[4 * ((j / 4) * texels + t) + j % 4];
    }
  }
  return values;
}

// The box as AgreeWholeBounds() brings it to the max: -low, high.
std::vector<double> MaxBox(vtkVolume* volume)
{
  const double* b = volume->GetBounds();
  return { -b[0], -b[2], -b[4], b[1], b[3], b[5] };
}

// Largest difference relative to the largest magnitude of `reference`.
double RelativeError(const std::vector<float>& values, const std::vector<float>& reference)
{
  if (values.size() != reference.size() || reference.empty())
  {
    return HUGE_VAL;
  }
  double largest = 0.0, difference = 0.0;
  for (size_t i = 0; i < values.size(); ++i)
  {
    largest = std::max(largest, std::abs(static_cast<double>(reference[i])));
    difference = std::max(difference, std::abs(static_cast<double>(values[i]) - reference[i]));
  }
  return largest > 0.0 ? difference / largest : HUGE_VAL;
}

vtkSmartPointer<vtkImageData> Piece(vtkImageData* whole, int x0, int x1)
{
  auto piece = vtkSmartPointer<vtkImageData>::New();
  piece->DeepCopy(whole);
  const int* e = whole->GetExtent();
  const int extent[6] = { x0, x1, e[2], e[3], e[4], e[5] };
  piece->Crop(extent);
  return piece;
}
}

int TestTransmittanceMapReducer(int, char*[])
{
  vtkSmartPointer<vtkImageData> cloud = tyndall_test::MakeCloud(32);

  // The whole cloud in one process: the reference maps.
  Process whole(cloud);
  whole.Window->Render();
  const std::vector<float> reference = whole.ReadMaps();
  Check(static_cast<vtkIdType>(reference.size()) == kMapFloats, "the whole cloud's maps are read");
  const int wholeBuilds = whole.Mapper->GetMapBuildCount();
  Check(whole.Prepare() && whole.Mapper->GetMapBuildCount() == wholeBuilds,
    "without a reducer PrepareDistributedMaps() does nothing");
  vtkNew<vtkTransmittanceMapReducer> alone;
  whole.Mapper->SetMapReducer(alone);
  Check(whole.Prepare() && whole.Mapper->GetMapBuildCount() == wholeBuilds,
    "with a reducer of one process it does nothing");
  whole.Window->Render();
  Check(whole.Mapper->GetMapBuildCount() == wholeBuilds && !whole.Messages->GetWarning(),
    "a reducer of one process leaves the frame as it was");

  // Two halves sharing the plane x = 16, as ParaView's pieces of an image.
  Process left(Piece(cloud, 0, 16));
  Process right(Piece(cloud, 16, 31));
  vtkNew<vtkScriptedPeer> rightPeer, leftPeer;
  right.Mapper->SetMapReducer(rightPeer);
  left.Mapper->SetMapReducer(leftPeer);
  rightPeer->PeerBox = MaxBox(left.Volume);
  leftPeer->PeerBox = MaxBox(right.Volume);

  // The right process goes first (its peer brings nothing yet), then the
  // left one, whose peer brings the right's own maps.
  Check(right.Prepare(), "the right half prepares its maps");
  Check(static_cast<vtkIdType>(rightPeer->Brought.size()) == kMapFloats,
    "the right half brings its maps to the sum");
  leftPeer->PeerMap = rightPeer->Brought;
  Check(left.Prepare(), "the left half prepares its maps");
  Check(leftPeer->Sums == 1, "the left half adds once");

  // Render() shades with the added maps: no build, no reduction, no warning.
  const int builds = left.Mapper->GetMapBuildCount();
  left.Window->Render();
  Check(left.Mapper->GetMapBuildCount() == builds && leftPeer->Sums == 1,
    "Render() neither builds nor reduces again");
  Check(!left.Messages->GetWarning() && !left.Messages->GetError(), "Render() warns of nothing");
  const double alone_error = RelativeError(ByTexel(leftPeer->Brought), reference);
  const double sum_error = RelativeError(left.ReadMaps(), reference);
  std::cout << "left half's own maps against the whole cloud's: " << alone_error
            << " (relative); added to the right half's: " << sum_error << "\n";
  Check(alone_error > 0.05, "the left half alone misses the right half's extinction");
  Check(sum_error < 1e-4, "the added maps, as Render() uses them, are the whole cloud's");

  // Nothing changed anywhere: the next frame's collectives agree not to
  // rebuild, and nothing is built or added.
  leftPeer->PeerVote[0] = 0.0;
  Check(left.Prepare(), "an unchanged frame prepares");
  Check(left.Mapper->GetMapBuildCount() == builds && leftPeer->Sums == 1,
    "an unchanged frame neither builds nor adds");

  // A change between the collective build and the render: the piece's own
  // maps, said once; the next collective build adds them again even when no
  // other process has changed.
  left.Property->SetDensityScale(2.0);
  left.Window->Render();
  Check(left.Messages->GetWarning() &&
      left.Messages->GetWarningMessage().find("not added") != std::string::npos,
    "maps not added before the render are said");
  left.Messages->Clear();
  Check(left.Prepare() && leftPeer->Sums == 2,
    "maps built for the piece alone are rebuilt and added at the next collective build");
  leftPeer->PeerVote[0] = 1.0;
  left.Property->SetDensityScale(1.0);

  // Other methods are drawn as ETM, said once.
  left.Mapper->SetTransmittanceMethodToAdaptiveETM();
  Check(left.Prepare(), "adaptive ETM prepares");
  Check(left.Messages->GetWarning() &&
      left.Messages->GetWarningMessage().find("drawn as ETM") != std::string::npos,
    "adaptive ETM under several processes is said to be drawn as ETM");
  Check(static_cast<vtkIdType>(leftPeer->Brought.size()) == kMapFloats, "and its maps are ETM's");
  left.Messages->Clear();
  Check(left.Prepare() && !left.Messages->GetWarning(), "said once");

  // A process with nothing to draw still takes part, with zeros.
  const int sums = leftPeer->Sums;
  Check(!left.Mapper->PrepareDistributedMaps(nullptr, nullptr), "no renderer: false");
  Check(left.Messages->GetError(), "no renderer: an error");
  Check(leftPeer->Sums == sums + 1 &&
      std::all_of(
        leftPeer->Brought.begin(), leftPeer->Brought.end(), [](float v) { return v == 0.0f; }),
    "no renderer: it adds zeros");
  left.Messages->Clear();

  // Release before the windows go.
  for (Process* p : { &whole, &left, &right })
  {
    p->Window->MakeCurrent();
    p->Mapper->ReleaseGraphicsResources(p->Window);
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
