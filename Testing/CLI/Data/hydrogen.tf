# A transfer function for hydrogen.vti (probability density, 0..1, unit voxels).
unit-distance 1
opacity 0.0    0.0
opacity 0.02   0.0
opacity 0.3    0.35
opacity 1.0    0.9
color   0.0    0.4 0.6 1.0   # albedo: bluish where thin ...
color   1.0    1.0 0.9 0.7   # ... warm where dense
