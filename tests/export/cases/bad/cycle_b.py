# imported by cycle_a
from cycle_a import A
B = 2.0
