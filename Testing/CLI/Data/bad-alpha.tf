opacity 0 0
opacity 1 1.5
