// Tyndall: the renderer's sky, its radiance and its importance sampling, for
// the path tracer (vtkTransmittancePathTraceFS.glsl, with
// TYNDALL_PATH_ENVIRONMENT). CPU twin: vtkTyndallEnvironment, whose tables
// these textures hold (vtkTransmittanceEnvironmentTextures): the radiance,
// one texel per patch of the sphere (row 0 straight down, nearest); the
// rows' cumulative probabilities (H x 1, the last 1) and each row's
// columns' (W x H).
#if TYNDALL_PATH_ENVIRONMENT
uniform sampler2D skyRadianceTexture;
uniform sampler2D skyRowTexture;
uniform sampler2D skyColumnTexture;
uniform ivec2 skySize;  // W, H
uniform float skyTotal; // the sum of mean channel x solid angle over the texels
uniform vec3 skyUp;     // the frame: up, right, front (unit, orthogonal)
uniform vec3 skyRight;
uniform vec3 skyFront;

// The texel the unit direction w falls in (vtkTyndallEnvironment::Texel()).
ivec2 tyndallSkyTexel(vec3 w)
{
  float x = dot(w, skyRight);
  float y = dot(w, skyUp);
  float z = dot(w, skyFront);
  // atan(x, z) is undefined at x = z = 0: straight up or down, any column.
  float u = 0.5 + (x == 0.0 && z == 0.0 ? 0.0 : atan(x, z)) / (2.0 * TYNDALL_PI);
  float v = 0.5 + atan(y, sqrt(x * x + z * z)) / TYNDALL_PI;
  ivec2 texel = ivec2(floor(vec2(u, v) * vec2(skySize)));
  return clamp(texel, ivec2(0), skySize - 1);
}

float tyndallSkyLuminance(vec3 L)
{
  return (L.r + L.g + L.b) / 3.0;
}

// L(w) for the unit direction w.
vec3 tyndallSkyRadiance(vec3 w)
{
  return texelFetch(skyRadianceTexture, tyndallSkyTexel(w), 0).rgb;
}

// The sampling density of the unit direction w, per steradian.
float tyndallSkyPdf(vec3 w)
{
  return tyndallSkyLuminance(tyndallSkyRadiance(w)) / skyTotal;
}

// The smallest k in [0, n - 1] whose value in row `row` of `table` is above
// u: a bin of probability above 0 (the row holds the n bins' cumulative
// probabilities, the last 1). log2(n) + 1 trips at most.
int tyndallSkySearch(sampler2D table, int row, int n, float u)
{
  int low = 0;
  int high = n - 1;
  for (int trip = 0; trip < 32 && low < high; ++trip)
  {
    int middle = (low + high) / 2;
    if (texelFetch(table, ivec2(middle, row), 0).r > u)
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  return low;
}

// A direction w drawn from four uniform numbers in [0, 1) (the row, the
// column, the azimuth and the elevation within the texel): returns its
// density per steradian, with its radiance in L (vtkTyndallEnvironment::
// Sample()).
float tyndallSampleSky(vec4 u, out vec3 w, out vec3 L)
{
  int j = tyndallSkySearch(skyRowTexture, 0, skySize.y, u.x);
  int i = tyndallSkySearch(skyColumnTexture, j, skySize.x, u.y);
  float phi = 2.0 * TYNDALL_PI * ((float(i) + u.z) / float(skySize.x) - 0.5);
  float s0 = sin(TYNDALL_PI * (float(j) / float(skySize.y) - 0.5));
  float s1 = sin(TYNDALL_PI * (float(j + 1) / float(skySize.y) - 0.5));
  float s = clamp(mix(s0, s1, u.w), -1.0, 1.0);
  float rho = sqrt(max(0.0, 1.0 - s * s));
  w = normalize(rho * sin(phi) * skyRight + s * skyUp + rho * cos(phi) * skyFront);
  L = texelFetch(skyRadianceTexture, ivec2(i, j), 0).rgb;
  return tyndallSkyLuminance(L) / skyTotal;
}
#endif
