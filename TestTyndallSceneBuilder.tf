opacity 0 0
opacity 5 0.5
color 0 1 0 0
emission 0 0 0 1
unit-distance 2
