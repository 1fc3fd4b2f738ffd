// vtkTransmittanceLightFrustum on the CPU: fitted frusta hold the box (every
// corner's texel inside [0, 1]^2), texel -> ray -> point -> texel round trips,
// and the clip matrix of the occlusion pass maps the point at distance t on
// texel (a, b)'s ray to clip x, y = 2a - 1, 2b - 1 with a depth that
// GetRayDistance() turns back into t; the box's corners lie inside the clip
// volume; ConfigureCamera() gives a vtkCamera whose composite projection is
// that matrix. Directional and positional lights, boxes rotated and scaled,
// and the refusals (zero direction, light inside the box, field of view over
// the maximum). No display needed.
#include "TyndallTestCheck.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkTransform.h"
#include "vtkTransmittanceLightFrustum.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

// The corners of [-1, 1] x [-0.5, 0.5] x [-2, 2] turned and moved.
void MakeCorners(vtkTransform* transform, double corners[24])
{
  for (int c = 0; c < 8; ++c)
  {
    const double p[3] = { (c & 1) ? 1.0 : -1.0, (c & 2) ? 0.5 : -0.5, (c & 4) ? 2.0 : -2.0 };
    transform->TransformPoint(p, corners + 3 * c);
  }
}

// Checks one fitted frustum; returns the worst errors seen.
void CheckFrustum(vtkTransmittanceLightFrustum* frustum, const double corners[24],
  vtkMinimalStandardRandomSequence* random, const std::string& what, double worst[3])
{
  // Every corner projects inside the map.
  for (int c = 0; c < 8; ++c)
  {
    double ab[2];
    frustum->GetTexel(corners + 3 * c, ab);
    Check(ab[0] > 0.0 && ab[0] < 1.0 && ab[1] > 0.0 && ab[1] < 1.0,
      what + ": corner " + std::to_string(c) + " inside the map");
  }
  vtkNew<vtkMatrix4x4> clip;
  frustum->ComputeClipMatrix(corners, clip);
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(corners, corners + 21));
  for (int k = 0; k < 200; ++k)
  {
    const double a = random->GetNextRangeValue(0.0, 1.0);
    const double b = random->GetNextRangeValue(0.0, 1.0);
    double o[3], d[3];
    frustum->GetRay(a, b, o, d);
    Check(std::abs(vtkMath::Norm(d) - 1.0) < 1e-12, what + ": unit ray direction");
    // Points on the ray between the near and far planes.
    const double t = random->GetNextRangeValue(0.05, 1.0) *
        (frustum->GetFarDistance() - std::max(frustum->GetNearDistance(), 0.0)) +
      std::max(frustum->GetNearDistance(), 0.0);
    const double x[4] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2], 1.0 };
    double ab[2];
    frustum->GetTexel(x, ab);
    worst[0] = std::max({ worst[0], std::abs(ab[0] - a), std::abs(ab[1] - b) });
    double h[4];
    clip->MultiplyPoint(x, h);
    const double ndc[3] = { h[0] / h[3], h[1] / h[3], h[2] / h[3] };
    worst[1] = std::max(
      { worst[1], std::abs(ndc[0] - (2.0 * a - 1.0)), std::abs(ndc[1] - (2.0 * b - 1.0)) });
    const double depth = 0.5 * ndc[2] + 0.5;
    worst[2] = std::max(worst[2], std::abs(frustum->GetRayDistance(a, b, depth) - t) / diagonal);
  }
  // The box lies inside the clip volume.
  for (int c = 0; c < 8; ++c)
  {
    const double x[4] = { corners[3 * c], corners[3 * c + 1], corners[3 * c + 2], 1.0 };
    double h[4];
    clip->MultiplyPoint(x, h);
    bool inside = h[3] > 0.0;
    for (int k = 0; k < 3; ++k)
    {
      inside = inside && std::abs(h[k] / h[3]) < 1.0;
    }
    Check(inside, what + ": corner " + std::to_string(c) + " inside the clip volume");
  }
  // A camera with exactly that projection.
  vtkNew<vtkCamera> camera;
  frustum->ConfigureCamera(corners, camera);
  vtkMatrix4x4* composite = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
  double difference = 0.0, magnitude = 0.0;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      difference =
        std::max(difference, std::abs(composite->GetElement(r, c) - clip->GetElement(r, c)));
      magnitude = std::max(magnitude, std::abs(clip->GetElement(r, c)));
    }
  }
  Check(difference <= 1e-9 * magnitude, what + ": the camera's projection is the clip matrix");
}
}

int TestTransmittanceLightFrustum(int, char*[])
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  double worst[3] = { 0.0, 0.0, 0.0 };
  for (int trial = 0; trial < 20; ++trial)
  {
    vtkNew<vtkTransform> transform;
    transform->Translate(random->GetNextRangeValue(-3, 3), random->GetNextRangeValue(-3, 3),
      random->GetNextRangeValue(-3, 3));
    transform->RotateWXYZ(random->GetNextRangeValue(0, 360), random->GetNextRangeValue(-1, 1),
      random->GetNextRangeValue(-1, 1), random->GetNextRangeValue(-1, 1));
    transform->Scale(random->GetNextRangeValue(0.2, 3.0), random->GetNextRangeValue(0.2, 3.0),
      random->GetNextRangeValue(0.2, 3.0));
    double corners[24], center[3] = { 0.0, 0.0, 0.0 };
    MakeCorners(transform, corners);
    for (int c = 0; c < 8; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        center[k] += corners[3 * c + k] / 8.0;
      }
    }
    double direction[3] = { random->GetNextRangeValue(-1, 1), random->GetNextRangeValue(-1, 1),
      random->GetNextRangeValue(-1, 1) };
    vtkNew<vtkTransmittanceLightFrustum> frustum;
    Check(frustum->FitDirectional(direction, corners), "a directional fit");
    CheckFrustum(frustum, corners, random, "directional " + std::to_string(trial), worst);

    // A positional light far enough for a field of view under 150 degrees.
    vtkMath::Normalize(direction);
    const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(corners, corners + 21));
    const double position[3] = { center[0] - 2.0 * diagonal * direction[0],
      center[1] - 2.0 * diagonal * direction[1], center[2] - 2.0 * diagonal * direction[2] };
    Check(frustum->FitPositional(position, corners), "a positional fit");
    CheckFrustum(frustum, corners, random, "positional " + std::to_string(trial), worst);

    // Refusals: inside the box, too wide, no direction.
    Check(!frustum->FitPositional(center, corners), "a light inside the box has no frustum");
    frustum->SetMaximumFieldOfView(1.0);
    Check(!frustum->FitPositional(position, corners), "a frustum wider than the maximum");
    frustum->SetMaximumFieldOfView(150.0);
    const double none[3] = { 0.0, 0.0, 0.0 };
    Check(!frustum->FitDirectional(none, corners), "a zero direction has no frustum");
  }
  std::cout << "texel round trip " << worst[0] << ", clip x/y " << worst[1]
            << ", depth -> distance " << worst[2] << " (of the diagonal)" << std::endl;
  Check(worst[0] < 1e-10, "texel -> ray -> texel");
  Check(worst[1] < 1e-10, "the clip matrix maps texel (a, b) to clip (2a - 1, 2b - 1)");
  Check(worst[2] < 1e-7, "depth -> distance along the ray");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
