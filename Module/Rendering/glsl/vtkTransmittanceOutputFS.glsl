// Tyndall: the mapper's display transform (vtkTransmittanceVolumeMapper's
// Exposure, ToneCurve and EncodeSRGB), the GLSL twin of
// vtkTyndallToneMapping: D(x) = sRGB(curve(x * 2^Exposure)) per channel.
// tyndallDisplay() maps a premultiplied colour (radiance L, opacity a) that
// is then blended over the frame buffer (ONE, ONE_MINUS_SRC_ALPHA) so that
// the pixel becomes D(L + (1 - a) D^-1(B)), B the background the renderer
// drew there (its colour or gradient, vtkTyndallToneMapping::MapOver()):
// the transform of the light that shows that background plus the medium's.
// Where the medium is absent the pixel keeps B; over black it is D(L).
// outputTransform 0: unchanged (the default, and every image the mapper's
// own passes draw).
uniform int outputTransform;
uniform float outputScale; // 2^Exposure
uniform int outputCurve;   // TYNDALL_TONE_LINEAR, TYNDALL_TONE_REINHARD, TYNDALL_TONE_ACES
uniform int outputSRGB;
uniform int outputBackground;       // 0: none known (black), 1: outputBottom to outputTop
uniform vec3 outputBottom;          // the background at the viewport's bottom edge
uniform vec3 outputTop;             // ... and top edge (a gradient; else the same)
uniform vec2 outputViewportY;       // the drawn viewport's first row and height (gl_FragCoord's)

float tyndallToneCurve(float x)
{
  // Negative or NaN: 0; the bounded curves: white far above it (keeps the
  // quotients finite).
  x = x > 0.0 ? x : 0.0;
  if (outputCurve == TYNDALL_TONE_LINEAR)
  {
    return x;
  }
  x = min(x, TYNDALL_TONE_LARGEST);
  if (outputCurve == TYNDALL_TONE_REINHARD)
  {
    return x / (1.0 + x);
  }
  if (outputCurve == TYNDALL_TONE_ACES)
  {
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  }
  return x;
}

// The exposed value whose curve is y (y in [0, 1] for the bounded curves).
float tyndallInverseToneCurve(float y)
{
  if (outputCurve == TYNDALL_TONE_REINHARD)
  {
    y = clamp(y, 0.0, TYNDALL_TONE_LARGEST / (1.0 + TYNDALL_TONE_LARGEST));
    return y / (1.0 - y);
  }
  if (outputCurve == TYNDALL_TONE_ACES)
  {
    // (2.51 - 2.43 y) x^2 + (0.03 - 0.59 y) x - 0.14 y = 0, its root >= 0.
    y = clamp(y, 0.0, 1.0);
    float A = 2.51 - 2.43 * y;
    float B = 0.03 - 0.59 * y;
    float root = sqrt(B * B + 0.56 * A * y);
    return B >= 0.0 ? 0.28 * y / max(B + root, 1e-30) : (root - B) / (2.0 * A);
  }
  return y;
}

float tyndallEncodeSRGB(float x)
{
  x = clamp(x, 0.0, 1.0);
  return x < 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

float tyndallDecodeSRGB(float v)
{
  v = clamp(v, 0.0, 1.0);
  return v < 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

vec3 tyndallForward(vec3 x)
{
  x *= outputScale;
  x = vec3(tyndallToneCurve(x.r), tyndallToneCurve(x.g), tyndallToneCurve(x.b));
  if (outputSRGB == 1)
  {
    x = vec3(tyndallEncodeSRGB(x.r), tyndallEncodeSRGB(x.g), tyndallEncodeSRGB(x.b));
  }
  return x;
}

vec3 tyndallInverse(vec3 d)
{
  if (outputSRGB == 1)
  {
    d = vec3(tyndallDecodeSRGB(d.r), tyndallDecodeSRGB(d.g), tyndallDecodeSRGB(d.b));
  }
  d = vec3(tyndallInverseToneCurve(d.r), tyndallInverseToneCurve(d.g),
    tyndallInverseToneCurve(d.b));
  return d / outputScale;
}

// `behind`: the transmittance the background is seen through, per channel
// (1 - a, or a coloured extinction's own).
vec4 tyndallDisplayBehind(vec4 premultiplied, vec3 behind)
{
  if (outputTransform == 0)
  {
    return premultiplied;
  }
  vec3 background = vec3(0.0);
  if (outputBackground == 1)
  {
    float t = clamp((gl_FragCoord.y - outputViewportY.x) / outputViewportY.y, 0.0, 1.0);
    background = mix(outputBottom, outputTop, t);
  }
  behind = clamp(behind, 0.0, 1.0);
  vec3 shown = tyndallForward(premultiplied.rgb + behind * tyndallInverse(background));
  return vec4(shown - behind * background, premultiplied.a);
}

vec4 tyndallDisplay(vec4 premultiplied)
{
  return tyndallDisplayBehind(premultiplied, vec3(1.0 - premultiplied.a));
}
