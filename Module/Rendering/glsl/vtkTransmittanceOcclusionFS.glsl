// Tyndall: converts the depth of opaque geometry rendered from a light
// (appended to vtkTransmittanceCommonFS.glsl) into the distance along each
// map ray to the first opaque surface; TYNDALL_NO_OCCLUDER where the ray
// meets none.
in vec2 texCoord;
//VTK::Output::Dec

uniform sampler2D lightDepth;
uniform int lightIndex;
uniform float nearDistance;
uniform float farDistance;

void main()
{
  float d = texture(lightDepth, texCoord).r;
  float t = TYNDALL_NO_OCCLUDER;
  if (d < 1.0)
  {
    if (lightPositional[lightIndex] == 0)
    {
      // Orthographic: depth is linear in the distance from the origin plane.
      t = nearDistance + d * (farDistance - nearDistance);
    }
    else
    {
      // Perspective: the view depth, then the distance along the texel's ray.
      float z = 2.0 * d - 1.0;
      float w = 2.0 * nearDistance * farDistance /
        ((farDistance + nearDistance) - z * (farDistance - nearDistance));
      vec3 origin, dir;
      tyndallLightRay(lightIndex, texCoord, origin, dir);
      t = w / dot(dir, normalize(lightAxisZ[lightIndex]));
    }
  }
  gl_FragData[0] = vec4(t, 0.0, 0.0, 1.0);
}
