unit-distance 1
opacity 0 0
opacity 1 0.5
opacity 2 O.7   # letter O, not zero
