FLPDE text 1
box 0 0 0 1 1 1
point 0 0 0
point 1 0 0
point 0 1 0
point 0 0 1
point 1 0 1
point 0 1 1
patch radii 0 a 0.25
spine 0 0 0 0 0 1 0 0 0 0 0 0
border 3 4 5
start 2 1 0
