unit-distance 0
opacity 0 0
