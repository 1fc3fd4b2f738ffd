// Tyndall: builds one light's transmittance map (appended to
// vtkTransmittanceCommonFS.glsl). One fragment per texel: the texel's light
// ray is marched through the medium (and the guests, other media the light
// crosses) across the maps' box and projected onto the TFM or ETM basis
// (Documentation/rendering-model.md). Layer k of the output holds
// coefficients 4k .. 4k+3; adaptive methods add a layer (s_min, s_max,
// T_beyond, 0).
in vec2 texCoord;
//VTK::Output::Dec

uniform int lightIndex;
uniform int method;
uniform int coefficientCount;
uniform int sampleCount;
uniform float adaptiveThreshold;
// Transmittance-function maps of a coloured extinction are built per
// channel: the channel's extinction relative to the medium's (else 1).
uniform float channelExtinction;

float coefficients[TYNDALL_MAX_COEFFICIENTS];

// Projects [sMin, sMax] of the segment [k_in, k_in + D dir] with sampleCount
// midpoint samples; returns the transmittance at the end.
float tyndallProject(vec3 kIn, vec3 dir, float D, float sMin, float sMax, bool etm)
{
  for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j)
  {
    coefficients[j] = 0.0;
  }
  float rangeLength = D * (sMax - sMin);
  float du = 1.0 / float(sampleCount);
  float tau = 0.0;
#if TYNDALL_SKIP_EMPTY
  // ETM projects sigma, zero in empty blocks: they are skipped. TFM projects
  // the transmittance, which is not zero there: it marches every sample.
  vec3 bo, bd;
  tyndallBlockRay(kIn, dir, bo, bd);
  float tBlockEnd = etm ? -1.0 : 1e30;
#endif
  int n = 0;
  for (int i = 0; i < sampleCount && n < sampleCount; ++i)
  {
    float u = (float(n) + 0.5) * du;
#if TYNDALL_SKIP_EMPTY
    if (tyndallSkipEmpty(bo, bd, (sMin + u * (sMax - sMin)) * D, tBlockEnd, n, sMin * D,
          rangeLength * du, 0.5, sampleCount))
    {
      continue;
    }
#endif
    ++n;
    float sigma = channelExtinction *
      tyndallSceneExtinction(kIn + (sMin + u * (sMax - sMin)) * D * dir, dir, rangeLength * du);
    float opticalStep = sigma * rangeLength * du;
    float value = etm ? sigma * rangeLength : exp(-(tau + 0.5 * opticalStep));
    // cos(j pi u) by the angle-addition recurrence.
    float c1 = cos(TYNDALL_PI * u);
    float s1 = sin(TYNDALL_PI * u);
    float cj = 1.0;
    float sj = 0.0;
    for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j) // constant: unrolled
    {
      coefficients[j] += j < coefficientCount ? 2.0 * value * cj * du : 0.0;
      float cNext = cj * c1 - sj * s1;
      sj = sj * c1 + cj * s1;
      cj = cNext;
    }
    tau += opticalStep;
  }
  return exp(-tau);
}

void main()
{
  vec3 origin, dir;
  tyndallLightRay(lightIndex, texCoord, origin, dir);
  vec2 range = tyndallIntersectMapBox(origin, dir);
  bool etm = method == TYNDALL_ETM || method == TYNDALL_ADAPTIVE_ETM;
  bool adaptive = method == TYNDALL_ADAPTIVE_TFM || method == TYNDALL_ADAPTIVE_ETM;
  vec3 bounds = vec3(0.0, 1.0, 1.0);
  if (range.x < range.y)
  {
    float D = range.y - range.x;
    vec3 kIn = origin + range.x * dir;
    if (adaptive)
    {
      // First march: the first sample with extinction, and where the
      // transmittance falls below the threshold.
      float du = 1.0 / float(sampleCount);
      float tau = 0.0;
      float sMin = -1.0;
      float sMax = 1.0;
#if TYNDALL_SKIP_EMPTY
      vec3 bo, bd;
      tyndallBlockRay(kIn, dir, bo, bd);
      float tBlockEnd = -1.0;
#endif
      int n = 0;
      for (int i = 0; i < sampleCount && n < sampleCount; ++i)
      {
#if TYNDALL_SKIP_EMPTY
        if (tyndallSkipEmpty(
              bo, bd, (float(n) + 0.5) * du * D, tBlockEnd, n, 0.0, du * D, 0.5, sampleCount))
        {
          continue;
        }
#endif
        float sigma = channelExtinction *
          tyndallSceneExtinction(kIn + (float(n) + 0.5) * du * D * dir, dir, du * D);
        if (sMin < 0.0 && sigma > 0.0)
        {
          sMin = float(n) * du;
        }
        float opticalStep = sigma * D * du;
        if (exp(-(tau + 0.5 * opticalStep)) < adaptiveThreshold)
        {
          // The range ends after this sample, whose depth T_beyond includes
          // (a surface may hold all of the ray's depth in one sample).
          sMax = float(n + 1) * du;
          tau += opticalStep;
          break;
        }
        tau += opticalStep;
        ++n;
      }
      if (sMin < 0.0)
      {
        sMin = 0.0;
      }
      float tBeyond = exp(-tau);
      bounds = vec3(sMin, sMax, tBeyond);
      tyndallProject(kIn, dir, D, sMin, sMax, etm);
    }
    else
    {
      bounds.z = tyndallProject(kIn, dir, D, 0.0, 1.0, etm);
    }
  }
  else
  {
    // The ray misses the volume: T = 1 everywhere.
    for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j)
    {
      coefficients[j] = 0.0;
    }
    if (!etm)
    {
      coefficients[0] = 2.0;
    }
  }
  //TYNDALL::MapOutputs
}
