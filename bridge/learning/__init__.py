"""Learners that turn pours (parameterizations and the oracle's scores) into
defeasible rules."""
