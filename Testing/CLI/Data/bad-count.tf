opacity 0 0
color 1 0.5 0.5
