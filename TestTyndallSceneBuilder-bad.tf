opacity 0 2
