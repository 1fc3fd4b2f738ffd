//VTK::System::Dec
// Tyndall: adds one particle's extinction coefficients to the texels of one
// light's extinction map it covers (vtkTransmittanceSplatPass; blended
// additively over the map the march built). The particle is the smooth
// sphere of vtkParticleKernel, density rho (1 - r^2/R^2)^2; along the
// texel's light ray, across the maps' box [t_in, t_in + D], its extinction
// integrates in closed form to
//   c_j = 2 s rho cos(w t_c) h^5 / (R^4 lambda) g(w h / lambda),  w = j pi / D,
// with t_c the closest approach (world distance from t_in), h the half
// chord in data units, lambda the data length of a unit world step, s the
// density scale and g(x) = 16 ((3 - x^2) sin x - 3 x cos x) / x^5
// (vtkParticleKernel::AddExtinctionCoefficients, the CPU twin). The
// light-map functions (vtkTransmittanceLightMapFS.glsl) are inserted below.
flat in vec4 splatParticle;
flat in float splatDensity;

uniform mat4 worldToData;
uniform float mapSize;
uniform int lightIndex;
uniform int coefficientCount;
uniform float splatDensityScale;

//VTK::Output::Dec

//TYNDALL::LightMaps

float coefficients[TYNDALL_MAX_COEFFICIENTS];

// g(x) = integral over [-1, 1] of (1 - v^2)^2 cos(x v) for x >= 0, from sin x
// and cos x: its Taylor series below 1 (the closed form cancels there in single
// precision; seven terms reach 1e-11), else the closed form.
float tyndallProfileCosineIntegral(float x, float sinX, float cosX)
{
  if (x < 1.0)
  {
    // sum over k of (-1)^k x^2k / (2k)! * 16 / ((2k + 1)(2k + 3)(2k + 5)), Horner.
    float y = x * x;
    return 16.0 / 15.0 +
      y * (-16.0 / 210.0 +
        y * (16.0 / 7560.0 +
          y * (-16.0 / 498960.0 +
            y * (16.0 / 51891840.0 + y * (-16.0 / 7783776000.0 + y * (16.0 / 1.5878903e12))))));
  }
  float x2 = x * x;
  return 16.0 * ((3.0 - x2) * sinX - 3.0 * x * cosX) / (x2 * x2 * x);
}

void main()
{
  vec3 origin, dir;
  tyndallLightRay(lightIndex, gl_FragCoord.xy / mapSize, origin, dir);
  vec2 range = tyndallIntersectMapBox(origin, dir);
  if (!(range.x < range.y))
  {
    discard;
  }
  float D = range.y - range.x;
  vec3 o = (worldToData * vec4(origin + range.x * dir, 1.0)).xyz;
  vec3 d = (worldToData * vec4(dir, 0.0)).xyz;
  float lambda = length(d);
  d /= lambda;
  vec3 toCentre = splatParticle.xyz - o;
  float sc = dot(toCentre, d);
  vec3 perpendicular = toCentre - sc * d;
  float R = splatParticle.w;
  float h2 = R * R - dot(perpendicular, perpendicular);
  if (h2 <= 0.0)
  {
    discard;
  }
  float h = sqrt(h2);
  float tc = sc / lambda;
  float hw = h / lambda;
  float R2 = R * R;
  float scale = 2.0 * splatDensityScale * splatDensity * (h2 / R2) * (h2 / R2) * h / lambda;
  // cos(j w1 t_c), and sin and cos of j w1 h_w, by the angle-addition
  // recurrence (w1 = pi / D): two sines and two cosines per fragment.
  float w1 = TYNDALL_PI / D;
  float c1 = cos(w1 * tc);
  float s1 = sin(w1 * tc);
  float cx1 = cos(w1 * hw);
  float sx1 = sin(w1 * hw);
  float cj = 1.0;
  float sj = 0.0;
  float cx = 1.0;
  float sx = 0.0;
  for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j) // constant: unrolled
  {
    coefficients[j] = j < coefficientCount
      ? scale * cj * tyndallProfileCosineIntegral(float(j) * w1 * hw, sx, cx)
      : 0.0;
    float cNext = cj * c1 - sj * s1;
    sj = sj * c1 + cj * s1;
    cj = cNext;
    float cxNext = cx * cx1 - sx * sx1;
    sx = sx * cx1 + cx * sx1;
    cx = cxNext;
  }
  //TYNDALL::MapOutputs
}
