# only colours
color 0 1 1 1
