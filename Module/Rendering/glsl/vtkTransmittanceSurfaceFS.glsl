// Tyndall: what an opaque surface's fragment shader adds to receive the
// medium's shadow (after vtkTransmittanceLightMapFS.glsl, inserted by
// vtkVolumeShadowReceiverPass among the light declarations of VTK's polydata
// shaders). The surface's lighting multiplies each light's diffuse and
// specular terms by tyndallSurfaceTransmittance() of that light.
uniform mat4 tyndallViewToWorld; // VTK's view coordinates -> world

// The medium's transmittance from a surface point (view coordinates, as
// VTK's vertexVC) to Tyndall's light l, read from the light's map: 1 outside
// the map's frustum (no medium along that ray) and between the light and the
// medium (the reconstruction at s <= 0).
TyndallTransmittance tyndallSurfaceTransmittance(int l, vec4 pointVC)
{
  vec3 x = (tyndallViewToWorld * vec4(pointVC.xyz / pointVC.w, 1.0)).xyz;
  vec2 ab = tyndallLightTexel(l, x);
  if (any(lessThan(ab, vec2(0.0))) || any(greaterThan(ab, vec2(1.0))))
  {
    return TyndallTransmittance(1.0);
  }
  return tyndallMapTransmittance(l, x);
}
