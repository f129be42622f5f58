FLPDE text 1
box 0 0 0 1 1 1
patch radii 64 a 1e308
