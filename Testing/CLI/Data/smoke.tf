# For ../shared/data/vdb/smoke.vdb (fog density 0 .. 5.7, voxel size 0.476).
unit-distance 0.5
opacity 0.0   0.0
opacity 0.05  0.0
opacity 2.0   0.35
opacity 6.0   0.8
color   0.0   0.85 0.85 0.88
color   6.0   0.70 0.70 0.72
