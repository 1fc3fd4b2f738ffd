# For the synthetic blob of the loader tests (0..300).
unit-distance 2
opacity 0 0
opacity 300 0.8
