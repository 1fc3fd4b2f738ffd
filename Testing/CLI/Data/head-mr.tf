# A transfer function for HeadMRVolume.mhd (uint8 MR, 0..255, 4 mm voxels):
# air and noise transparent, tissue a faint warm fog, bright tissue dense.
unit-distance 8          # alpha below is the opacity of an 8 mm slab
opacity   0   0.0
opacity  40   0.0
opacity  80   0.15
opacity 255   0.6
color     0   1.0 0.85 0.75
color   255   1.0 0.95 0.9
