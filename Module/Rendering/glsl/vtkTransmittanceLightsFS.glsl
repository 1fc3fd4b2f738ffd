// Tyndall: the renderer's lights as the camera rays and the projections
// see them (appended after vtkTransmittanceCameraRayFS.glsl, before
// vtkTransmittanceRayCastFS.glsl or vtkTransmittanceProjectionFS.glsl):
// their geometry, and with TYNDALL_SHADING the colours and coefficients of
// a plain property's gradient shading (vtkTyndallShading, its CPU twin).
// vtkTransmittanceFrame::SetLightUniforms() sets them.
uniform int numberOfLights;    // the renderer's lights, 0 to numberOfLights - 1
uniform int numberOfSkyLights; // the sky's after them (vtkTyndallSkyLights): scattering and shading
uniform vec3 lightPosition[TYNDALL_MAX_LIGHTS];     // positional lights
uniform vec3 lightDirection[TYNDALL_MAX_LIGHTS];    // direction the light travels
uniform vec3 lightAttenuation[TYNDALL_MAX_LIGHTS];
uniform float lightConeCosine[TYNDALL_MAX_LIGHTS];  // -2: no cone
uniform float lightExponent[TYNDALL_MAX_LIGHTS];

// Light l seen from x: the unit direction towards it, the distance to a
// positional light (1e30 for a directional one), and `E` (the light's
// irradiance or colour) with a positional light's attenuation and spot cone
// applied; false where it gives nothing.
bool tyndallLightAt(int l, vec3 x, inout vec3 E, out vec3 toLight, out float distance)
{
  distance = 1e30;
  if (lightPositional[l] == 0)
  {
    toLight = -lightDirection[l]; // directional
  }
  else
  {
    vec3 v = lightPosition[l] - x;
    distance = length(v);
    toLight = v / distance;
    vec3 a = lightAttenuation[l];
    E /= max(a.x + a.y * distance + a.z * distance * distance, 1e-12);
    if (lightConeCosine[l] > -1.5)
    {
      float cosPhi = dot(-toLight, lightDirection[l]);
      E *= cosPhi >= lightConeCosine[l] ? pow(max(cosPhi, 0.0), lightExponent[l]) : 0.0;
    }
  }
  return E.r + E.g + E.b > 0.0;
}

#if TYNDALL_SHADING
uniform vec4 shadingCoefficients[4]; // per component: Ka, Kd, Ks, specular power
uniform vec3 lightColor[TYNDALL_MAX_LIGHTS];
uniform int lightHeadlight[TYNDALL_MAX_LIGHTS];
// The sky's mean radiance m as light from every direction, where no sky
// light carries the sky (vtkTyndallSceneReader::GetShadingSkyMean()); else 0.
uniform vec3 shadingSkyMean;

// The sky's mean as light from every direction, unshadowed, for the
// coefficients k (vtkTyndallShading::AddSkyMean(), its CPU twin): Kd c 2 pi m
// for the two-sided diffuse lobe (|n.s| over the sphere: 2 pi), where the
// normal is not 0 (a sample without a gradient gets none, as from the
// lights); the volumetric term's (no cosine) is twice that.
vec3 tyndallSkyMeanDiffuse(vec4 k, vec3 color)
{
  return (2.0 * TYNDALL_PI * k.y) * shadingSkyMean * color;
}

// Light's term Kd |n.s| c + Ks |n.h|^p with coefficients k; the base of pow
// kept positive: pow(0, 0) is undefined in GLSL, 1 on the CPU.
vec3 tyndallShadingTerm(vec4 k, vec3 n, vec3 s, vec3 h, vec3 color)
{
  return k.y * abs(dot(n, s)) * color + k.z * pow(max(abs(dot(n, h)), 1e-30), k.w);
}

// The half vector of the light direction s and the view direction v; 0
// where the light faces the camera exactly (the CPU's guard).
vec3 tyndallHalfVector(vec3 s, vec3 v)
{
  vec3 sv = s + v;
  float svLength = length(sv);
  return svLength > 0.0 ? sv / svLength : vec3(0.0);
}
#endif
