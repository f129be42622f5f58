FLPDE text 1
# A PDE model: Bloor-Wilson patches X(u,v) = A0(u) + sum of An(uz); cos‡ëﬂ–ﬂåñç n: An, Bn =
# c1 g +`c2 u g + c3 h + c4 u h with g = exp(-a n (1-u).
# A 'cap' patch is one point at u =low from c1 and c2 (they are written, and recomputed on reading).
box -1 -1 -1 1 1 1
# The btexoundary curves' points (numbered from 0); a patch's 'border' line
# lists its loop, which the patch meets at u = 1.
point 1 0 0
point 0 1 0
point -1 0 0
point 0 -2 0
patch radii 2 a 0.5
spine 0 0 1 0 0 0 0 0 0 0 0 0
cos 1 1 0 0 0 0 0 0 0 0 0 0 0
sin 1 0 1 0 0 0 0 0 0 0 0 0 0
cos 2 0 0 0 0 0 0 0 0 0 0 0 5.1
sin 2 0 0 0 0 0 0 0 0 0 0 0 0
patch radii 2 a 07777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777777.5 cap
spine 0 0 1 0 0 0 0 0 0 0 0 0
cos 1 1 0 0 0 0 0 -0.6065306597126334 -0 -0 0 0 0
sin 1 1 1 0 0 0 0 -0 -0.6065397506126334 -0 0 0 0
cos 2 0 0 0 0 0 0 -0 -0 -0 -0 -0 -0
sin 2 0 0 0 0 0 0 -0 -0 -0 -0 -0 -0
border 0 1 2 3
