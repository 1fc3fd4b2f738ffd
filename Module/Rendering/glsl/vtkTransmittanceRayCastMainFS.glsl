// Tyndall: the camera rays' march (appended after vtkTransmittanceRayCastFS.glsl,
// whose functions it calls; the path tracer, vtkTransmittancePathTraceFS.glsl,
// takes the same functions with its own main()).
void main()
{
  vec3 p0, w;
  float tNear, tFar;
  tyndallCameraRay(p0, w, tNear, tFar);
  vec3 radiance;
  TyndallTransmittance Tv;
  if (!tyndallStartRay(p0, w, tNear, tFar, radiance, Tv))
  {
    return;
  }
  float offset = tyndallStepOffset();
  TyndallSkip skip = tyndallStartSkipping(p0, w);
  // Step n spans [tNear + n stepLength, tNear + (n + 1) stepLength), the last
  // one cut at tFar; its sample lies at `offset` of it.
  float stepTold = stepLength;
  tyndallCameraStep(w, stepTold);
  int n = firstStep;
  for (int i = firstStep; i < endStep && n < endStep; ++i)
  {
    float t0 = tNear + float(n) * stepLength;
    if (!(t0 < tFar))
    {
      break;
    }
    float dt = min(stepLength, tFar - t0);
    float ts = t0 + offset * dt;
    if (tyndallSkipStep(skip, ts, n, tNear, offset))
    {
      continue;
    }
    ++n;
    if (dt != stepTold)
    {
      stepTold = dt;
      tyndallCameraStep(w, dt);
    }
    vec3 x = p0 + ts * w;
    TyndallCameraSample medium = tyndallCameraSample(x, p0 + t0 * w, w, dt);
    float sigma = medium.Sigma;
    radiance += tyndallStepArrayEmission(x, sigma, dt, Tv);
    if (sigma > 0.0)
    {
      TyndallTransmittance stepOpacity = 1.0 - exp(-sigma * extinctionColor * dt);
      radiance += Tv * stepOpacity * tyndallSource(medium, w);
      Tv *= 1.0 - stepOpacity;
      if (tyndallLargest(Tv) < TYNDALL_VIEW_TERMINATION)
      {
        Tv = TyndallTransmittance(0.0);
        break;
      }
    }
  }
  tyndallWrite(radiance, Tv);
}
