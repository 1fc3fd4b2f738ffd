//VTK::System::Dec
// Tyndall: one pass of the path-traced picture's denoiser
// (vtkTransmittanceDenoisePass; vtkTyndallDenoiser is its CPU twin and
// describes it): the edge-avoiding a-trous filter of the residual
// mean - guide, the guide (the map-based frame) the edge stop. Pass i's
// taps are denoiseStep = 2^i pixels apart; the first pass reads the
// residual from meanImage - guideImage, the later ones from residualImage;
// the last adds the guide back. Drawn into an image the size of the
// pictures.
//TYNDALL::Constants
in vec2 texCoord; // the image's pixel: its centre over the image's size
uniform sampler2D meanImage;
uniform sampler2D guideImage;
uniform sampler2D residualImage;
uniform int denoiseFirst;
uniform int denoiseLast;
uniform int denoiseStep;
uniform float denoiseScale; // 1 / EdgeStop^2
//VTK::Output::Dec

// The residual at pixel q.
vec4 tyndallResidual(ivec2 q)
{
  return denoiseFirst == 1 ? texelFetch(meanImage, q, 0) - texelFetch(guideImage, q, 0)
                           : texelFetch(residualImage, q, 0);
}

// vtkTyndallDenoiser::Difference().
float tyndallGuideDifference(vec4 a, vec4 b)
{
  vec4 d = a - b;
  return dot(d, d) / (dot(a, a) + dot(b, b) + TYNDALL_DENOISE_EPSILON);
}

// vtkTyndallDenoiser::KernelWeight().
float tyndallKernel(int tap)
{
  return tap == 0 ? TYNDALL_DENOISE_KERNEL_0
                  : (abs(tap) == 1 ? TYNDALL_DENOISE_KERNEL_1 : TYNDALL_DENOISE_KERNEL_2);
}

void main()
{
  ivec2 size = textureSize(guideImage, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
  vec4 guide = texelFetch(guideImage, p, 0);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int dy = -2; dy <= 2; ++dy)
  {
    for (int dx = -2; dx <= 2; ++dx)
    {
      ivec2 q = p + denoiseStep * ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
      {
        continue;
      }
      float w = tyndallKernel(dx) * tyndallKernel(dy) *
        exp(-tyndallGuideDifference(guide, texelFetch(guideImage, q, 0)) * denoiseScale);
      sum += w * tyndallResidual(q);
      weights += w;
    }
  }
  vec4 residual = sum / weights;
  // The radiance at least 0 and the opacity in [0, 1]; NaN meant to give 0
  // as in the twin (GLSL leaves NaN undefined; not tested on the GPU).
  vec4 value = guide + residual;
  vec4 positive = mix(vec4(0.0), value, greaterThan(value, vec4(0.0)));
  gl_FragData[0] =
    denoiseLast == 1 ? vec4(positive.rgb, min(positive.a, 1.0)) : residual;
}
