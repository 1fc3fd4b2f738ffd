//VTK::System::Dec
// Tyndall: the particles' splats into one light's extinction map
// (vtkTransmittanceSplatPass), one instance per particle: a rectangle of two
// triangles over the particle's footprint in the map, half a texel wider on
// each side. A directional light: the exact box around the projection of the
// particle's sphere (an ellipse when the volume's matrix stretches it: the
// sphere's extent along a map axis X is R |A^T X| for the matrix A); a
// positional light: the texel box of the eight corners of the cube around
// the sphere (the sphere's projection lies inside it). The light-map functions
// (vtkTransmittanceLightMapFS.glsl) are inserted below.
in vec4 particle; // centre (data coordinates), radius
in float density;

uniform mat4 dataToWorld;
uniform float mapSize;
uniform int lightIndex;

flat out vec4 splatParticle;
flat out float splatDensity;

//TYNDALL::LightMaps

void main()
{
  int l = lightIndex;
  vec2 lo, hi;
  if (lightPositional[l] == 0)
  {
    mat3 toWorld = mat3(dataToWorld);
    vec2 ab = tyndallLightTexel(l, (dataToWorld * vec4(particle.xyz, 1.0)).xyz);
    vec3 X = lightAxisX[l];
    vec3 Y = lightAxisY[l];
    vec2 extent = particle.w * vec2(length(transpose(toWorld) * X) / dot(X, X),
      length(transpose(toWorld) * Y) / dot(Y, Y));
    lo = ab - extent;
    hi = ab + extent;
  }
  else
  {
    lo = vec2(1.0e30);
    hi = vec2(-1.0e30);
    bool behind = false;
    for (int c = 0; c < 8; ++c)
    {
      vec3 side = vec3((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0,
        (c & 4) != 0 ? 1.0 : -1.0);
      vec3 x = (dataToWorld * vec4(particle.xyz + particle.w * side, 1.0)).xyz;
      behind = behind || dot(x - lightOrigin[l], lightAxisZ[l]) <= 0.0;
      vec2 ab = tyndallLightTexel(l, x);
      lo = min(lo, ab);
      hi = max(hi, ab);
    }
    if (behind)
    {
      // A corner at or behind the light's plane: the whole map.
      lo = vec2(0.0);
      hi = vec2(1.0);
    }
  }
  lo = clamp(lo - 0.5 / mapSize, 0.0, 1.0);
  hi = clamp(hi + 0.5 / mapSize, 0.0, 1.0);
  // Two triangles: corners (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
  int v = gl_VertexID;
  vec2 corner = vec2(v == 1 || v == 2 || v == 4 ? 1.0 : 0.0, v == 2 || v == 4 || v == 5 ? 1.0 : 0.0);
  gl_Position = vec4(2.0 * mix(lo, hi, corner) - 1.0, 0.0, 1.0);
  splatParticle = particle;
  splatDensity = density;
}
