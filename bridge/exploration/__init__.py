"""The numeric side of Algorithm 1, which theory/curiosity.pl drives: the
session that owns the simulator and the saved state, equation (1)'s weights,
plane fitting and its permutation test, the novelty of candidates,
qualifying outcomes, the trace, and the loop's options."""
