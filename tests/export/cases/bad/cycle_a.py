# imports cycle_b, which imports this module back
from cycle_b import B
A = 1.0
